using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Cli.Bench;

/// <summary>The operations <c>acphys bench</c> times: the same inputs as bench/ (BenchmarkDotNet), in both arithmetic modes.</summary>
internal static class BenchOps
{
    private static readonly CellId Cell = new(0xA9B40031);
    private static readonly CellId Position = new(0xA9B40005);
    private static readonly Sphere[] Interior = [new Sphere(new Vector3(12, 100, 0.5f), 0.5f)];
    private static readonly Sphere[] Corner = [new Sphere(new Vector3(0.1f, 0.2f, 0.5f), 0.5f)];
    // Eight inputs cycled by the loops, so the JIT cannot hoist a constant computation out of the loop.
    private static readonly float[] Xs = [150f, -0.5f, 23.99f, 191.9f, -191.5f, 0.0001f, 96f, -12.5f];
    private static readonly double[] XsDouble = [.. Xs.Select(x => (double)x)];
    private static readonly CellId[] Cells = [Cell, new(0xA9B40001), new(0x00000040), new(0xFEFE0021), Cell, new(0x12340008), new(0xA9B40031), new(0x7F7F0011)];

    private static readonly Sphere[] Body = [new Sphere(new Vector3(0.1f, 0.2f, 0.5f), 0.5f), new Sphere(new Vector3(0.1f, 0.2f, 1.5f), 0.5f), new Sphere(new Vector3(191.9f, 23.9f, 0.5f), 0.6f)];

    /// <summary>Gets every operation, float32 and double side by side.</summary>
    public static IReadOnlyList<BenchOp> All { get; } =
    [
        new("LandDefs", "AdjustToOutside, 8 points cycled", "float32", true, AdjustFloat),
        new("LandDefs", "AdjustToOutside, 8 points cycled", "double", true, AdjustDouble),
        new("LandDefs", "GetOutsideLcoord, 8 points cycled", "float32", true, OutsideFloat),
        new("LandDefs", "GetOutsideLcoord, 8 points cycled", "double", true, OutsideDouble),
        new("LandDefs", "GidToLcoord + LcoordToGid, 8 ids cycled", "—", true, RoundTrip),
        .. Modes("outdoor set", "1 sphere, cell interior (1 cell)", (array, fidelity) => Set(array, Interior, fidelity)),
        .. Modes("outdoor set", "1 sphere, 4-block corner (4 cells)", (array, fidelity) => Set(array, Corner, fidelity)),
        .. Modes("outdoor set", "3 spheres across lines", (array, fidelity) => Set(array, Body, fidelity)),
        .. Modes("find_cell_list outdoor", "corner, retail pick", (array, fidelity) => (long)CellQuery.FindCellListOutdoor(array, Position, Corner, CellId.None, PickPolicy.Retail, OpenLand.Instance, fidelity).Value),
        .. Modes("find_cell_list outdoor", "corner, current-first pick", (array, fidelity) => (long)CellQuery.FindCellListOutdoor(array, Position, Corner, new CellId(0xA9B40001), PickPolicy.CurrentFirst, OpenLand.Instance, fidelity).Value),
        .. IndoorBenchCases.All.SelectMany(Indoor),
    ];

    // find_cell_list in a scene (the case's options: a movement query unless stated), BSP cells then AABB cells.
    private static IEnumerable<BenchOp> Indoor(IndoorBenchCase c)
    {
        foreach (var mode in new[] { VolumeMode.Bsp, VolumeMode.Aabb })
        {
            var scene = SceneBuild.Build(c.Description, mode);
            var array = new CellArray();
            var spheres = c.Spheres;
            long Once()
            {
                var result = SceneQuery.FindCellList(array, scene, c.Position, spheres, c.Position, c.Options);
                return result.Containing.Value + array.Count;
            }

            Once(); // grow the array once: steady state is allocation-free
            yield return new BenchOp($"find_cell_list indoor, {c.Scene}", c.Name, mode == VolumeMode.Bsp ? "BSP" : "AABB", true, n =>
            {
                long sum = 0;
                for (int i = 0; i < n; i++)
                {
                    sum += Once();
                }

                return sum;
            });
        }
    }

    private static IEnumerable<BenchOp> Modes(string group, string name, Func<CellArray, OutdoorFidelity, long> body)
    {
        foreach (var (mode, fidelity) in new[] { ("float32", OutdoorFidelity.Retail), ("double", OutdoorFidelity.Double) })
        {
            var array = new CellArray();
            body(array, fidelity); // grow the array once: steady state is allocation-free
            yield return new BenchOp(group, name, mode, true, n =>
            {
                long sum = 0;
                for (int i = 0; i < n; i++)
                {
                    sum += body(array, fidelity);
                }

                return sum;
            });
        }
    }

    private static long Set(CellArray array, Sphere[] spheres, OutdoorFidelity fidelity)
    {
        array.Reset();
        OutdoorCells.AddAllOutsideCells(array, Position, Vector3.Zero, spheres, OpenLand.Instance, fidelity);
        return array.Count;
    }

    private static long AdjustFloat(int n)
    {
        long sum = 0;
        for (int i = 0; i < n; i++)
        {
            var id = Cell;
            float x = Xs[i & 7], y = Xs[(i + 1) & 7];
            LandDefs.AdjustToOutside(ref id, ref x, ref y);
            sum += id.Value;
        }

        return sum;
    }

    private static long AdjustDouble(int n)
    {
        long sum = 0;
        for (int i = 0; i < n; i++)
        {
            var id = Cell;
            double x = XsDouble[i & 7], y = XsDouble[(i + 1) & 7];
            LandDefs.AdjustToOutsideInDouble(ref id, ref x, ref y);
            sum += id.Value;
        }

        return sum;
    }

    private static long OutsideFloat(int n)
    {
        long sum = 0;
        for (int i = 0; i < n; i++)
        {
            LandDefs.GetOutsideLcoord(Cell, Xs[i & 7], Xs[(i + 1) & 7], out var lc);
            sum += lc.X;
        }

        return sum;
    }

    private static long OutsideDouble(int n)
    {
        long sum = 0;
        for (int i = 0; i < n; i++)
        {
            LandDefs.GetOutsideLcoordInDouble(Cell, XsDouble[i & 7], XsDouble[(i + 1) & 7], out var lc);
            sum += lc.X;
        }

        return sum;
    }

    private static long RoundTrip(int n)
    {
        long sum = 0;
        for (int i = 0; i < n; i++)
        {
            LandDefs.GidToLcoord(Cells[i & 7], out var lc);
            sum += LandDefs.LcoordToGid(lc).Value;
        }

        return sum;
    }
}
