using System.CommandLine;
using System.Diagnostics;
using AcPhys.Cli.Diff;
using AcPhys.Cli.Impl;
using AcPhys.Contract;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Spectre.Console;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>diff</c> verb: differential testing. Generated queries and walks go to an implementation and to the reference
/// core; every diverging input is counted in its divergence class (op, shape of the difference, input class), and each
/// class's first input is shrunk and written as a replayable case or walk file beside a side-by-side table.
/// </summary>
internal static class DiffCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var impl = new ImplementationOptions();
        var cases = new Option<int?>("--cases") { Description = "Generated inputs per check (default 1,000).", HelpName = "N" };
        var only = new Option<string>("--only") { Description = "Run one check: DIFF-LANDDEFS, DIFF-OUTSIDE-CELLS, DIFF-FIND-CELL, DIFF-WALK, DIFF-PARTS, DIFF-SCENE-WALK.", HelpName = "CHECK" };
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

            string folder = parse.GetValue(output) ?? Path.Combine("artifacts", "diff");
            OutputPath.CheckFolder("-o", folder); // before the implementation starts (issue 28: -o FILE was exit 70 after the run)
            return Run(choice, n, parse.GetValue(only), fixedSeed, folder, parse.GetValue(quiet));
        }));
        return command;
    }

    private static int Run(ImplementationChoice choice, int cases, string? only, Seed? fixedSeed, string folder, bool quiet)
    {
        var (impl, owned) = choice.Open(quiet ? null : line => Console.Error.WriteLine("[impl] " + line));
        using (owned)
        {
            var reference = Conformance.ReferenceFor(impl); // the pick, indoor and outdoor fidelity the implementation declares
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
                Terminal.Line($"diff: {impl.Name} against {reference.Name}; {Fmt.Count(cases)} generated inputs per check, every divergence counted in its class, ops both offer: {string.Join(", ", OpNames.Names(impl.Ops).Concat(Transports.Negotiated(impl)))}");
            }

            var stopwatch = Stopwatch.StartNew();
            var results = new List<DiffResult>();
            ProgressBars.Run($"diff {impl.Name}", checks.Count, advance =>
            {
                foreach (var check in checks)
                {
                    var seed = fixedSeed ?? Seed.Derive(AcPhys.Spec.Running.Profile.Pr.BaseSeed!.Value, check.Id);
                    results.Add(Transports.Streamed(impl, () => check.Run(impl, cases, seed))); // streamed, repeated where an answer differs (docs/protocol.md, "Pipelining")
                    advance(check.Id);
                }
            },
            enabled: !quiet);

            if (!quiet)
            {
                Terminal.Out.Write(DiffReport.Overview(results));
            }

            var report = new DiffReport(impl, reference, choice, cases, folder);
            var rows = results.Where(r => r.Differs).SelectMany(report.Write).ToArray();
            int differs = results.Count(r => r.Differs);
            Terminal.Line();
            if (differs > 0)
            {
                Terminal.Line($"summary  {report.WriteSummary(results, rows)}");
            }

            string classes = differs > 0 ? $"; {rows.Length} divergence class{(rows.Length == 1 ? string.Empty : "es")} over {Fmt.Count(results.Sum(r => r.Divergent))} inputs" : string.Empty;
            Terminal.Line($"diff: {results.Count} checks, {results.Count(r => r.NotComparedReason is null && !r.Differs)} same, {differs} differ, {results.Count(r => r.NotComparedReason is not null)} not compared{classes} ({Fmt.Seconds(stopwatch.Elapsed)})");
            return differs > 0 ? ExitCodes.Violated : ExitCodes.Ok;
        }
    }
}
