using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using AcPhys.Cli.Diff;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Verify;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Running;
using Spectre.Console;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>diff</c> verb: differential testing. Generated queries and walks go to an implementation and to the reference
/// core; the first divergence of each kind is shrunk and written as a replayable case or walk file beside a
/// side-by-side table of the two answers.
/// </summary>
internal static class DiffCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var impl = new ImplementationOptions();
        var cases = new Option<int?>("--cases") { Description = "Generated inputs per check (default 1,000).", HelpName = "N" };
        var only = new Option<string>("--only") { Description = "Run one check: DIFF-LANDDEFS, DIFF-OUTSIDE-CELLS, DIFF-FIND-CELL, DIFF-WALK, DIFF-PARTS.", HelpName = "CHECK" };
        var seed = new Option<string>("--seed") { Description = "Use this seed (a divergence's replay seed reproduces it).", HelpName = "seed,gamma[,size]" };
        var output = new Option<string>("--output", "-o") { Description = "Folder for the divergence files (default artifacts/diff).", HelpName = "DIR" };
        var quiet = new Option<bool>("--quiet", "-q") { Description = "Print only divergences and the summary line." };
        var command = new Command("diff", "Compare an implementation (--impl or --impl-cmd) with the reference core on generated queries and walks.")
        {
            cases, only, seed, output, quiet,
        };
        foreach (var option in impl.All)
        {
            command.Options.Add(option);
        }

        command.SetAction(parse => Guard.Run("diff", () =>
        {
            var choice = impl.Read(parse);
            if (!choice.IsExternal)
            {
                throw new UsageException("diff needs an implementation to compare: --impl PATH.dll or --impl-cmd \"COMMAND\"");
            }

            int n = parse.GetValue(cases) ?? 1000;
            if (n is < 1 or > 10_000_000)
            {
                throw new UsageException($"--cases must be between 1 and 10,000,000 (got {n})");
            }

            Seed? fixedSeed = null;
            if (parse.GetValue(seed) is string s)
            {
                fixedSeed = Seed.TryParse(s, out var parsed) ? parsed : throw new UsageException($"malformed seed '{s}': expected seed,gamma[,size]");
            }

            return Run(choice, n, parse.GetValue(only), fixedSeed, parse.GetValue(output) ?? Path.Combine("artifacts", "diff"), parse.GetValue(quiet));
        }));
        return command;
    }

    private static int Run(ImplementationChoice choice, int cases, string? only, Seed? fixedSeed, string folder, bool quiet)
    {
        var (impl, owned) = choice.Open(quiet ? null : line => Console.Error.WriteLine("[impl] " + line));
        using (owned)
        {
            var reference = new ReferenceAdapter(impl.Pick);
            var checks = new DiffChecks(reference).All;
            if (only is not null)
            {
                checks = checks.Where(c => string.Equals(c.Id, only, StringComparison.OrdinalIgnoreCase)).ToArray();
                if (checks.Count == 0)
                {
                    throw new UsageException($"unknown check '{only}' (known: {string.Join(", ", new DiffChecks(reference).All.Select(c => c.Id))})");
                }
            }

            if (!quiet)
            {
                Terminal.Line($"diff: {impl.Name} against {reference.Name}; {Fmt.Count(cases)} generated inputs per check, ops both offer: {string.Join(", ", OpNames.Names(impl.Ops))}");
            }

            var stopwatch = Stopwatch.StartNew();
            var table = new Table().AddColumn("Check").AddColumn(new TableColumn("Inputs").RightAligned()).AddColumn("Verdict").AddColumn(new TableColumn("Time").RightAligned());
            var results = new List<InvariantResult>();
            ProgressBars.Run($"diff {impl.Name}", checks.Count, advance =>
            {
                foreach (var check in checks)
                {
                    results.Add(check.Run(impl, cases, fixedSeed ?? Seed.Derive(Spec.Running.Profile.Pr.BaseSeed!.Value, check.Id)));
                    advance(check.Id);
                }
            },
            enabled: !quiet);
            foreach (var result in results)
            {
                var check = result.Invariant;
                string verdict = result.Status switch
                {
                    ResultStatus.Passed => "same",
                    ResultStatus.Failed => "DIFFERS",
                    _ => "not compared (" + result.NotTestedReason + ")",
                };
                table.AddRow(check.Id, result.Status == ResultStatus.NotTested ? "-" : Fmt.Count(result.Cases), verdict, Fmt.Seconds(result.Elapsed));
            }

            if (!quiet)
            {
                Terminal.Out.Write(table);
            }

            foreach (var r in results.Where(r => r.Status == ResultStatus.Failed))
            {
                Report(r, impl, reference, choice, cases, folder);
            }

            int differs = results.Count(r => r.Status == ResultStatus.Failed);
            Terminal.Line();
            Terminal.Line($"diff: {results.Count} checks, {results.Count(r => r.Status == ResultStatus.Passed)} same, {differs} differ, {results.Count(r => r.Status == ResultStatus.NotTested)} not compared ({Fmt.Seconds(stopwatch.Elapsed)})");
            return differs > 0 ? ExitCodes.Violated : ExitCodes.Ok;
        }
    }

    private static void Report(InvariantResult r, ICellPhysics impl, ICellPhysics reference, ImplementationChoice choice, int cases, string folder)
    {
        var v = r.Violation!;
        Terminal.Line();
        Terminal.Out.MarkupLine($"[red bold]DIFFERS[/] [bold]{Markup.Escape(r.Invariant.Id)}[/]: {Markup.Escape(impl.Name)} vs {Markup.Escape(reference.Name)}");
        Terminal.Line($"  shrunk     {v.CaseText}");
        Terminal.Line($"  first      {v.Message}");
        var rows = SideBySide.Rows(v.Case, impl, reference);
        var table = new Table().AddColumn("Query").AddColumn(impl.Name).AddColumn(reference.Name).AddColumn(string.Empty);
        foreach (var (query, mine, theirs) in rows)
        {
            table.AddRow(new Text(query), new Text(mine), new Text(theirs), new Markup(mine == theirs ? string.Empty : "[red]differs[/]"));
        }

        Terminal.Out.Write(table);

        var words = new List<string> { ReplayLine.Program, "diff", "--only", r.Invariant.Id, "--cases", cases.ToString(CultureInfo.InvariantCulture) };
        if (r.Replay is Seed replay)
        {
            words.AddRange(["--seed", replay.ToString()]);
        }

        words.AddRange(choice.Words());
        string replayLine = string.Join(' ', words.Select(ReplayLine.Quote));
        Terminal.Line($"  seed       {r.Seed}");
        Terminal.Line($"  replay     {replayLine}");

        string? caseFile = FailureFile.Write(v, folder, "diff", r.Seed.ToString());
        string sideFile = Path.Combine(folder, (caseFile is null ? r.Invariant.Id : Path.GetFileNameWithoutExtension(caseFile)) + ".diff.md");
        string header = $"# {r.Invariant.Id}: {impl.Name} vs {reference.Name}\n\n{r.Invariant.Statement}\n\nShrunk input: `{v.CaseText}`\n\nFirst divergence: {v.Message}\n\n";
        string files = caseFile is null ? string.Empty : $"Replay the walk/case against either side: `{ReplayLine.Program} replay {caseFile}{(choice.Words().Count > 0 ? " " + string.Join(' ', choice.Words().Select(ReplayLine.Quote)) : string.Empty)}`\n\n";
        AtomicFile.WriteAllText(sideFile, header + SideBySide.Markdown(rows, impl.Name) + $"\nSeed `{r.Seed}`; replay the diff: `{replayLine}`\n\n" + files);
        if (caseFile is not null)
        {
            Terminal.Line($"  case file  {caseFile}");
        }

        Terminal.Line($"  side by side {sideFile}");
    }
}
