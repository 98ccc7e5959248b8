using System.CommandLine;
using AcPhys.Cli.Verify;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Spectre.Console;
using Profile = AcPhys.Spec.Running.Profile;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>bite</c> verb (docs/bite.md): runs every known-bug catalogue entry (mutation/known-bugs/) against every
/// invariant, prints the bug × invariant matrix and the time to detect each bug, and exits 1 when one escapes.
/// </summary>
internal static class BiteCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var profile = new Option<string>("--profile")
        {
            Description = "Budget: pr (5,000 cases per invariant, fixed seeds) or nightly (200,000, a fresh base seed). Default: $ACPHYS_PROFILE, else pr.",
        };
        profile.AcceptOnlyFromAmong("pr", "nightly");
        var seeds = new Option<int>("--seeds")
        {
            Description = "Seeds per bug (time to detect is the median and max over them); seed 0 is the profile's own.",
            HelpName = "N",
            DefaultValueFactory = _ => 1,
        };
        var markdown = new Option<string>("--markdown") { Description = "Also write the report as markdown to this file (atomically).", HelpName = "FILE" };
        var json = new Option<string>("--json") { Description = "Also write the report as JSON (format acphys-bite) to this file (atomically).", HelpName = "FILE" };
        var bug = new Option<string[]>("--bug")
        {
            Description = "Run only these catalogue bugs (comma-separated or repeated).",
            HelpName = "ID[,ID...]",
        };
        var except = new Option<string[]>("--except")
        {
            Description = "Leave out these invariants (comma-separated or repeated), e.g. the conformance ones to see what the independent invariants catch.",
            HelpName = "ID[,ID...]",
        };
        var command = new Command("bite", "Prove the suite bites: run every known-bug catalogue entry against every invariant and report the matrix.")
        {
            profile, seeds, markdown, json, bug, except,
        };
        command.SetAction(parse => Guard.Run("bite", () => Run(
            parse.GetValue(profile) ?? DefaultProfile(),
            parse.GetValue(seeds),
            parse.GetValue(markdown),
            parse.GetValue(json),
            parse.GetValue(bug) ?? [],
            parse.GetValue(except) ?? [],
            Environment.GetCommandLineArgs())));
        return command;
    }

    private static string DefaultProfile() => ToolEnvironment.Process.ProfileName ?? "pr";

    private static int Run(string profileName, int seeds, string? markdownPath, string? jsonPath, string[] bugIds, string[] exceptIds, string[] args)
    {
        var profile = Profile.Find(profileName) is { Name: "pr" or "nightly" } p ? p
            : throw new UsageException($"unknown profile '{profileName}' (known: pr, nightly)");
        if (seeds < 1)
        {
            throw new UsageException($"--seeds must be at least 1 (got {seeds})");
        }

        OutputPath.Check("--markdown", markdownPath);
        OutputPath.Check("--json", jsonPath);
        OutputPath.CheckDistinct([("--markdown", markdownPath), ("--json", jsonPath)], []);

        IReadOnlyList<KnownBug> catalogue;
        try
        {
            catalogue = KnownBugCatalogue.All;
        }
        catch (FormatException e)
        {
            throw new UsageException(e.Message, e);
        }

        var ids = bugIds.SelectMany(b => b.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)).ToList();
        var unknown = ids.Where(id => KnownBugCatalogue.Find(id) is null).ToList();
        if (unknown.Count > 0)
        {
            throw new UsageException($"unknown catalogue bug(s): {string.Join(", ", unknown)}; known: {string.Join(", ", catalogue.Select(b => b.Id))}");
        }

        var left = exceptIds.SelectMany(b => b.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)).ToList();
        var unknownInvariants = left.Where(id => InvariantCatalogue.Find(id) is null).ToList();
        if (unknownInvariants.Count > 0)
        {
            throw new UsageException($"unknown invariant(s) for --except: {string.Join(", ", unknownInvariants)} (see: acphys invariants)");
        }

        var bugs = ids.Count == 0 ? catalogue : catalogue.Where(b => ids.Contains(b.Id, StringComparer.OrdinalIgnoreCase)).ToList();
        var report = RunWithProgress(bugs, profile, seeds, left);
        Print(report);

        string command = string.Join(' ', new[] { ReplayLine.Program }.Concat(args.Skip(1)).Select(ReplayLine.Quote));
        Write(markdownPath, () => BiteReportText.Markdown(report, command));
        Write(jsonPath, () => BiteReportText.Json(report));
        return report.Escaped.Any() ? ExitCodes.Violated : ExitCodes.Ok;
    }

    private static BiteReport RunWithProgress(IReadOnlyList<KnownBug> bugs, Profile profile, int seeds, IReadOnlyCollection<string> except)
    {
        if (!Terminal.ShowsProgress)
        {
            using var log = new ProgressLog("bite", bugs.Count);
            return BiteRunner.Run(bugs, profile, seeds, progress: row => log.Advance($"{row.Bug.Id} {row.Status.ToString().ToLowerInvariant()}"), except: except);
        }

        BiteReport? report = null;
        int done = 0;
        Terminal.Err.Status().Start($"running {bugs.Count} catalogue bugs × {InvariantCatalogue.All.Count - except.Count} invariants × {seeds} seed(s) ...", context =>
        {
            report = BiteRunner.Run(bugs, profile, seeds, progress: row =>
            {
                done++;
                context.Status(Markup.Escape($"ran {done}/{bugs.Count} bugs (last: {row.Bug.Id} {row.Status.ToString().ToLowerInvariant()}) ..."));
            }, except: except);
        });
        return report!;
    }

    private static void Print(BiteReport report)
    {
        var table = new Table().AddColumns("Bug", "Status", "Caught by (every seed)", "Median", "Max");
        foreach (var b in report.Bugs)
        {
            string status = b.Status switch
            {
                BugStatus.Caught => "[green]caught[/]",
                BugStatus.Escaped => "[red]ESCAPED[/]",
                _ => "[yellow]pending[/]",
            };
            string by = b.Status == BugStatus.Pending ? b.Bug.NotAvailableReason ?? string.Empty : string.Join(", ", b.CaughtBy);
            table.AddRow(new Text(b.Bug.Id), new Markup(status), new Text(by), new Text(BiteReportText.Ms(b.Median)), new Text(BiteReportText.Ms(b.Max)));
        }

        Terminal.Out.Write(table);

        var matrix = new Table().AddColumn("Bug");
        for (int i = 0; i < report.InvariantIds.Count; i++)
        {
            matrix.AddColumn(new TableColumn((i + 1).ToString(System.Globalization.CultureInfo.InvariantCulture)).Centered());
        }

        foreach (var b in report.Run)
        {
            var byId = b.Cells.ToDictionary(c => c.InvariantId);
            matrix.AddRow([new Text(b.Bug.Id), .. report.InvariantIds.Select(id => new Text(byId.TryGetValue(id, out var c) ? BiteReportText.Mark(c, report.Seeds) : string.Empty))]);
        }

        Terminal.Out.Write(matrix);
        Terminal.Line("● caught under every seed, k/N under k of N seeds, · not caught, – not applicable. Columns: "
            + string.Join(", ", report.InvariantIds.Select((id, i) => $"{i + 1} {id}")));

        foreach (var b in report.Escaped)
        {
            Terminal.Line($"ESCAPED {b.Bug.Id}: no invariant caught fault '{b.Bug.Fault}' under seed(s) {string.Join(", ", b.TimeToDetect.Select((t, k) => (t, k)).Where(x => x.t is null).Select(x => x.k))}; replay: {ReplayLine.Program} verify --fault {b.Bug.Fault}");
        }

        foreach (var b in report.Run.Where(b => b.Status == BugStatus.Caught && b.MissedDeclared.Any()))
        {
            Terminal.Line($"note {b.Bug.Id}: declared catcher(s) {string.Join(", ", b.MissedDeclared)} did not catch it under every seed");
        }

        foreach (var b in report.Run.Where(b => b.Example is not null))
        {
            var e = b.Example!;
            Terminal.Line($"{b.Bug.Id}: first caught by {e.InvariantId}; replay: {ReplayLine.Program} verify --fault {b.Bug.Fault} --only {e.InvariantId} --seed {e.Replay}");
        }

        Terminal.Line($"base seed {report.BaseSeed}; run time {report.Elapsed.TotalSeconds:0.0} s");
        Terminal.Line(BiteReportText.Summary(report));
    }

    private static void Write(string? path, Func<string> text)
    {
        if (string.IsNullOrEmpty(path))
        {
            return;
        }

        OutputPath.Write(path, text());
    }
}
