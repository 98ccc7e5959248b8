using System.Diagnostics;
using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Studies.Numerics;

/// <summary>One row of the indoor accuracy table: a source, a room shape and a boundary class.</summary>
/// <param name="Source">Where the queries came from.</param>
/// <param name="Shape">The room shape every cell of the scene was given.</param>
/// <param name="Class">The boundary class (<see cref="IndoorAccuracyClass"/>).</param>
/// <param name="Queries">Queries compared.</param>
/// <param name="CellsDiffer">Queries whose AABB cell set differs from the BSP's (as sets).</param>
/// <param name="PickDiffers">Queries whose AABB containing cell differs.</param>
/// <param name="Any">Queries where either differs.</param>
/// <param name="Reasons">Disagreements by kind (<see cref="IndoorAccuracyRun.Reason"/>).</param>
public sealed record IndoorAccuracyRow(string Source, string Shape, string Class, long Queries, long CellsDiffer, long PickDiffers, long Any, IReadOnlyDictionary<string, long> Reasons);

/// <summary>One example of an AABB-vs-BSP disagreement.</summary>
/// <param name="Source">The source.</param>
/// <param name="Shape">The room shape.</param>
/// <param name="Class">The boundary class.</param>
/// <param name="Reason">The kind.</param>
/// <param name="Text">Where (the nearest cell's local frame), the query and both answers.</param>
public sealed record IndoorAccuracyExample(string Source, string Shape, string Class, string Reason, string Text);

/// <summary>The indoor accuracy measurement.</summary>
/// <param name="Rows">One row per source × shape × class (empty rows included).</param>
/// <param name="Examples">The first example per source × shape × class × reason.</param>
/// <param name="Scenes">Generated scenes (recipes) per shape.</param>
/// <param name="Elapsed">Wall time.</param>
public sealed record IndoorAccuracyReport(IReadOnlyList<IndoorAccuracyRow> Rows, IReadOnlyList<IndoorAccuracyExample> Examples, int Scenes, TimeSpan Elapsed);

/// <summary>
/// Measures how often the AABB cell volumes (<see cref="VolumeMode.Aabb"/>) answer find_cell_list differently from
/// retail's BSP (<see cref="VolumeMode.Bsp"/>, the reference for indoor membership), over generated scenes (the
/// suite's <see cref="SceneGens.Recipes"/>, every room reshaped as a box, an L or stairs by <see cref="RoomShapes"/>):
/// every step of the scene walks (run with BSP cells; the AABB answers the same query), and bodies scattered in and
/// around the rooms, queried from the room and from the land cell. Split by room shape and boundary class.
/// </summary>
public static class IndoorAccuracyRun
{
    /// <summary>Gets the source names, in table order.</summary>
    public static IReadOnlyList<string> Sources { get; } = ["scene walk steps", "scattered bodies"];

    private static readonly ReferenceAdapter Bsp = new() { Volumes = VolumeMode.Bsp };
    private static readonly ReferenceAdapter Aabb = new() { Volumes = VolumeMode.Aabb };

