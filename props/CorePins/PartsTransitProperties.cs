using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;
using static AcPhys.Props.Mutation.CellArrays;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The parts variants of env transit and building entry (facts §5.2, §5.3) against the facts read as set statements
/// ("a portal contributes iff some part passes its sphere gate and its box is not wholly on the cell's side"), over
/// generated cottages (yaw, 1–4 rooms, both PortalSide values, back door, storey), parts placed around a portal plane
/// at the ±(r + EPS) gate edges, parts framed in a neighbouring block, rooms left out of the scene and the ACE switches.
/// </summary>
public sealed class PartsTransitProperties
{
    [FixedSeedProperty(0x9A75_0001, DisplayName = "facts §5.2: by parts, each portal adds its neighbour (or a not-loaded hint, or the outside) iff some part passes the sphere gate and its box is not wholly on the cell's side; the neighbour only if such a box intersects it")]
    public Property FindTransitCells_IsTheSetStatementOfTheFacts() =>
        Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            var actual = new CellArray();
            EnvTransitParts.FindTransitCells(actual, c.Scene, c.Cell, c.Parts, c.Fidelity);
            var expected = ExpectedTransit(c.Scene, c.Cell, c.Parts, c.Fidelity, out var kinds);
            return Same(actual, expected).Label($"cell {c.Cell.Id}, parts {string.Join("; ", c.Parts)}: {Text(actual)} vs {Text(expected)}")
                .Collect(string.Join("+", kinds.Distinct().Order()));
        });

    [FixedSeedProperty(0x9A75_0002, DisplayName = "facts §5.3: by parts, a building portal enters its cell iff some part passes the entering gate, its box side is Crossing or the accepted side (retail: the cell's own, ACE: the other) and the box intersects the cell; then that cell's parts transit runs, with the declared outdoor parts rules")]
    public Property CheckBuildingTransit_IsTheSetStatementOfTheFacts() =>
        Prop.ForAll(FixedSeed.Zip(Cases, Gen.Elements(PartsFidelity.Retail, PartsFidelity.Ace), Gen.Choose(-2, 5)).ToArbitrary(), t =>
        {
            var (c, partsFidelity, pick) = t;
            ushort portalId = pick == -2 ? BldPortal.None : pick == -1 ? (ushort)c.Cell.Portals.Length : (ushort)c.PortalIndex;
            // The first part aims at the building portal's own plane (the others anywhere), so its gate edges are hit.
            var parts = c.Plans.Select((p, i) => (i == 0 ? p with { Probe = p.Probe with { Portal = c.PortalIndex } } : p).At(c.Cell)).ToArray();
            var actual = new CellArray();
            bool entered = EnvTransitParts.CheckBuildingTransit(actual, c.Scene, c.Cell, portalId, parts, c.Fidelity, partsFidelity);

            var expected = new CellArray();
            bool enters = false;
            if (portalId < c.Cell.Portals.Length)
            {
                var portal = c.Cell.Portals[portalId];
                var own = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
                var accepted = c.Fidelity.AceBoxSidePairing ? Other(own) : own; // the declared switch (§7 #14)
                enters = parts.Any(p =>
                {
                    float d = portal.Plane.Distance(LocalCentre(c.Cell, p));
                    float r = p.Radius + LandDefs.Epsilon;
                    bool reachesIn = portal.PortalSide ? d <= r : d >= -r; // entering: the mirror of the leaving gate
                    var box = BoxSide.InFrame(p, c.Cell.Id, c.Cell.Frame);
                    var side = BoxSide.Of(portal.Plane, box);
                    return reachesIn && (side == Sidedness.Crossing || side == accepted) && c.Cell.Volume.BoxIntersects(box);
                });
            }

            if (enters)
            {
                expected.Add(c.Cell.Id, true);
                EnvTransitParts.FindTransitCells(expected, c.Scene, c.Cell, parts, c.Fidelity, partsFidelity);
            }

            return (entered == enters && Same(actual, expected)).Label($"{Text(actual)} vs {Text(expected)}")
                .Classify(enters, "entered").Classify(portalId >= c.Cell.Portals.Length, "no such portal");
        });

    private static Gen<Case> Cases { get; } =
        from cottage in CottageProbe.Cottages
        from parts in Gen.Choose(1, 3).SelectMany(n => PartGen(cottage.Cell).ArrayOf(n))
        from portalIndex in Gen.Choose(0, 7)
        from flags in Gen.Choose(0, 15)
        let fidelity = new IndoorFidelity(AceNeighbourViaVisibleCells: (flags & 1) != 0, AceLoadHintLowKey: (flags & 2) != 0, AceOutsideByCellId: (flags & 4) != 0) { AceBoxSidePairing = (flags & 8) != 0 }
        select new Case(cottage.Scene, cottage.Cell, parts, fidelity, portalIndex % cottage.Cell.Portals.Length);

    // A part around one of the cell's portal planes (CottageProbe.Probes: its centre at, just inside and just outside
    // the gate's r + EPS, or anywhere in the room), its box from a point to larger than a door, its frame yawed, and its
    // position framed in the cell's block or in one of the eight around it.
    private static Gen<PartPlan> PartGen(EnvCell cell) =>
        from probe in CottageProbe.Probes(cell)
        from half in Gen.Elements(0f, 0.05f, 0.2f, 1f, 2.5f)
        from yaw in Gen.Elements(0f, 0.7f, MathF.PI / 2)
        from dx in Gen.Choose(-1, 1)
        from dy in Gen.Choose(-1, 1)
        select new PartPlan(probe, half, yaw, dx, dy);

    // §5.2 as set statements; the outdoor part (§3.4, tested on its own) is the core's.
    private static CellArray ExpectedTransit(IScene scene, EnvCell cell, Part[] parts, IndoorFidelity fidelity, out List<string> kinds)
    {
        var expected = new CellArray();
        kinds = [];
        bool outside = false;
        foreach (var portal in cell.Portals)
        {
            var own = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
            var passing = parts.Where(p =>
            {
                float d = portal.Plane.Distance(LocalCentre(cell, p));
                float r = p.Radius + LandDefs.Epsilon;
                bool reachesOut = portal.PortalSide ? d >= -r : d <= r; // the neighbour lies on the positive side iff PortalSide (§5.4)
                return reachesOut && BoxSide.Of(portal.Plane, BoxSide.InFrame(p, cell.Id, cell.Frame)) != own;
            }).ToList();
            if (passing.Count == 0)
            {
                kinds.Add("none");
                continue;
            }

            bool exit = fidelity.AceOutsideByCellId ? portal.OtherCellId == 0xFFFF : (portal.Flags & CellPortal.OutsideFlag) != 0;
            if (exit)
            {
                kinds.Add("outside");
                outside = true;
                continue;
            }

            var otherId = new CellId((cell.Id.Value & 0xFFFF0000) | portal.OtherCellId);
            var other = fidelity.AceNeighbourViaVisibleCells && !cell.Sees(otherId) ? null : scene.GetEnvCell(otherId);
            if (other is null)
            {
                kinds.Add("hint");
                expected.Add(fidelity.AceLoadHintLowKey ? new CellId(portal.OtherCellId) : otherId, false);
            }
            else if (passing.Any(p => other.Volume.BoxIntersects(BoxSide.InFrame(p, other.Id, other.Frame))))
            {
                kinds.Add("neighbour");
                expected.Add(other.Id, true);
            }
            else
            {
                kinds.Add("gate passed, box misses");
            }
        }

        if (outside)
        {
            OutdoorParts.AddAllOutsideCells(expected, parts, cell.Id, scene);
        }

        return expected;
    }

    private static Vector3 LocalCentre(EnvCell cell, Part p) =>
        cell.Frame.GlobalToLocal(p.Frame.Origin + new Vector3(LandDefs.BlockLength * (p.Cell.BlockX - cell.Id.BlockX), LandDefs.BlockLength * (p.Cell.BlockY - cell.Id.BlockY), 0));

    private static Sidedness Other(Sidedness s) => s == Sidedness.Positive ? Sidedness.Negative : Sidedness.Positive;

    private sealed record Case(CellScene Scene, EnvCell Cell, PartPlan[] Plans, IndoorFidelity Fidelity, int PortalIndex)
    {
        public Part[] Parts { get; } = [.. Plans.Select(p => p.At(Cell))];

        public override string ToString() => $"cell {Cell.Id}, {Parts.Length} parts, {Fidelity}";
    }

    private sealed record PartPlan(GateProbe Probe, float Half, float Yaw, int BlockDx, int BlockDy)
    {
        // The centre: CottageProbe.OnPlane in the cell's block, then framed in the part's own block.
        public Part At(EnvCell cell)
        {
            var inCellBlock = CottageProbe.OnPlane(cell, Probe.Portal, Probe.Distance, Probe.Along);
            var partCell = new CellId((byte)(cell.Id.BlockX + BlockDx), (byte)(cell.Id.BlockY + BlockDy), 1);
            var origin = inCellBlock - new Vector3(LandDefs.BlockLength * BlockDx, LandDefs.BlockLength * BlockDy, 0);
            return new Part(partCell, new Frame(origin, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Yaw)), new Box(new Vector3(-Half), new Vector3(Half)), Probe.Radius, false);
        }
    }
}
