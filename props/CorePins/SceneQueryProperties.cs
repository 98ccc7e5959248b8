using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;
using static AcPhys.Props.Mutation.CellArrays;

namespace AcPhys.Props.Mutation;

/// <summary>
/// find_cell_list's outputs other than the pick (facts §4) as statements over generated queries: cottages (yaw, 1–3
/// rooms, storey, back door) with their block or neighbours sometimes unloaded; positions indoor (a room, a room the
/// scene lacks, the block id), outdoor (the centre's land cell, a land cell of a neighbouring block, an out-of-range
/// low word); 0–3 spheres at a door or anywhere near the cottage; every pick policy, LoadCells and ACE switch, with a
/// stale array from an earlier query when ACE keeps stale cells. <see cref="SceneQueryMutationTests"/> has one worked
/// example per statement.
/// </summary>
public sealed class SceneQueryProperties
{
    [FixedSeedProperty(0x5C0E_0001, DisplayName = "facts §4 step 3, §5.3: HitsInteriorCell is set iff the position is indoor or an env cell joined the array (building entry, or the interior pick it makes possible)")]
    public Property HitsInteriorCell_IsIndoorOrAnEnvCellJoined() =>
        Prop.ForAll(Queries.ToArbitrary(), q =>
        {
            var fresh = q with { Options = q.Options with { LoadCells = true, Fidelity = q.Fidelity with { AceKeepsStaleCells = false } } };
            var (result, array) = fresh.Run();
            bool envJoined = array.ToIdArray().Any(id => id.IsEnv);
            bool expected = q.Position.IsIndoorByLowWord || envJoined;
            return (result.HitsInteriorCell == expected).Label($"{q}: hits {result.HitsInteriorCell}, array {Text(array)}")
                .Classify(q.Position.IsIndoorByLowWord, "indoor").Classify(!q.Position.IsIndoorByLowWord && envJoined, "outdoor, entered");
        });

    [FixedSeedProperty(0x5C0E_0002, DisplayName = "facts §4 step 2: a position with no visible cell (id 0, an out-of-range low word, an unloaded block, a room the scene lacks) is neither walked nor picked from, stale cells or not")]
    public Property InvisiblePosition_PicksNothing() =>
        Prop.ForAll(Queries.ToArbitrary(), q =>
        {
            bool visible = q.Position.IsIndoorByLowWord
                ? q.Scene.GetEnvCell(q.Position) is not null
                : q.Position.IsLand && q.Scene.IsLoaded(q.Position.Landblock);
            var (result, _) = q.Run();
            bool ok = visible || (result.Containing == CellId.None && result.HitsInteriorCell == q.Position.IsIndoorByLowWord);
            return ok.Label($"{q}: {result}").Classify(!visible, "invisible").Classify(!visible && q.Stale, "invisible, stale array");
        });

    [FixedSeedProperty(0x5C0E_0003, DisplayName = "facts §4 step 4a: whenever a loaded land cell is walked, the position's own outdoor cells are in the array (LandCell.find_transit_cells runs add_all_outside_cells first)")]
    public Property WalkedLandCell_BringsThePositionsOutdoorCells() =>
        Prop.ForAll(Queries.ToArbitrary(), q =>
        {
            var probe = q with { Options = q.Options with { LoadCells = true } }; // no filter: what was added stays
            var (_, array) = probe.Run();
            bool walked = q.Spheres.Length > 0 && q.Scene.GetEnvCell(q.Position) is not null
                && Entries(array).Any(e => e.Loaded && e.Id.IsLand);
            var outdoor = new CellArray();
            OutdoorCells.AddAllOutsideCells(outdoor, q.Position, Vector3.Zero, q.Spheres, q.Scene, q.Fidelity.Outdoor);
            bool ok = !walked || outdoor.ToIdArray().All(array.Contains);
            return ok.Label($"{q}: {Text(array)} lacks some of {Text(outdoor)}")
                .Classify(walked, "indoor position, a land cell walked").Classify(walked && q.Stale, "stale land cell walked");
        });

