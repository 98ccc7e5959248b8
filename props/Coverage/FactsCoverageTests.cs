using System.Reflection;
using System.Text;
using AcPhys.Contract;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Coverage;

/// <summary>
/// The facts-coverage matrix is enforced (issue 27, docs/facts-coverage.md): every rule the facts name is hit by its class
/// on the pr profile, and where something breaks it, the broken reference is judged violated on one of that class's cases —
/// a generated case whose answer depends on the rule. A rule with no hits fails, unless the matrix says why it is out of reach.
/// </summary>
public sealed class FactsCoverageTests(ITestOutputHelper output)
{
    private static readonly Dictionary<string, List<(object Case, HashSet<string> Classes)>> Sweeps = [];

    [Fact(DisplayName = "FACTS-COVERAGE: every rule of the facts is reached by a generated class on the pr profile (the rule broken answers differently on one of its cases), or the matrix says why it is out of reach")]
    public void EveryRuleIsReached()
    {
        var failures = new List<string>();
        var table = new StringBuilder("| facts | rule | class | pr hits | broken by | judge | reached at |\n|---|---|---|---:|---|---|---:|\n");
        foreach (var row in FactsMatrix.Rows)
        {
            if (row.OutOfReach is not null)
            {
                Assert.True(row.OutOfReach.Length > 20, $"{row.Facts}: an out-of-reach row needs its reason");
                table.AppendLine($"| {row.Facts} | {row.Rule} | — | — | {row.Breaker ?? "—"} | — | out of reach: {row.OutOfReach} |");
                continue;
            }

            var judge = InvariantCatalogue.Find(row.Judge!) ?? throw new InvalidOperationException($"{row.Facts}: unknown judge {row.Judge}");
            var sweep = SweepOf(judge);
            var ofClass = sweep.Where(c => c.Classes.Contains(row.Class!)).Select(c => c.Case).ToList();
            string reached = "—";
            if (ofClass.Count == 0)
            {
                failures.Add($"{row.Facts} ({row.Rule}): class {row.Class} has no hits among {judge.Id}'s pr cases (seed {PrSeed(judge)})");
            }
            else if (row.Breaker is not null)
            {
                var broken = Breaker(row.Breaker);
                int at = ofClass.FindIndex(c => Check(judge, broken, c).IsViolation);
                if (at < 0)
                {
                    failures.Add($"{row.Facts} ({row.Rule}): {row.Breaker} is never judged violated by {judge.Id} on the {ofClass.Count} cases of {row.Class} (seed {PrSeed(judge)}; replay: ./acphys verify --only {judge.Id} {ReplayFlag(row.Breaker)})");
                }
                else
                {
                    reached = $"{at + 1} of {ofClass.Count}";
                }
            }

            table.AppendLine($"| {row.Facts} | {row.Rule} | `{row.Class}` | {ofClass.Count:N0} | {row.Breaker ?? "— (no planted fault yet)"} | {judge.Id} | {reached} |");
        }

        output.WriteLine(table.ToString());
        Assert.True(failures.Count == 0, string.Join("\n", failures));
    }

    [Fact(DisplayName = "FACTS-COVERAGE: the matrix names only catalogue invariants, known faults and known deviations")]
    public void MatrixNamesExist()
    {
        foreach (var row in FactsMatrix.Rows)
        {
            Assert.True((row.Class is null) == (row.OutOfReach is not null), $"{row.Facts}: a row has a class or a reason, not both");
            if (row.Judge is not null)
            {
                Assert.NotNull(InvariantCatalogue.Find(row.Judge));
            }

            if (row.Breaker is not null)
            {
                Assert.NotNull(Breaker(row.Breaker));
            }
        }
    }

    private static Seed PrSeed(Invariant judge) => Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id);

    private static string ReplayFlag(string breaker) => breaker.StartsWith("fault:", StringComparison.Ordinal)
        ? "--fault " + breaker["fault:".Length..]
        : "--impl-cmd \"./acphys serve " + (breaker == "deviation:current-first" ? "--pick current-first" : "--fidelity " + breaker["deviation:".Length..]) + " --announce-retail\"";

    // The pr profile's cases of a judge, with their classes: generated once per judge, as the gate generates them.
    private static List<(object Case, HashSet<string> Classes)> SweepOf(Invariant judge)
    {
        lock (Sweeps)
        {
            if (!Sweeps.TryGetValue(judge.Id, out var list))
            {
                list = (List<(object, HashSet<string>)>)typeof(FactsCoverageTests).GetMethod(nameof(Sweep), BindingFlags.NonPublic | BindingFlags.Static)!
                    .MakeGenericMethod(judge.CaseType).Invoke(null, [judge, PrSeed(judge)])!;
                Sweeps[judge.Id] = list;
            }

            return list;
        }
    }

    private static List<(object Case, HashSet<string> Classes)> Sweep<TCase>(Invariant<TCase> judge, Seed seed)
    {
        var list = new List<(object, HashSet<string>)>();
        CaseSweep.Each(judge.Domain, Profile.Pr.CasesPerInvariant, seed, c =>
        {
            list.Add((c!, judge.Domain.Classes(c).ToHashSet()));
            return true;
        });
        return list;
    }

    private static Outcome Check(Invariant judge, ICellPhysics impl, object c) =>
        (Outcome)judge.GetType().GetMethod("Check")!.Invoke(judge, [impl, c])!;

    // A planted fault, or the reference serving a documented deviation while declaring retail.
    private static ICellPhysics Breaker(string breaker)
    {
        if (breaker.StartsWith("fault:", StringComparison.Ordinal))
        {
            return PlantedFaults.Create(breaker["fault:".Length..]);
        }

        string name = breaker["deviation:".Length..];
        if (name == "current-first")
        {
            return PortShimFaults.AnnouncingRetail(ReferenceAdapter.CurrentFirst);
        }

        Assert.True(FidelityNames.TryParse([name], out var indoor, out var outdoor, out _), $"unknown deviation {name}");
        return PortShimFaults.AnnouncingRetail(new ReferenceAdapter(outdoor: outdoor) { Indoor = indoor });
    }
}