    /// <summary>Runs the measurement.</summary>
    /// <param name="seed">The seed.</param>
    /// <param name="scenes">Generated scene recipes (each is measured in every shape).</param>
    /// <param name="scatter">Scattered bodies per scene and shape.</param>
    /// <returns>The report.</returns>
    public static IndoorAccuracyReport Run(int seed, int scenes, int scatter)
    {
        var stopwatch = Stopwatch.StartNew();
        var recipes = Gen.Sample(SceneGens.Recipes, scenes, new Rnd((ulong)seed, 0x2545F4914F6CDD1DUL), 50);
        var jobs = new List<(string Source, string Shape, Scene Scene, CellId Position, Sphere[] Spheres)>();
        for (int k = 0; k < recipes.Length; k++)
        {
            var built = recipes[k].Build();
            foreach (var shape in RoomShapes.All)
            {
                var scene = RoomShapes.Shaped(built.Scene, shape);
                string name = RoomShapes.Name(shape);
                foreach (var step in SceneWalkRunner.Run(Bsp, new SceneWalk(scene, built.Walk)))
                {
                    jobs.Add((Sources[0], name, scene, step.Query.Cell, [.. step.Query.Spheres]));
                }

                var random = new Random(unchecked((seed * 1_000_003) + (k * 31) + (int)shape)); // not HashCode.Combine: that is salted per process
                for (int i = 0; i < scatter; i++)
                {
                    foreach (var (position, spheres) in Scatter(scene, random))
                    {
                        jobs.Add((Sources[1], name, scene, position, spheres));
                    }
                }
            }
        }

        var results = new (string Class, bool Cells, bool Pick, string Reason, string Detail)[jobs.Count];
        Parallel.For(0, jobs.Count, i =>
        {
            var (_, _, scene, position, spheres) = jobs[i];
            var b = Bsp.FindCell(scene, position, spheres, CellId.None);
            var a = Aabb.FindCell(scene, position, spheres, CellId.None);
            bool cells = !b.Cells.ToHashSet().SetEquals(a.Cells);
            bool pick = b.Containing != a.Containing;
            results[i] = (IndoorAccuracyClass.Of(scene, position, spheres), cells, pick, cells || pick ? Reason(b, a) : string.Empty,
                cells || pick ? $"where {IndoorAccuracyClass.Where(scene, position, spheres[0].Center)}; query {new OutdoorCase(position, spheres)} → BSP [{string.Join(", ", b.Cells)}] pick {b.Containing}; AABB [{string.Join(", ", a.Cells)}] pick {a.Containing}" : string.Empty);
        });

        var rows = new List<IndoorAccuracyRow>();
        var examples = new List<IndoorAccuracyExample>();
        foreach (string source in Sources)
        {
            foreach (string shape in RoomShapes.All.Select(RoomShapes.Name))
            {
                foreach (string cls in IndoorAccuracyClass.All)
                {
                    long n = 0, cells = 0, pick = 0, any = 0;
                    var reasons = new SortedDictionary<string, long>(StringComparer.Ordinal);
                    for (int i = 0; i < results.Length; i++)
                    {
                        var r = results[i];
                        if (jobs[i].Source != source || jobs[i].Shape != shape || r.Class != cls)
                        {
                            continue;
                        }

                        n++;
                        cells += r.Cells ? 1 : 0;
                        pick += r.Pick ? 1 : 0;
                        if (r.Cells || r.Pick)
                        {
                            any++;
                            reasons[r.Reason] = reasons.GetValueOrDefault(r.Reason) + 1;
                            if (!examples.Any(e => e.Source == source && e.Shape == shape && e.Class == cls && e.Reason == r.Reason))
                            {
                                examples.Add(new IndoorAccuracyExample(source, shape, cls, r.Reason, r.Detail));
                            }
                        }
                    }

                    rows.Add(new IndoorAccuracyRow(source, shape, cls, n, cells, pick, any, reasons));
                }
            }
        }

        stopwatch.Stop();
        return new IndoorAccuracyReport(rows, examples, recipes.Length, stopwatch.Elapsed);
    }

    /// <summary>
    /// Names a disagreement: the pick first (<c>pick BSP→AABB</c> with each side env, land or none), else which cells
    /// only one mode has (<c>AABB +env</c>: the AABB added an env cell the BSP did not; <c>−</c>: it lacks one).
    /// </summary>
    /// <param name="bsp">The BSP answer.</param>
    /// <param name="aabb">The AABB answer.</param>
    /// <returns>The kind.</returns>
    public static string Reason(FindCellResult bsp, FindCellResult aabb)
    {
        static string Kind(CellId c) => c.IsNone ? "none" : c.IsEnv ? "env" : "land";
        if (bsp.Containing != aabb.Containing)
        {
            return $"pick {Kind(bsp.Containing)}→{Kind(aabb.Containing)}";
        }

        var extra = aabb.Cells.Except(bsp.Cells).Select(c => "+" + Kind(c));
        var missing = bsp.Cells.Except(aabb.Cells).Select(c => "−" + Kind(c));
        return "AABB " + string.Join(" ", extra.Concat(missing).Distinct().Order(StringComparer.Ordinal));
    }

    // A body (two spheres 0.7 m apart, r 0.25–1 m) uniformly in one cell's box grown by 1.5 m horizontally and 0.5 m
    // vertically, queried from that cell and from the land cell under it (when on the map).
    private static IEnumerable<(CellId Position, Sphere[] Spheres)> Scatter(Scene scene, Random random)
    {
        if (scene.Cells.Count == 0)
        {
            yield break;
        }

        var cell = scene.Cells[random.Next(scene.Cells.Count)];
        var pieces = cell.Pieces.Select(p => p.ToConvex()).ToArray();
        var min = pieces.Select(p => p.Bounds.Min).Aggregate(Vector3.Min) - new Vector3(1.5f, 1.5f, 0.5f);
        var max = pieces.Select(p => p.Bounds.Max).Aggregate(Vector3.Max) + new Vector3(1.5f, 1.5f, 0.5f);
        var local = min + ((max - min) * new Vector3(random.NextSingle(), random.NextSingle(), random.NextSingle()));
        float r = 0.25f + (0.75f * random.NextSingle());
        var centre = new Frame(cell.Origin, cell.Rotation).LocalToGlobal(local);
        Sphere[] spheres = [new Sphere(centre, r), new Sphere(centre + new Vector3(0, 0, 0.7f), r)];
        yield return (cell.Id, spheres);
        var land = cell.Id.Landblock.BlockCell;
        var at = centre;
        if (LandDefs.AdjustToOutside(ref land, ref at))
        {
            var shift = at - centre;
            yield return (land, [.. spheres.Select(s => s with { Center = s.Center + shift })]);
        }
    }
}
