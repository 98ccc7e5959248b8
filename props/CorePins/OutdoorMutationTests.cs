using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// Outdoor membership statements (facts §3.1–§3.3, §4 step 4b, §5.9, §7 #2) checked where the mutation run found them
/// untested: the cell array's own contract, check_add_cell_boundary at its strict edges, the no-sphere variant, and
/// which candidates the outdoor pick may choose.
/// </summary>
public sealed class OutdoorMutationTests
{
    private enum OpKind
    {
        Add,
        Remove,
        Reset,
    }

    [FixedSeedProperty(0x0C7D_0001, DisplayName = "facts §5.9: CellArray keeps insertion order, ignores a duplicate, removes by moving the last entry into the hole, Reset truncates and clears the latch")]
    public Property CellArray_BehavesAsTheRetailOrderedSet() =>
        Prop.ForAll(Gen.Zip(Gen.Elements(-3, 0, 1, 2, 4, 16), Ops.ListOf()).ToArbitrary(), t =>
        {
            var (capacity, ops) = t;
            var array = new CellArray(capacity);
            var model = new List<CellEntry>();
            foreach (var (kind, id, loaded) in ops)
            {
                switch (kind)
                {
                    case OpKind.Add:
                        bool fresh = !model.Exists(e => e.Id == id);
                        if (fresh)
                        {
                            model.Add(new CellEntry(id, loaded));
                        }

                        array.AddedOutside = true;
                        if (array.Add(id, loaded) != fresh)
                        {
                            return false;
                        }

                        break;
                    case OpKind.Remove:
                        int at = model.FindIndex(e => e.Id == id);
                        if (at >= 0)
                        {
                            model[at] = model[^1];
                            model.RemoveAt(model.Count - 1);
                        }

                        if (array.Remove(id) != at >= 0)
                        {
                            return false;
                        }

                        break;
                    default:
                        model.Clear();
                        array.Reset();
                        if (array.AddedOutside)
                        {
                            return false;
                        }

                        break;
                }

                if (!SameAs(array, model))
                {
                    return false;
                }
            }

            return true;
        });

    [Fact(DisplayName = "facts §5.9: CellArray's indexer refuses -1, Count and beyond with ArgumentOutOfRangeException, even where capacity is spare")]
    public void CellArray_IndexerRefusesOutsideCount()
    {
        var array = new CellArray(16);
        array.Add(new CellId(0xA9B40001), true);
        array.Add(new CellId(0xA9B40002), false);
        array.Remove(new CellId(0xA9B40002));
        Assert.Equal(new CellEntry(new CellId(0xA9B40001), true), array[0]);
        Assert.All(new[] { -1, 1, 2, 15, 16, int.MaxValue, int.MinValue }, i => Assert.Throws<ArgumentOutOfRangeException>(() => array[i]));
    }

    [FixedSeedProperty(0x0C7D_0002, DisplayName = "facts §3.2: check_add_cell_boundary adds exactly the neighbours of the strict per-axis rule, in retail's call order, skipping off-map lcoords")]
    public Property CheckAddCellBoundary_IsTheStrictPerAxisRuleInCallOrder() =>
        Prop.ForAll(FixedSeed.Zip(Radii, Gen.Zip(Gen.Choose(0, 9), Gen.Choose(0, 9)), Gen.Zip(MapEdgeInts, MapEdgeInts)).ToArbitrary(), t =>
        {
            var (r, (px, py), (x, y)) = t;
            float minRad = r, maxRad = LandDefs.CellLength - r;
            float ptX = InCellPoint(px, r), ptY = InCellPoint(py, r);
            var array = new CellArray();
            OutdoorCells.CheckAddCellBoundary(array, ptX, ptY, new Lcoord(x, y), minRad, maxRad, OpenLand.Instance, OutdoorFidelity.Retail);

            var expected = new List<CellId>();
            void Add(int dx, int dy)
            {
                var id = LandDefs.LcoordToGid(x + dx, y + dy);
                if (!id.IsNone && !expected.Contains(id))
                {
                    expected.Add(id);
                }
            }

            if (ptX > maxRad)
            {
                Add(1, 0);
                if (ptY > maxRad)
                {
                    Add(1, 1);
                }

                if (ptY < minRad)
                {
                    Add(1, -1);
                }
            }

            if (ptX < minRad)
            {
                Add(-1, 0);
                if (ptY > maxRad)
                {
                    Add(-1, 1);
                }

                if (ptY < minRad)
                {
                    Add(-1, -1);
                }
            }

            if (ptY > maxRad)
            {
                Add(0, 1);
            }

            if (ptY < minRad)
            {
                Add(0, -1);
            }

            return array.ToIdArray().SequenceEqual(expected);
        });

