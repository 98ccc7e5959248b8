using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Protocol.Client;
using AcPhys.Protocol.Messages;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Spectre.Console;

namespace AcPhys.Cli.Verify;

/// <summary>Prints a <c>verify</c> run: header, results table, failures with their replay lines, and the summary line.</summary>
/// <param name="settings">The run's settings.</param>
/// <param name="impl">The implementation under test.</param>
internal sealed class VerifyReport(VerifySettings settings, ICellPhysics impl)
{
    private readonly Dictionary<string, FailureDetail> details = [];

    /// <summary>Returns the verdict word of a status.</summary>
    /// <param name="status">The status.</param>
    /// <returns>PASS, FAIL or NOT TESTED.</returns>
    public static string Verdict(ResultStatus status) => status switch
    {
        ResultStatus.Passed => "PASS",
        ResultStatus.Failed => "FAIL",
        _ => "NOT TESTED",
    };

    /// <summary>Writes what is about to run: implementation, profile, seeds.</summary>
    public void WriteHeader()
    {
        int count = settings.Only.Count == 0 ? InvariantCatalogue.All.Count : settings.Only.Count;
        string budget = settings.FixedSeed is Seed s
            ? $"profile {settings.Profile.Name}, seed {s} for every invariant (no exhaustive sweeps)"
            : $"profile {settings.Profile.Name}: {Fmt.Count(settings.Profile.CasesPerInvariant)} generated cases per invariant"
                + (settings.Profile.Exhaustive ? " + exhaustive sweeps" : string.Empty);
        Terminal.Line($"verify: {count} invariant{(count == 1 ? string.Empty : "s")} against {impl.Name}; {budget}");
        if ((Op.All & ~impl.Ops) != Op.None)
        {
            // A partial implementation: say up front what it offers; invariants needing the rest are NOT TESTED.
            Terminal.Line($"capabilities: offers {string.Join(", ", OpNames.Names(impl.Ops).Concat(Transports.Negotiated(impl)))}; lacks {string.Join(", ", OpNames.Names(Op.All & ~impl.Ops))}");
        }

        if (settings.Fault is not null)
        {
            Terminal.Line($"planted fault {settings.Fault.Id}: {settings.Fault.Title} (expected catchers: {string.Join(", ", settings.Fault.CaughtBy)})");
        }

        if (settings.FixedSeed is null)
        {
            Terminal.Line(settings.FreshBaseSeed
                ? $"base seed {Fmt.Decimal(settings.BaseSeed)} (fresh for this run; replay the whole run with: {WholeRunReplay()})"
                : $"base seed {Fmt.Decimal(settings.BaseSeed)} ({(settings.ExplicitBaseSeed ? "given" : "fixed by the profile")})");
        }

        Terminal.Line();
    }

    /// <summary>Writes one row per invariant.</summary>
    /// <param name="results">The results.</param>
    public void WriteTable(IReadOnlyList<InvariantResult> results)
    {
        var table = new Table()
            .AddColumn("Invariant")
            .AddColumn(new TableColumn("Cases (generated + exhaustive)").RightAligned())
            .AddColumn(new TableColumn("Applicable").RightAligned())
            .AddColumn(new TableColumn($"Boundary classes hit (LandDefs: of {BoundaryCoverage.AllTags.Count})"))
            .AddColumn("Verdict")
            .AddColumn(new TableColumn("Time").RightAligned());
        foreach (var r in results)
        {
            string cases = r.Status == ResultStatus.NotTested ? "-"
                : r.ExhaustiveCases > 0 ? $"{Fmt.Count(r.Cases)} + {Fmt.Count(r.ExhaustiveCases)}"
                : Fmt.Count(r.Cases);
            string applicable = r.Status == ResultStatus.NotTested ? "-" : $"{Fmt.Count(r.Applicable)} ({Fmt.Percent(r.Applicable, r.Cases)})";
            table.AddRow(
                new Text(r.Invariant.Id),
                new Text(cases),
                new Text(applicable),
                new Text(r.Status switch
                {
                    ResultStatus.NotTested => "-",
                    ResultStatus.Failed => $"{BoundaryCoverage.Hit(r.Classes)} (cases up to the first failure)",
                    _ => BoundaryCoverage.Brief(r.Classes),
                }),
                new Markup(VerdictMarkup(r.Status)),
                new Text(Fmt.Seconds(r.Elapsed)));
        }

        Terminal.Out.Write(table);
    }

