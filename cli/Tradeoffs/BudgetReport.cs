using System.Globalization;
using System.Text;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Running;
using AcPhys.Studies.Running;
using static AcPhys.Cli.Tradeoffs.Markdown;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>
/// The verification budget curve (docs/tradeoffs.md): detection probability of every known-bug catalogue entry
/// (outdoor and indoor) against the budget in cases per invariant and in seconds, for the pr profile (its fixed seed)
/// and nightly-style fresh seeds;
/// CSV files for the plot, and markdown tables.
/// </summary>
internal static class BudgetReport
{
    /// <summary>Gets the budgets (cases per invariant) on the curve.</summary>
    public static IReadOnlyList<int> Budgets { get; } = [1, 2, 3, 5, 10, 30, 100, 300, 1_000, 5_000, 20_000];

    /// <summary>Runs the measurement.</summary>
    /// <param name="seeds">Independent seeds per fault.</param>
    /// <param name="maxCases">The cap in cases per invariant.</param>
    /// <param name="outDir">Where the CSV files go, or null for none.</param>
    /// <param name="fuzzCsv">docs/tradeoffs/fuzz-first-crash.csv (fault,target,seconds,execs,source; seconds "&gt;S" = no crash in S seconds), or null.</param>
    /// <returns>0.</returns>
    public static int Run(int seeds, int maxCases, string? outDir, string? fuzzCsv)
    {
        var fuzz = ReadFuzz(fuzzCsv);
        Terminal.Line($"<!-- acphys tradeoffs budget --seeds {seeds} --max-cases {maxCases}; {Machine.Describe()} at start -->");
        var budgets = Budgets.Where(b => b <= maxCases).ToList();
        ulong prSeed = Profile.Pr.BaseSeed!.Value;
        int prCases = Profile.Pr.CasesPerInvariant, nightlyCases = Profile.Nightly.CasesPerInvariant;
        const ulong master = 0x8B4D6E7_2026UL;

        // Every known-bug catalogue entry whose fault exists, with the catalogue's own catchers.
        var bugs = KnownBugCatalogue.All.Where(b => b.IsAvailable).ToList();
        var rows = new List<(KnownBug Bug, bool Indoor, string? Sweep, DetectionSample Pr, List<DetectionSample> Fresh)>();
        foreach (var bug in bugs)
        {
            var fault = bug.PlantedFault!;
            var pr = BudgetCurve.Measure(fault, prSeed, Math.Max(maxCases, prCases), bug.CaughtBy);
            var fresh = new List<DetectionSample>();
            for (int i = 0; i < seeds; i++)
            {
                fresh.Add(BudgetCurve.Measure(fault, BudgetCurve.SeedAt(master, i), maxCases, bug.CaughtBy));
            }

            rows.Add((bug, IndoorFaults.All.Contains(fault), BudgetCurve.CaughtBySweeps(fault), pr, fresh));
            Console.Error.WriteLine($"  {bug.Id}: pr {pr.CasesToDetect?.ToString(CultureInfo.InvariantCulture) ?? "-"}, fresh median {Median(fresh)}");
        }

        // The seconds axis: the catalogue's cost per case, timed at the largest budget (small budgets are all timer
        // noise on a shared machine), times the budget. Measured times are printed beside the model.
        BudgetCurve.CatalogueTime(30, prSeed); // warm-up: JIT and generator set-up out of the timing
        var measured = budgets.Where(b => b >= 1_000).ToDictionary(b => b, b => BudgetCurve.CatalogueTime(b, prSeed).TotalSeconds);
        double perCase = measured[budgets.Max()] / budgets.Max();
        var seconds = budgets.ToDictionary(b => b, b => b * perCase);
        Terminal.Line($"<!-- catalogue timed; {Machine.Describe()} -->");

        Terminal.Line($"**Detection probability by budget**: every known-bug catalogue entry ({rows.Count}: {rows.Count(r => !r.Indoor)} outdoor, {rows.Count(r => r.Indoor)} indoor), its catalogue catchers only; generated cases per invariant; {seeds} fresh seeds; sweeps not counted. "
            + $"pr profile = its fixed seed at {N(prCases)} cases; nightly profile = fresh seeds at {N(nightlyCases)} cases, so its detection probability is at least P@{N(budgets.Max())}:");
        Terminal.Line();
        Table(
            ["bug (fault)", "scope", .. budgets.Select(b => $"P@{N(b)}"), "median cases", "worst", $"pr profile (fixed seed, {N(prCases)})", $"nightly profile (P ≥)", "sweeps", "AFL++ first crash"],
            rows.Select(r => (IReadOnlyList<string>)
            [
                r.Bug.Id == r.Bug.Fault ? r.Bug.Id : $"{r.Bug.Id} ({r.Bug.Fault})", r.Indoor ? "indoor" : "outdoor",
                .. budgets.Select(b => P(BudgetCurve.Probability(r.Fresh, b))), Median(r.Fresh), Worst(r.Fresh, maxCases),
                r.Pr.CasesToDetect is long k && k <= prCases ? $"caught at {N(k)} ({r.Pr.Invariant})" : $"missed within {N(prCases)}", P(BudgetCurve.Probability(r.Fresh, maxCases)),
                r.Sweep ?? "—",
                fuzz.TryGetValue(r.Bug.Fault, out var f) ? f : r.Indoor ? "see docs/fuzzing.md" : "not fuzzed",
            ]));

        Terminal.Line($"**Seconds per budget**: the whole catalogue (every invariant, generated cases only) against the reference; model = {perCase * 1e3:0.###} ms per case per invariant-set (timed at {N(budgets.Max())}):");
        Terminal.Line();
        Table(
            ["cases per invariant", "seconds (model)", "seconds (measured)"],
            budgets.Select(b => (IReadOnlyList<string>)
            [
                b == prCases ? $"{N(b)} (pr profile)" : N(b), seconds[b].ToString(seconds[b] < 1 ? "0.0000" : "0.0", CultureInfo.InvariantCulture),
                measured.TryGetValue(b, out double m) ? m.ToString("0.0", CultureInfo.InvariantCulture) : "—",
            ]).Append([$"{N(nightlyCases)} (nightly profile)", (nightlyCases * perCase).ToString("0", CultureInfo.InvariantCulture), "—"]));
        Terminal.Line($"Profiles: pr = {N(prCases)} cases per invariant, fixed seed, plus sweeps; nightly = {N(nightlyCases)}, fresh seeds, plus sweeps.");
        Terminal.Line($"<!-- {Machine.Describe()} at end -->");

        if (outDir is not null)
        {
            Directory.CreateDirectory(outDir);
            var samples = new StringBuilder("fault,seed_kind,seed,cases_to_detect,invariant,seconds\n");
            var curve = new StringBuilder("fault,cases,seconds,p_generated,p_with_sweeps,pr_detected,scope\n");
            foreach (var (bug, indoor, sweep, pr, fresh) in rows)
            {
                foreach (var (kind, s) in fresh.Select(s => ("fresh", s)).Prepend(("pr", pr)))
                {
                    samples.Append(CultureInfo.InvariantCulture, $"{bug.Id},{kind},{s.Seed},{s.CasesToDetect?.ToString(CultureInfo.InvariantCulture) ?? string.Empty},{s.Invariant},{s.Elapsed.TotalSeconds:0.###}\n");
                }

                foreach (int b in budgets)
                {
                    double p = BudgetCurve.Probability(fresh, b);
                    curve.Append(CultureInfo.InvariantCulture, $"{bug.Id},{b},{seconds[b]:0.######},{p:0.###},{(sweep is null ? p : 1):0.###},{(pr.CasesToDetect <= b ? 1 : 0)},{(indoor ? "indoor" : "outdoor")}\n");
                }
            }

            AtomicFile.WriteAllText(Path.Combine(outDir, "budget-samples.csv"), samples.ToString());
            AtomicFile.WriteAllText(Path.Combine(outDir, "budget-curve.csv"), curve.ToString());
            Console.Error.WriteLine($"  wrote {Path.Combine(outDir, "budget-samples.csv")} and budget-curve.csv");
        }

        return ExitCodes.Ok;
    }