    [FixedSeedProperty(0x0C7D_0003, DisplayName = "facts §3.3 step 3: with no spheres, add_all_outside_cells adds the one land cell AdjustToOutside gives the position, or nothing, and sets the latch")]
    public Property AddAllOutsideCells_NoSpheresAddsThePositionsColumn() =>
        Prop.ForAll(Gen.Zip(Positions, Points).ToArbitrary(), t =>
        {
            var (position, origin) = t;
            var array = new CellArray();
            OutdoorCells.AddAllOutsideCells(array, position, origin, ReadOnlySpan<Sphere>.Empty, OpenLand.Instance);
            var id = position;
            float x = origin.X, y = origin.Y;
            CellId[] expected = LandDefs.AdjustToOutside(ref id, ref x, ref y) ? [id] : [];
            return array.AddedOutside && array.ToIdArray().SequenceEqual(expected);
        });

    [FixedSeedProperty(0x0C7D_0004, DisplayName = "facts §4 step 4: find_cell_list with no spheres collects the position's column and picks nothing")]
    public Property FindCellListOutdoor_NoSpheresPicksNothing() =>
        Prop.ForAll(Positions.ToArbitrary(), position =>
        {
            var array = new CellArray();
            array.Add(new CellId(0x01010001), true); // stale: the query truncates first
            var pick = CellQuery.FindCellListOutdoor(array, position, ReadOnlySpan<Sphere>.Empty, position, PickPolicy.CurrentFirst, OpenLand.Instance);
            var id = position;
            float x = 0f, y = 0f;
            CellId[] expected = LandDefs.AdjustToOutside(ref id, ref x, ref y) ? [id] : [];
            return pick == CellId.None && array.ToIdArray().SequenceEqual(expected);
        });

    [Fact(DisplayName = "facts §4 step 4b: the outdoor pick chooses only loaded land cells; a loaded env id or an unloaded land cell whose square holds the centre is skipped")]
    public void PickOutdoor_ChoosesOnlyLoadedLandCells()
    {
        var position = new CellId(0xA9B40005);

        var envOnly = new CellArray();
        envOnly.Add(new CellId(0xA9B40100), true); // as a land index, 0x100 would be the square x 744..768, y 168..192
        Assert.Equal(CellId.None, ContainingCell.PickOutdoor(envOnly, position, new Vector3(750f, 170f, 0f), PickPolicy.Retail, CellId.None));

        var hintOnly = new CellArray();
        hintOnly.Add(new CellId(0xA9B40001), false);
        Assert.Equal(CellId.None, ContainingCell.PickOutdoor(hintOnly, position, new Vector3(12f, 12f, 0f), PickPolicy.Retail, CellId.None));
        Assert.Equal(CellId.None, ContainingCell.PickOutdoor(hintOnly, position, new Vector3(12f, 12f, 0f), PickPolicy.CurrentFirst, new CellId(0xA9B40001)));

        var both = new CellArray();
        both.Add(new CellId(0xA9B40001), true);
        both.Add(new CellId(0xA9B40100), true);
        Assert.Equal(new CellId(0xA9B40001), ContainingCell.PickOutdoor(both, position, new Vector3(12f, 12f, 0f), PickPolicy.Retail, CellId.None));
    }

