using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Running;

/// <summary>
/// CATALOGUE-JOBS (issue 51): <c>verify --jobs</c> spreads a planted fault over one instance per thread, which is the
/// same run only when no answer depends on the calls before it; the faults that do are listed in
/// <see cref="StatefulFaults"/> and run on one thread. The probe: every query asked of one instance after all the
/// queries before it is answered as a fresh instance answers it alone.
/// </summary>
public sealed class StatefulFaultsTests
{
    private static readonly Rnd Seed = new(0x51, 0x9E3779B97F4A7C15UL);
    private static readonly OutdoorCase[] Outdoor = Gen.Sample(OutdoorGens.Cases, 40, Seed, 50);
    private static readonly PartsCase[] Parts = Gen.Sample(PartsGens.Cases, 20, Seed, 50);
    private static readonly SceneWalk[] Walks = Gen.Sample(SceneGens.Recipes.Select(r => r.Build()), 6, Seed, 50);

    public static TheoryData<string> Faults() => [.. PlantedFaults.All.Select(f => f.Id)];

    [Theory(DisplayName = "CATALOGUE-JOBS: a planted fault answers as a fresh instance after other queries exactly when it is not listed as stateful")]
    [MemberData(nameof(Faults))]
    public void StatefulExactlyWhenListed(string id)
    {
        var fault = PlantedFaults.Find(id)!;
        var used = PlantedFaults.Create(id);
        var queries = Queries(used.Ops);
        var differs = queries
            .Where(q => Answer(q, used) != Answer(q, PlantedFaults.Create(id)))
            .Select(q => q.What)
            .ToList();

        Assert.True(queries.Count >= 40, $"{id}: only {queries.Count} queries probed");
        if (StatefulFaults.All.Contains(fault))
        {
            Assert.True(differs.Count > 0, $"{id} is listed as stateful, but none of {queries.Count} queries answered differently after the others");
        }
        else
        {
            Assert.True(differs.Count == 0, $"{id} answers differently after earlier queries ({differs.Count} of {queries.Count}, first: {differs.FirstOrDefault()}): list it in StatefulFaults");
        }
    }

    private static List<(string What, Func<ICellPhysics, string> Ask)> Queries(Op ops)
    {
        var queries = new List<(string, Func<ICellPhysics, string>)>();
        foreach (var c in Outdoor)
        {
            queries.Add(("find_cell " + c, impl => Text(impl.FindCell(c.Cell, c.Origin, c.Spheres, c.Cell))));
            queries.Add(("outside_cells " + c, impl => string.Join(",", impl.OutsideCells(c.Cell, c.Origin, c.Spheres))));
        }

        foreach (var p in Parts)
        {
            queries.Add(("outside_cells_parts " + p, impl => string.Join(",", impl.OutsideCellsParts(p.Parts))));
        }

        foreach (var sw in Walks)
        {
            foreach (bool loadCells in SceneQueryKinds.Offered(ops))
            {
                queries.Add(($"walk ({(loadCells ? "transition" : "static")}) {sw.Walk}", impl => string.Join(" / ", SceneWalkRunner.Run(impl, sw, loadCells).Select(s => s.Containing + ":" + string.Join(",", s.Cells)))));
            }

            foreach (bool loadCells in new[] { false, true }.Where(l => (ops & (l ? Op.FindCellPartsTransition : Op.FindCellPartsScene)) != 0))
            {
                foreach (var (index, parts) in ScenePartsQueries.Of(sw))
                {
                    queries.Add(($"find_cell_parts step {index} of {sw.Walk}", impl => Text(impl.FindCellParts(sw.Scene, parts, loadCells))));
                }
            }
        }

        return queries;
    }

    private static string Answer((string What, Func<ICellPhysics, string> Ask) query, ICellPhysics impl)
    {
        try
        {
            return query.Ask(impl);
        }
        catch (Exception e) when (e is not Xunit.Sdk.XunitException)
        {
            return "throws " + e.GetType().Name; // checked-cast: an exception is its answer
        }
    }

    private static string Text(FindCellResult r) =>
        $"{r.Containing} [{string.Join(",", r.Cells)}] hits={r.HitsInteriorCell} loaded=[{string.Join(",", r.Loaded ?? [])}]";
}