    /// <summary>Writes the hit count of every boundary class, per invariant.</summary>
    /// <param name="results">The results.</param>
    public void WriteClasses(IReadOnlyList<InvariantResult> results)
    {
        var tested = results.Where(r => r.Status != ResultStatus.NotTested).ToArray();
        var table = new Table().AddColumn("Boundary class")
            .AddColumn(new TableColumn("Fewest hits").RightAligned())
            .AddColumn(new TableColumn("Most hits").RightAligned())
            .AddColumn("Missed by");
        foreach (var tag in BoundaryCoverage.AllTags)
        {
            var counts = tested.Select(r => r.Classes.GetValueOrDefault(tag)).ToArray();
            var missedBy = tested.Where(r => r.Classes.GetValueOrDefault(tag) == 0).Select(r => r.Invariant.Id).ToArray();
            table.AddRow(
                new Text(tag),
                new Text(counts.Length == 0 ? "-" : Fmt.Count(counts.Min())),
                new Text(counts.Length == 0 ? "-" : Fmt.Count(counts.Max())),
                new Text(missedBy.Length == 0 ? "-" : string.Join(", ", missedBy)));
        }

        Terminal.Line();
        Terminal.Line("Boundary classes (generated cases; a failing invariant counts only up to its first failure):");
        Terminal.Out.Write(table);

        // The domains' own classes (scene shapes, routes, estate classes ...): hits over the invariants that saw them.
        var own = new Table().AddColumn("Case class")
            .AddColumn(new TableColumn("Fewest hits").RightAligned())
            .AddColumn(new TableColumn("Most hits").RightAligned())
            .AddColumn(new TableColumn("Invariants").RightAligned());
        foreach (var tag in tested.SelectMany(r => r.Classes.Keys).Where(t => !BoundaryCoverage.AllTags.Contains(t)).Distinct().Order(StringComparer.Ordinal))
        {
            var counts = tested.Where(r => r.Classes.ContainsKey(tag)).Select(r => r.Classes[tag]).ToArray();
            own.AddRow(new Text(tag), new Text(Fmt.Count(counts.Min())), new Text(Fmt.Count(counts.Max())), new Text(Fmt.Count(counts.Length)));
        }

        Terminal.Line();
        Terminal.Line("Case classes (the domains' own tags; generated cases):");
        Terminal.Out.Write(own);
    }

    /// <summary>Writes why invariants were not tested.</summary>
    /// <param name="results">The results.</param>
    public void WriteNotTested(IReadOnlyList<InvariantResult> results)
    {
        foreach (var r in results.Where(r => r.Status == ResultStatus.NotTested))
        {
            Terminal.Line($"NOT TESTED {r.Invariant.Id}: {r.NotTestedReason ?? "the implementation lacks an operation it needs"}");
        }
    }

    /// <summary>Writes every failure: statement, shrunk case, message, original case, seeds and one replay line.</summary>
    /// <param name="results">The results.</param>
    public void WriteFailures(IReadOnlyList<InvariantResult> results)
    {
        foreach (var r in results.Where(r => r.Status == ResultStatus.Failed))
        {
            Terminal.Line();
            Terminal.Out.MarkupLine($"[red bold]FAIL[/] [bold]{Markup.Escape(r.Invariant.Id)}[/] on {Markup.Escape(impl.Name)}");
            var block = FailureBlock.Of(r, impl, impl.Name, ReplayLine.Command(settings), FailureFolder, FinderNames.Verify);
            foreach (string field in block.Fields)
            {
                Terminal.Line(field);
            }

            details[r.Invariant.Id] = new FailureDetail(block.ReplayLine, block.Confirmed, block.CaseFile, block.CaseReplay, r.Violation?.Case is AnyCase.OutdoorWalk { Walk: var walk } ? StepRows(walk) : null);
        }
    }