    [FixedSeedProperty(0x5C0E_0004, DisplayName = "facts §4 step 5: indoors without LoadCells, the filter leaves only the position, the loaded cells it sees and load hints, unless ACE returned early from an interior pick")]
    public Property IndoorFilter_RunsUnlessAceReturnedEarly() =>
        Prop.ForAll(Queries.ToArbitrary(), q =>
        {
            var probe = q with { Options = q.Options with { LoadCells = false } };
            var (result, array) = probe.Run();
            var visible = q.Scene.GetEnvCell(q.Position);
            bool guard = q.Fidelity.AceFilterOutsideGuard || (visible is not null && q.Spheres.Length > 0);
            bool earlyReturn = q.Fidelity.AceEarlyReturn && probe.Options.Pick && visible is not null && q.Spheres.Length > 0 && result.Containing.IsEnv;
            bool filtered = q.Position.IsIndoorByLowWord && guard && !earlyReturn;
            bool ok = !filtered || Entries(array).All(e =>
                !e.Loaded || e.Id == q.Position || (visible is not null && visible.Sees(e.Id) && q.Scene.GetEnvCell(e.Id) is not null));
            return ok.Label($"{q}: {Text(array)}")
                .Classify(filtered && !probe.Options.Pick, "filtered, no pick").Classify(earlyReturn, "ACE early return");
        });

    [FixedSeedProperty(0x5C0E_0005, DisplayName = "facts §4 step 4b: current-first differs from the retail pick only by keeping a held, loaded current cell that still contains the centre (an env cell always, a land cell unless an env cell contains it); interior iff an env cell is the answer")]
    public Property CurrentFirst_IsTheRetailPickUnlessTheCurrentCellStillHolds() =>
        Prop.ForAll(Queries.ToArbitrary(), q =>
        {
            var candidates = new CellArray();
            SceneQuery.FindCellList(candidates, q.Scene, q.Position, q.Spheres, CellId.None, q.Options with { Pick = false, LoadCells = true });
            var centre = q.Spheres.Length > 0 ? q.Spheres[0].Center : Vector3.Zero;
            var options = q.Options with { Policy = PickPolicy.CurrentFirst };
            var retail = SceneQuery.PickContaining(candidates, q.Scene, q.Position, centre, CellId.None, q.Options with { Policy = PickPolicy.Retail }, out _);
            var pick = SceneQuery.PickContaining(candidates, q.Scene, q.Position, centre, q.Current, options, out bool interior);

            int at = candidates.IndexOf(q.Current);
            bool holds = !q.Current.IsNone && at >= 0 && candidates[at].Loaded && SceneQuery.Contains(q.Scene, q.Position, q.Current, centre, q.Fidelity);
            var expected = holds && (q.Current.IsEnv || (q.Current.IsLand && !retail.IsEnv)) ? q.Current : retail;
            return (pick == expected && interior == expected.IsEnv).Label($"{q}: {pick} {interior} vs {expected}")
                .Classify(holds, "current still holds").Classify(at < 0 && !q.Current.IsNone, "current not in the array");
        });

    [FixedSeedProperty(0x5C0E_0006, DisplayName = "facts §4 step 2, §5.3: a scene answers an env cell or a building iff it was declared and its block is loaded")]
    public Property CellScene_AnswersOnlyDeclaredCellsOfLoadedBlocks() =>
        Prop.ForAll(FixedSeed.Zip(Plans, Gen.Choose(0, 511), Gen.Choose(0, 7)).ToArbitrary(), t =>
        {
            var (plan, mask, extra) = t;
            var full = SceneBuild.Build(SceneKit.Cottage(plan));
            var blocks = CottageProbe.Around(plan.Block).Where((_, i) => (mask & (1 << i)) != 0).ToArray();
            var scene = new CellScene(blocks, Rooms(full, plan), full.Buildings.Values);
            bool loaded = blocks.Contains(plan.Block);
            var room = plan.RoomId(extra % (plan.Rooms + 2)); // one past the rooms (and the storey) is never declared
            bool declared = full.GetEnvCell(room) is not null;
            var owner = full.Buildings.Keys.Single();
            bool ok = (scene.GetEnvCell(room) is not null) == (declared && loaded)
                && (scene.GetBuilding(owner) is not null) == loaded
                && scene.GetBuilding(owner.WithLow((ushort)((owner.Low % 64) + 1))) is null;
            return ok.Classify(loaded, "block loaded").Classify(declared, "declared");
        });

