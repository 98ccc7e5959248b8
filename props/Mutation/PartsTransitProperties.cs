using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The parts variants of env transit and building entry (facts §5.2, §5.3) against the facts read as set statements
/// ("a portal contributes iff some part passes its sphere gate and its box is not wholly on the cell's side"), over
/// generated cottages (yaw, 1–4 rooms, both PortalSide values, back door, storey), parts placed around a portal plane
/// at the ±(r + EPS) gate edges, parts framed in a neighbouring block, rooms left out of the scene and the ACE switches.
/// </summary>
public sealed class PartsTransitProperties
{
    [Fact(DisplayName = "facts §5.2: by parts, each portal adds its neighbour (or a not-loaded hint, or the outside) iff some part passes the sphere gate and its box is not wholly on the cell's side; the neighbour only if such a box intersects it")]
    public void FindTransitCells_IsTheSetStatementOfTheFacts() =>
        Check.One(FixedSeed.Config(0x9A75_0001), Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            var actual = new CellArray();
            EnvTransitParts.FindTransitCells(actual, c.Scene, c.Cell, c.Parts, c.Fidelity);
            var expected = ExpectedTransit(c.Scene, c.Cell, c.Parts, c.Fidelity, out var kinds);
            return Same(actual, expected).Label($"cell {c.Cell.Id}, parts {string.Join("; ", c.Parts)}: {Text(actual)} vs {Text(expected)}")
                .Collect(string.Join("+", kinds.Distinct().Order()));
        }));

    [Fact(DisplayName = "facts §5.3: by parts, a building portal enters its cell iff some part passes the entering gate, its box side is Crossing or the accepted side (retail: the cell's own, ACE: the other) and the box intersects the cell; then that cell's parts transit runs")]
    public void CheckBuildingTransit_IsTheSetStatementOfTheFacts() =>
        Check.One(FixedSeed.Config(0x9A75_0002), Prop.ForAll(FixedSeed.Zip(Cases, Gen.Elements(false, true), Gen.Choose(-2, 5)).ToArbitrary(), t =>
        {
            var (c, aceBoxSide, pick) = t;
            ushort portalId = pick == -2 ? BldPortal.None : pick == -1 ? (ushort)c.Cell.Portals.Length : (ushort)c.PortalIndex;
            // The first part aims at the building portal's own plane (the others anywhere), so its gate edges are hit.
            var parts = c.Plans.Select((p, i) => (i == 0 ? p with { Portal = c.PortalIndex } : p).At(c.Cell)).ToArray();
            var actual = new CellArray();
            bool entered = EnvTransitParts.CheckBuildingTransit(actual, c.Scene, c.Cell, portalId, parts, c.Fidelity, aceBoxSide);

            var expected = new CellArray();
            bool enters = false;
            if (portalId < c.Cell.Portals.Length)
            {
                var portal = c.Cell.Portals[portalId];
                var own = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
                var accepted = aceBoxSide ? Other(own) : own;
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
                EnvTransitParts.FindTransitCells(expected, c.Scene, c.Cell, parts, c.Fidelity);
            }

            return (entered == enters && Same(actual, expected)).Label($"{Text(actual)} vs {Text(expected)}")
                .Classify(enters, "entered").Classify(portalId >= c.Cell.Portals.Length, "no such portal");
        }));

    private static Gen<Case> Cases { get; } =
        from blockX in Gen.Choose(1, 250)
        from blockY in Gen.Choose(1, 250)
        from at in Gen.Zip(Gen.Choose(30, 150), Gen.Choose(30, 150))
        from yaw in Gen.Elements(0f, MathF.PI / 2, 0.3f, -1.1f)
        from rooms in Gen.Choose(1, 4)
        from size in Gen.Elements(4f, 6f, 9f)
        from flips in Gen.Choose(0, 15)
        from backDoor in Gen.Elements(false, true)
        from storey in Gen.Elements(false, true)
        let plan = new CottagePlan((blockX * 192.0) + at.Item1, (blockY * 192.0) + at.Item2, yaw, rooms, size, size, flips, backDoor, storey)
        let full = SceneBuild.Build(SceneKit.Cottage(plan))
        from room in Gen.Choose(0, rooms - 1)
        from missing in Gen.Choose(-1, rooms) // a room (or the storey) left out of the scene, or none
        from parts in Gen.Choose(1, 3).SelectMany(n => PartGen(full.GetEnvCell(plan.RoomId(room))!).ArrayOf(n))
        from portalIndex in Gen.Choose(0, 7)
        from flags in Gen.Choose(0, 7)
        let cell = full.GetEnvCell(plan.RoomId(room))!
        let scene = missing < 0 || missing == room ? full : Without(full, plan, rooms, missing)
        let fidelity = new IndoorFidelity(AceNeighbourViaVisibleCells: (flags & 1) != 0, AceLoadHintLowKey: (flags & 2) != 0, AceOutsideByCellId: (flags & 4) != 0)
        select new Case(scene, cell, parts, fidelity, portalIndex % cell.Portals.Length);

    // A part around one of the cell's portal planes: its centre at a signed distance from the plane at, just inside
    // and just outside the gate's r + EPS (or anywhere in the room), its box from a point to larger than a door, its
    // frame yawed, and its position framed in the cell's block or in one of the eight around it.
    private static Gen<PartPlan> PartGen(EnvCell cell) =>
        from portal in Gen.Choose(0, cell.Portals.Length - 1)
        from radius in Gen.Frequency((1, Gen.Constant(0f)), (4, Gen.Elements(0.25f, 0.5f, 1.5f).Select(ExactGate)))
        from edge in Gen.Elements(-1, 0, 1, 2)
        from sign in Gen.Elements(-1f, 1f)
        from nudge in Gen.Frequency((3, Gen.Constant(0f)), (2, Gen.Elements(-0.001f, 0.001f, -0.5f, 0.5f, 3f)))
        from along in Gen.Zip(Gen.Choose(-30, 30), Gen.Choose(-30, 30))
        from half in Gen.Elements(0f, 0.05f, 0.2f, 1f, 2.5f)
        from yaw in Gen.Elements(0f, 0.7f, MathF.PI / 2)
        from dx in Gen.Choose(-1, 1)
        from dy in Gen.Choose(-1, 1)
        select new PartPlan(portal, radius, edge == 2 ? nudge : (sign * (radius + LandDefs.Epsilon) * edge) + nudge, new Vector2(along.Item1 * 0.1f, along.Item2 * 0.1f), half, yaw, dx, dy);

    // The radius r whose gate r + EPS is exactly `gate` in float32, so that in an unrotated cottage a centre placed at
    // ±gate from an axis plane sits exactly on the gate's edge (where < and <= differ).
    private static float ExactGate(float gate)
    {
        float r = gate - LandDefs.Epsilon;
        for (int i = 0; i < 8 && r + LandDefs.Epsilon != gate; i++)
        {
            r = r + LandDefs.Epsilon > gate ? MathF.BitDecrement(r) : MathF.BitIncrement(r);
        }

        return r;
    }

    private static CellScene Without(CellScene full, CottagePlan plan, int rooms, int missing)
    {
        var keep = Enumerable.Range(0, rooms + 1).Where(i => i != missing).Select(i => full.GetEnvCell(plan.RoomId(i))).OfType<EnvCell>();
        var blocks = Enumerable.Range(-1, 3).SelectMany(dx => Enumerable.Range(-1, 3).Select(dy => new LandblockId((byte)(plan.Block.X + dx), (byte)(plan.Block.Y + dy))));
        return new CellScene(blocks, keep, full.Buildings.Values);
    }

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

    private static bool Same(CellArray a, CellArray b) =>
        a.Count == b.Count && Enumerable.Range(0, a.Count).All(i => a[i] == b[i]);

    private static string Text(CellArray a) => string.Join(",", Enumerable.Range(0, a.Count).Select(i => $"{a[i].Id}{(a[i].Loaded ? string.Empty : "?")}"));

    private sealed record Case(CellScene Scene, EnvCell Cell, PartPlan[] Plans, IndoorFidelity Fidelity, int PortalIndex)
    {
        public Part[] Parts { get; } = [.. Plans.Select(p => p.At(Cell))];

        public override string ToString() => $"cell {Cell.Id}, {Parts.Length} parts, {Fidelity}";
    }

    private sealed record PartPlan(int Portal, float Radius, float Distance, Vector2 Along, float Half, float Yaw, int BlockDx, int BlockDy)
    {
        // The centre: the room's middle projected onto the portal plane, moved along the plane and then to Distance.
        public Part At(EnvCell cell)
        {
            var plane = cell.Portals[Portal % cell.Portals.Length].Plane;
            var mid = (cell.Volume.Bounds.Min + cell.Volume.Bounds.Max) / 2;
            var foot = mid - (plane.Normal * plane.Distance(mid));
            var t1 = Vector3.Normalize(Vector3.Cross(plane.Normal, MathF.Abs(plane.Normal.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitX));
            var t2 = Vector3.Cross(plane.Normal, t1);
            var local = foot + (t1 * Along.X) + (t2 * Along.Y) + (plane.Normal * Distance);
            var inCellBlock = cell.Frame.LocalToGlobal(local);
            var partCell = new CellId((byte)(cell.Id.BlockX + BlockDx), (byte)(cell.Id.BlockY + BlockDy), 1);
            var origin = inCellBlock - new Vector3(LandDefs.BlockLength * BlockDx, LandDefs.BlockLength * BlockDy, 0);
            return new Part(partCell, new Frame(origin, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Yaw)), new Box(new Vector3(-Half), new Vector3(Half)), Radius, false);
        }
    }
}