    /// <summary>Warns (on stderr, also with --quiet) about op names in hello that protocol v1 does not know: a misspelt op is otherwise silently NOT TESTED.</summary>
    public void WriteUnknownOps()
    {
        var unknown = UnknownOps;
        if (unknown.Count > 0)
        {
            var run = new GateRun(impl.Name, settings, [], details, TimeSpan.Zero) { UnknownOps = unknown };
            Terminal.Error("verify", $"warning: the implementation announced ops protocol v1 does not know: {run.UnknownOpsText} (ignored; known: {string.Join(", ", CapabilityNames.Known())})");
        }
    }

    /// <summary>Says so when nothing failed but fewer invariants were tested than <c>--min-tested</c>.</summary>
    /// <param name="results">The results.</param>
    /// <returns>Whether the run tested too little to pass.</returns>
    public bool WriteTooFewTested(IReadOnlyList<InvariantResult> results)
    {
        var run = new GateRun(impl.Name, settings, results, details, TimeSpan.Zero) { UnknownOps = UnknownOps };
        if (run.TooFewTested)
        {
            Terminal.Error("verify", run.TooFewTestedText);
        }

        return run.TooFewTested;
    }

    private IReadOnlyList<string> UnknownOps => impl is ProcessAdapter process ? process.UnknownOps : [];

    /// <summary>Writes the last line: counts, profile, time.</summary>
    /// <param name="results">The results.</param>
    /// <param name="elapsed">Wall time of the run.</param>
    public void WriteSummary(IReadOnlyList<InvariantResult> results, TimeSpan elapsed)
    {
        int passed = results.Count(r => r.Status == ResultStatus.Passed);
        int failed = results.Count(r => r.Status == ResultStatus.Failed);
        int notTested = results.Count(r => r.Status == ResultStatus.NotTested);
        var details = new List<string> { "profile " + settings.Profile.Name };
        if (settings.FixedSeed is Seed s)
        {
            details.Add("seed " + s);
        }
        else if (settings.FreshBaseSeed || settings.ExplicitBaseSeed)
        {
            details.Add("base seed " + Fmt.Decimal(settings.BaseSeed));
        }

        if (settings.Fault is not null)
        {
            details.Add("fault " + settings.Fault.Id);
        }

        details.Add(Fmt.Seconds(elapsed));
        if (!settings.Quiet || failed > 0)
        {
            Terminal.Line();
        }

        // Retail statements and hardening rules kept apart (issue #18): a port that matches retail may fail only the latter.
        Terminal.Line("by scope: " + string.Join("; ", new[] { AcPhys.Spec.Invariants.Scope.Retail, AcPhys.Spec.Invariants.Scope.Hardening }.Select(scope =>
        {
            var mine = results.Where(r => r.Invariant.Scope == scope).ToArray();
            return $"{AcPhys.Spec.Invariants.InvariantScope.Name(scope)} {mine.Count(r => r.Status == ResultStatus.Passed)} passed, {mine.Count(r => r.Status == ResultStatus.Failed)} failed, {mine.Count(r => r.Status == ResultStatus.NotTested)} not tested";
        })));
        Terminal.Line($"verify: {results.Count} invariant{(results.Count == 1 ? string.Empty : "s")}, {passed} passed, {failed} failed, {notTested} not tested ({string.Join(", ", details)})");
    }