    private static string P(double p) => p.ToString("0.##", CultureInfo.InvariantCulture);

    private static string Median(List<DetectionSample> samples)
    {
        var found = samples.Select(s => s.CasesToDetect ?? long.MaxValue).Order().ToList();
        long m = found[found.Count / 2];
        return m == long.MaxValue ? "—" : N(m);
    }

    private static string Worst(List<DetectionSample> samples, int cap) =>
        samples.Any(s => s.CasesToDetect is null) ? $"> {N(cap)} ({samples.Count(s => s.CasesToDetect is null)} seeds)" : N(samples.Max(s => s.CasesToDetect!.Value));

    private static Dictionary<string, string> ReadFuzz(string? path)
    {
        var map = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        if (path is null)
        {
            return map;
        }

        if (!File.Exists(path))
        {
            throw new UsageException($"{path}: no such file");
        }

        foreach (string line in File.ReadLines(path).Skip(1).Where(l => l.Length > 0 && !l.StartsWith('#')))
        {
            var cells = line.Split(',');
            if (cells.Length < 4)
            {
                throw new UsageException($"{path}: expected fault,target,seconds,execs[,source], got '{line}'");
            }

            map[cells[0]] = cells[2].StartsWith('>')
                ? $"no crash in {cells[2][1..]} s, {cells[3]} execs ({cells[1]})"
                : $"{cells[2]} s @ {cells[3]} execs ({cells[1]})";
        }

        return map;
    }
}