    private static Gen<CottagePlan> Plans { get; } =
        from blockX in Gen.Choose(2, 250)
        from blockY in Gen.Choose(2, 250)
        from at in Gen.Zip(Gen.Choose(30, 160), Gen.Choose(30, 160))
        from yaw in Gen.Elements(0f, MathF.PI / 2, 0.3f)
        from rooms in Gen.Choose(1, 3)
        from flips in Gen.Choose(0, 15)
        from backDoor in Gen.Elements(false, true)
        from storey in Gen.Elements(false, true)
        from neighbours in Gen.Elements(true, true, false)
        select new CottagePlan((blockX * 192.0) + at.Item1, (blockY * 192.0) + at.Item2, yaw, rooms, 6f, 6f, flips, backDoor, storey, neighbours);

    private static Gen<IndoorFidelity> Fidelities { get; } = Gen.Frequency(
        (1, Gen.Constant(IndoorFidelity.Retail)),
        (1, Gen.Constant(IndoorFidelity.Ace)),
        (2, Gen.Choose(0, 511).Select(f => new IndoorFidelity(
            (f & 1) != 0, (f & 2) != 0, (f & 4) != 0, (f & 8) != 0, (f & 16) != 0, (f & 32) != 0, (f & 64) != 0, (f & 128) != 0, (f & 256) != 0))));

    private static Gen<Query> Queries { get; } =
        from plan in Plans
        let full = SceneBuild.Build(SceneKit.Cottage(plan))
        from blockUnloaded in Gen.Elements(false, false, false, true)
        let scene = blockUnloaded ? new CellScene(CottageProbe.Around(plan.Block).Where(b => b != plan.Block), Rooms(full, plan), full.Buildings.Values) : full
        from room in Gen.Choose(0, plan.Rooms - 1)
        let cell = full.GetEnvCell(plan.RoomId(room))!
        from point in Gen.Frequency((2, DoorPoint(cell)), (1, Gen.Zip(Gen.Choose(-30, 30), Gen.Choose(-30, 30)).Select(p => plan.Origin + new Vector3(p.Item1 * 0.7f, p.Item2 * 0.7f, 1))))
        from count in Gen.Frequency((1, Gen.Constant(0)), (5, Gen.Choose(1, 3)))
        from radii in Gen.Elements(0f, 0.3f, 0.5f, 1.5f).ArrayOf(count)
        from jitter in Gen.Choose(-10, 10).Three().ArrayOf(count)
        from kind in Gen.Frequency((4, Gen.Constant(0)), (4, Gen.Constant(1)), (2, Gen.Constant(2)), (1, Gen.Constant(3)), (1, Gen.Constant(4)), (1, Gen.Constant(5)))
        from shift in Gen.Zip(Gen.Choose(-1, 1), Gen.Choose(-1, 1))
        from low in Gen.Elements<ushort>(0x0000, 0x0041, 0x0080, 0x00FF)
        let posBlock = kind == 2 ? new LandblockId((byte)(plan.Block.X + shift.Item1), (byte)(plan.Block.Y + shift.Item2)) : plan.Block
        let offset = new Vector3(LandDefs.BlockLength * (posBlock.X - plan.Block.X), LandDefs.BlockLength * (posBlock.Y - plan.Block.Y), 0)
        let spheres = Enumerable.Range(0, count).Select(i => new Sphere(point - offset + (i == 0 ? Vector3.Zero : new Vector3(jitter[i].Item1, jitter[i].Item2, jitter[i].Item3) * 0.1f), radii[i])).ToArray()
        let position = kind switch
        {
            0 => plan.RoomId(room),
            1 => LandAt(plan.Block, point),
            2 => LandAt(posBlock, point - offset),
            3 => low == 0 ? CellId.None : plan.Block.BlockCell.WithLow(low),
            4 => plan.RoomId(plan.Rooms + 1), // never declared
            _ => plan.Block.BlockCell,
        }
        from fidelity in Fidelities
        from policy in Gen.Elements(PickPolicy.Retail, PickPolicy.CurrentFirst)
        from pick in Gen.Frequency((1, Gen.Constant(false)), (3, Gen.Constant(true)))
        from loadCells in Gen.Elements(false, true)
        from currentKind in Gen.Choose(0, 3)
        let current = currentKind switch { 0 => CellId.None, 1 => cell.Id, 2 => LandAt(plan.Block, point), _ => plan.RoomId(plan.Rooms + 1) }
        from stalePoint in Gen.Frequency((1, Gen.Constant(point)), (1, Gen.Zip(Gen.Choose(5, 185), Gen.Choose(5, 185)).Select(p => new Vector3(p.Item1, p.Item2, 1))))
        select new Query(scene, position, spheres, current, new CellQueryOptions(policy, pick, loadCells, fidelity), LandAt(plan.Block, stalePoint), stalePoint);