    /// <summary>Writes what a run stopped by a signal had finished: the failures found so far and one summary line.</summary>
    /// <param name="finished">The invariants that finished.</param>
    /// <param name="total">How many the run would have checked.</param>
    /// <param name="elapsed">Wall time until the signal.</param>
    public void WritePartialSummary(IReadOnlyList<InvariantResult> finished, int total, TimeSpan elapsed)
    {
        foreach (var r in finished.Where(r => r.Status == ResultStatus.Failed))
        {
            Terminal.Line($"FAILED {r.Invariant.Id} (before the stop; run it again with --only {r.Invariant.Id} for its replay line)");
        }

        Terminal.Line($"verify: stopped after {finished.Count} of {total} invariants, {finished.Count(r => r.Status == ResultStatus.Passed)} passed, "
            + $"{finished.Count(r => r.Status == ResultStatus.Failed)} failed, {finished.Count(r => r.Status == ResultStatus.NotTested)} not tested, the rest not run "
            + $"(profile {settings.Profile.Name}{(settings.FixedSeed is null ? $", base seed {Fmt.Decimal(settings.BaseSeed)}" : string.Empty)}, {Fmt.Seconds(elapsed)})");
    }

    /// <summary>Writes the <c>--junit</c> and <c>--markdown</c> files, when asked for (atomically).</summary>
    /// <param name="results">The results.</param>
    /// <param name="elapsed">Wall time of the run.</param>
    public void WriteFiles(IReadOnlyList<InvariantResult> results, TimeSpan elapsed)
    {
        var run = new GateRun(impl.Name, settings, results, details, elapsed) { UnknownOps = UnknownOps };
        if (settings.JunitPath is string junit)
        {
            WriteFile(junit, JunitReport.Render(run));
        }

        if (settings.MarkdownPath is string markdown)
        {
            WriteFile(markdown, MarkdownSummary.Render(run));
        }
    }

    private IReadOnlyList<string[]> StepRows(Walk walk) =>
        WalkRunner.Run(impl, walk).Select(step => new[]
        {
            step.Index.ToString(System.Globalization.CultureInfo.InvariantCulture),
            step.Frame.ToString(),
            $"({FloatText.Format(step.Position.X)}, {FloatText.Format(step.Position.Y)})",
            step.Containing.IsNone ? "none" : step.Containing.ToString(),
            "[" + string.Join(", ", step.Cells) + "]",
        }).ToArray();

    private static void WriteFile(string path, string text)
    {
        OutputPath.Write(path, text);
        if (path == OutputPath.Stdout || !Terminal.ShowsProgress)
        {
            return;
        }

        Terminal.Err.MarkupLine($"[grey]wrote {Markup.Escape(path)}[/]");
    }

    private static string VerdictMarkup(ResultStatus status) => status switch
    {
        ResultStatus.Passed => "[green]PASS[/]",
        ResultStatus.Failed => "[red bold]FAIL[/]",
        _ => "[yellow]NOT TESTED[/]",
    };

    /// <summary>Gets the folder shrunk failing cases are written to: <c>ACPHYS_FAILURES</c>, else artifacts/failures.</summary>
    public static string FailureFolder => ToolEnvironment.Process.FailureFolder ?? Path.Combine("artifacts", "failures");

    private string WholeRunReplay()
    {
        var words = new List<string> { ReplayLine.Program, "verify", "--profile", settings.Profile.Name, "--base-seed", Fmt.Decimal(settings.BaseSeed) };
        if (settings.OnlyGiven.Count > 0)
        {
            words.AddRange(["--only", string.Join(',', settings.OnlyGiven)]);
        }

        if (settings.Except.Count > 0)
        {
            words.AddRange(["--except", string.Join(',', settings.Except)]);
        }

        words.AddRange(settings.Mode.Words());
        words.AddRange(settings.Implementation.Words());
        return string.Join(' ', words.Select(ReplayLine.Quote));
    }
}
