using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;
using static AcPhys.Props.Mutation.CellArrays;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The sphere variants of env transit and building entry (facts §5.1, §5.3) against the facts read as set statements,
/// over generated cottages (yaw, 1–4 rooms, both PortalSide values, back door, storey), spheres at the ±(r + EPS) gate
/// edges of a portal plane, query positions framed in the cell's block or in one of the eight around it (retail uses
/// the centres as given, facts §6.11; <see cref="IndoorFidelity.ReframeTransit"/> re-frames them), rooms left out of
/// the scene, building portals with no portal id, and the ACE switches.
/// </summary>
public sealed class SphereTransitProperties
{
    // Declared before the generators that use it (static initialisers run in textual order).
    private static readonly Gen<IndoorFidelity> Fidelities =
        from flags in Gen.Choose(0, 15)
        select new IndoorFidelity(
            AceNeighbourViaVisibleCells: (flags & 1) != 0,
            AceLoadHintLowKey: (flags & 2) != 0,
            AceOutsideByCellId: (flags & 4) != 0,
            ReframeTransit: (flags & 8) != 0);

    [FixedSeedProperty(0x5F7A_0001, DisplayName = "facts §5.1: by spheres, an exit portal adds the outside iff −R < d < R; a loaded neighbour is added iff a sphere (unpadded, its frame) intersects it; otherwise a hint iff the sphere reaches the neighbour's side; centres re-framed only when the fidelity says so (§6.11)")]
    public Property FindTransitCells_IsTheSetStatementOfTheFacts() =>
        Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            var actual = new CellArray();
            EnvTransit.FindTransitCells(actual, c.Scene, c.Cell, c.Position, c.Spheres, c.Fidelity);
            var expected = ExpectedTransit(c, out var kinds);
            return Same(actual, expected).Label($"{c}: {Text(actual)} vs {Text(expected)}")
                .Collect(string.Join("+", kinds.Distinct().Order()))
                .Classify(c.Position.Landblock != c.Cell.Id.Landblock, "position in a neighbouring block");
        });

    [FixedSeedProperty(0x5F7A_0002, DisplayName = "facts §5.3: by spheres, each building portal with a portal id whose cell is loaded adds that cell iff a sphere (unpadded, the cell's frame) intersects it, and the answer says whether any did (HitsInteriorCell)")]
    public Property FindBuildingTransitCells_IsTheSetStatementOfTheFacts() =>
        Prop.ForAll(Gen.Zip(Cases, Gen.Choose(0, 255)).ToArbitrary(), t =>
        {
            var (c, mask) = t;
            var (landCell, building) = c.Scene.Buildings.First();

            // Every room behind a portal (the cottage has one door): some with no portal id (0xFFFF), some absent.
            var portals = Enumerable.Range(0, c.Rooms + 1)
                .Select(i => new BldPortal(0, (ushort)(0x100 + i), (mask & (1 << i)) != 0 ? BldPortal.None : (ushort)i))
                .ToArray();
            var probe = building with { Portals = portals };

            var actual = new CellArray();
            bool hit = EnvTransit.FindBuildingTransitCells(actual, c.Scene, landCell, probe, c.Position, c.Spheres, c.Fidelity);

            var expected = new CellArray();
            bool hits = false;
            foreach (var portal in portals)
            {
                var env = c.Scene.GetEnvCell(landCell.WithLow(portal.OtherCellId));
                if (env is null || portal.OtherPortalId == BldPortal.None)
                {
                    continue;
                }

                if (c.Spheres.Any(s => env.Volume.SphereIntersects(new Sphere(env.Frame.GlobalToLocal(Used(c, s, env.Id)), s.Radius)) != BoundingType.Outside))
                {
                    hits = true;
                    expected.Add(env.Id, true);
                }
            }

            return (hit == hits && Same(actual, expected)).Label($"{c}: {hit} {Text(actual)} vs {hits} {Text(expected)}")
                .Classify(hits, "entered")
                .Classify(portals.Any(p => p.OtherPortalId != BldPortal.None && c.Scene.GetEnvCell(landCell.WithLow(p.OtherCellId)) is null), "a portal to an absent room");
        });

    private static Gen<Case> Cases { get; } =
        from cottage in CottageProbe.Cottages
        from probes in Gen.Choose(1, 3).SelectMany(n => CottageProbe.Probes(cottage.Cell).ArrayOf(n))
        from shift in Gen.Frequency((2, Gen.Constant((0, 0))), (1, Gen.Zip(Gen.Choose(-1, 1), Gen.Choose(-1, 1))))
        from fidelity in Fidelities
        let cell = cottage.Cell
        let position = new CellId((byte)(cell.Id.BlockX + shift.Item1), (byte)(cell.Id.BlockY + shift.Item2), 1)
        let offset = new Vector3(LandDefs.BlockLength * shift.Item1, LandDefs.BlockLength * shift.Item2, 0)
        let spheres = probes.Select(p => new Sphere(CottageProbe.OnPlane(cell, p.Portal, p.Distance, p.Along) - offset, p.Radius)).ToArray()
        select new Case(cottage.Scene, cell, position, spheres, fidelity, cottage.Plan.Rooms);

    // The centre a test reads in `cell`'s block frame: as given (retail, §6.11), or moved by the block offset.
    private static Vector3 Used(Case c, Sphere s, CellId cell) => c.Fidelity.ReframeTransit
        ? s.Center - new Vector3(LandDefs.BlockLength * (cell.BlockX - c.Position.BlockX), LandDefs.BlockLength * (cell.BlockY - c.Position.BlockY), 0)
        : s.Center;

    // §5.1 as set statements; the outdoor part (§3.3, tested on its own) is the core's.
    private static CellArray ExpectedTransit(Case c, out List<string> kinds)
    {
        var expected = new CellArray();
        kinds = [];
        bool outside = false;
        foreach (var portal in c.Cell.Portals)
        {
            float Distance(Sphere s) => portal.Plane.Distance(c.Cell.Frame.GlobalToLocal(Used(c, s, c.Cell.Id)));
            bool exit = c.Fidelity.AceOutsideByCellId ? portal.OtherCellId == 0xFFFF : (portal.Flags & CellPortal.OutsideFlag) != 0;
            if (exit)
            {
                bool straddles = c.Spheres.Any(s => Distance(s) > -(s.Radius + LandDefs.Epsilon) && Distance(s) < s.Radius + LandDefs.Epsilon);
                kinds.Add(straddles ? "outside" : "exit missed");
                outside |= straddles;
                continue;
            }

            var otherId = new CellId((c.Cell.Id.Value & 0xFFFF0000) | portal.OtherCellId);
            var other = c.Fidelity.AceNeighbourViaVisibleCells && !c.Cell.Sees(otherId) ? null : c.Scene.GetEnvCell(otherId);
            if (other is not null)
            {
                bool touches = c.Spheres.Any(s => other.Volume.SphereIntersects(new Sphere(other.Frame.GlobalToLocal(Used(c, s, other.Id)), s.Radius)) != BoundingType.Outside);
                kinds.Add(touches ? "neighbour" : "neighbour missed");
                if (touches)
                {
                    expected.Add(other.Id, true);
                }

                continue; // a loaded neighbour that no sphere touches is not a hint
            }

            bool reaches = c.Spheres.Any(s => portal.PortalSide ? Distance(s) > -(s.Radius + LandDefs.Epsilon) : Distance(s) < s.Radius + LandDefs.Epsilon);
            kinds.Add(reaches ? "hint" : "hint missed");
            if (reaches)
            {
                expected.Add(c.Fidelity.AceLoadHintLowKey ? new CellId(portal.OtherCellId) : otherId, false);
            }
        }

        if (outside)
        {
            OutdoorCells.AddAllOutsideCells(expected, c.Position, Vector3.Zero, c.Spheres, c.Scene, c.Fidelity.Outdoor);
        }

        return expected;
    }

    private sealed record Case(CellScene Scene, EnvCell Cell, CellId Position, Sphere[] Spheres, IndoorFidelity Fidelity, int Rooms)
    {
        public override string ToString() => $"cell {Cell.Id} from {Position}, spheres {string.Join("; ", Spheres)}, {Fidelity}";
    }
}