    [FixedSeedProperty(0x0C7D_0005, DisplayName = "facts §3.1 and §7 #2: add_outside_cell adds an on-map cell with its block's loaded state (retail), or only when loaded (ACE)")]
    public Property AddOutsideCell_RetailHintsAceDrops() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(MapEdgeInts, MapEdgeInts), Gen.Elements(true, false)).ToArbitrary(), t =>
        {
            var ((x, y), ace) = t;
            var fidelity = ace ? OutdoorFidelity.Ace : OutdoorFidelity.Retail;
            var array = new CellArray();
            OutdoorCells.AddOutsideCell(array, x, y, Checkerboard.Instance, fidelity);
            var id = LandDefs.LcoordToGid(x, y);
            bool loaded = !id.IsNone && Checkerboard.Instance.IsLoaded(id.Landblock);
            CellEntry[] expected = id.IsNone || (ace && !loaded) ? [] : [new CellEntry(id, loaded)];
            return fidelity.DropUnloadedCells == ace && CellArrays.Entries(array).SequenceEqual(expected);
        });

    /// <summary>Sequences of array operations over a small pool of ids, so duplicates and removals of present ids are common.</summary>
    private static Gen<(OpKind Kind, CellId Id, bool Loaded)> Ops { get; } =
        FixedSeed.Zip(
            Gen.Frequency((6, Gen.Constant(OpKind.Add)), (3, Gen.Constant(OpKind.Remove)), (1, Gen.Constant(OpKind.Reset))),
            Gen.Choose(1, 12).Select(i => new CellId(0xA9, 0xB4, (ushort)i)),
            Gen.Elements(true, false));

    /// <summary>Radii: zero, typical, around 12 (where minRad and maxRad cross) and beyond 24.</summary>
    private static Gen<float> Radii { get; } = Gen.Elements(0f, 0.5f, 1f, 11.5f, 12f, 12.5f, 20f, 24f, 30f);

    /// <summary>Global lcoords on and next to both map edges, and anywhere.</summary>
    private static Gen<int> MapEdgeInts { get; } = Gen.Frequency(
        (2, Gen.Elements(-1, 0, 1, 2038, 2039, 2040)),
        (1, Gen.Choose(0, 2039)));

    /// <summary>Positions of every low-word class, on and off the map.</summary>
    private static Gen<CellId> Positions { get; } = Gen.Frequency(
        (4, FixedSeed.Zip(FixedSeed.Bytes, FixedSeed.Bytes, Gen.Elements<ushort>(1, 5, 64, 0x100, 0xFFFD, 0xFFFF)).Select(t => new CellId(t.Item1, t.Item2, t.Item3))),
        (1, Gen.Elements(CellId.None, new CellId(0xA9B40000), new CellId(0xA9B40041), new CellId(0xA9B4FFFE))));

    /// <summary>Block-frame coordinates: anywhere in the block, on cell and block lines, just outside it.</summary>
    private static Gen<float> Coordinate { get; } = Gen.Frequency(
        (3, Gen.Choose(0, 191_999).Select(i => i / 1000f)),
        (1, Gen.Elements(0f, 24f, 191.999f, 192f, -0.5f, -0.0001f, -200f, 400f)));

    /// <summary>Block-frame points inside, on the edge of and outside the block.</summary>
    private static Gen<Vector3> Points { get; } = Gen.Zip(Coordinate, Coordinate).Select(t => new Vector3(t.Item1, t.Item2, 3f));

    private static float InCellPoint(int choice, float r) => choice switch
    {
        0 => r,
        1 => MathF.BitDecrement(r),
        2 => MathF.BitIncrement(r),
        3 => LandDefs.CellLength - r,
        4 => MathF.BitDecrement(LandDefs.CellLength - r),
        5 => MathF.BitIncrement(LandDefs.CellLength - r),
        6 => 0f,
        7 => 12f,
        8 => 23.999998f,
        _ => 0.25f,
    };

    private static bool SameAs(CellArray array, List<CellEntry> model)
    {
        if (array.Count != model.Count || !CellArrays.Entries(array).SequenceEqual(model) || !array.ToIdArray().SequenceEqual(model.Select(e => e.Id)))
        {
            return false;
        }

        for (ushort low = 1; low <= 12; low++)
        {
            var id = new CellId(0xA9, 0xB4, low);
            int at = model.FindIndex(e => e.Id == id);
            if (array.IndexOf(id) != at || array.Contains(id) != at >= 0)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Loads the landblocks whose bytes have an even sum.</summary>
    private sealed class Checkerboard : ILandscape
    {
        public static Checkerboard Instance { get; } = new();

        public bool IsLoaded(LandblockId block) => ((block.X + block.Y) & 1) == 0;
    }
}