    // A point by one of the cell's portal planes (a door, an inner wall or the ceiling), on it or up to 1 m off.
    private static Gen<Vector3> DoorPoint(EnvCell cell) =>
        from portal in Gen.Choose(0, cell.Portals.Length - 1)
        from distance in Gen.Elements(-1f, -0.4f, -0.1f, 0f, 0.1f, 0.4f, 1f)
        from along in Gen.Choose(-20, 20)
        select CottageProbe.OnPlane(cell, portal, distance, new Vector2(along * 0.1f, 0));

    private static IEnumerable<EnvCell> Rooms(CellScene full, CottagePlan plan) =>
        Enumerable.Range(0, plan.Rooms + 1).Select(i => full.GetEnvCell(plan.RoomId(i))).OfType<EnvCell>();

    // The land cell of `block` whose square holds a block-frame point (facts §1.2: low = 8·⌊x/24⌋ + ⌊y/24⌋ + 1), clamped
    // into the block so that a point across a block line still names a cell of this block.
    private static CellId LandAt(LandblockId block, Vector3 p) =>
        block.BlockCell.WithLow((ushort)((Math.Clamp((int)MathF.Floor(p.X / 24), 0, 7) * 8) + Math.Clamp((int)MathF.Floor(p.Y / 24), 0, 7) + 1));

    private sealed record Query(CellScene Scene, CellId Position, Sphere[] Spheres, CellId Current, CellQueryOptions Options, CellId StaleLand, Vector3 StalePoint)
    {
        public IndoorFidelity Fidelity => Options.Fidelity;

        public bool Stale => Fidelity.AceKeepsStaleCells;

        // ACE's array outlives a call: an earlier outdoor query leaves its cells in it (facts §7 #6).
        public (CellQueryResult Result, CellArray Array) Run()
        {
            var array = new CellArray();
            if (Stale)
            {
                SceneQuery.FindCellList(array, Scene, StaleLand, [new Sphere(StalePoint, 0.5f)], CellId.None, Options with { LoadCells = true });
            }

            return (SceneQuery.FindCellList(array, Scene, Position, Spheres, Current, Options), array);
        }

        public override string ToString() =>
            $"position {Position}, spheres {string.Join("; ", Spheres)}, current {Current}, {Options}{(Stale ? $", stale from {StaleLand} {StalePoint}" : string.Empty)}";
    }
}
