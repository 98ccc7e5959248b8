using System.CommandLine;
using System.Runtime.InteropServices;
using AcPhys.Cli.Fuzz;
using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>fuzz</c> verb: an AFL++ campaign (one -M main, J − 1 -S secondaries on one sync folder) against a fuzz target,
/// then triage into minimised, deduplicated, replayable regressions (docs/fuzzing.md).
/// </summary>
internal static class FuzzCommand
{
    private const double MaxMinutes = 7 * 24 * 60;

    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var minutes = new Option<double>("--minutes") { Description = "How long afl-fuzz fuzzes (decimals allowed; start-up and triage come on top).", DefaultValueFactory = _ => 10 };
        var jobs = new Option<int>("--jobs", "-j") { Description = "afl-fuzz instances: one main and J-1 secondaries sharing one sync folder.", DefaultValueFactory = _ => 1 };
        var target = new Option<string>("--target", "-t")
        {
            Description = "The fuzz target: " + string.Join(", ", FuzzTargets.All.Select(t => $"{t.Name} ({t.Kind.ToString().ToLowerInvariant()})")) + ".",
            DefaultValueFactory = _ => "walk",
            HelpName = "TARGET",
        };
        var fault = new Option<string>("--fault") { Description = "Run against the reference with this planted fault (physics targets; see: acphys faults).", HelpName = "FAULT" };
        var quiet = new Option<bool>("--quiet", "-q") { Description = "No live progress, only the summary (CI)." };
        var timeout = new Option<int>("--timeout-ms") { Description = "afl-fuzz -t: per-input time limit.", DefaultValueFactory = _ => 1000 };
        var campaign = new Option<string>("--campaign") { Description = "Campaign folder (default .fuzz/campaigns/TARGET-FAULT|correct); kept so the next run resumes.", HelpName = "DIR" };
        var regressions = new Option<string>("--regressions") { Description = "Where minimised regressions go (default corpus/regressions).", HelpName = "DIR" };
        var fresh = new Option<bool>("--fresh") { Description = "Wipe the campaign folder first (no resume)." };
        var untilCrash = new Option<bool>("--until-crash") { Description = "Stop at the first crash (time-to-first-crash measurements)." };
        var buildDir = new Option<string>("--build-dir") { Description = "Where the instrumented harness is built (default .fuzz/build, shared by campaigns).", HelpName = "DIR" };
        var noBuild = new Option<bool>("--no-build") { Description = "Reuse the instrumented build in .fuzz/build as it is." };
        var triageOnly = new Option<bool>("--triage-only") { Description = "Do not fuzz: triage the crashes the campaign's sync folder holds (e.g. collected from other machines)." };
        var command = new Command("fuzz", "Run an AFL++ campaign on a fuzz target, then triage crashes into minimised regressions with replay lines.")
        {
            minutes, jobs, target, fault, quiet, timeout, campaign, regressions, fresh, untilCrash, buildDir, noBuild, triageOnly,
        };
        command.SetAction(parse => Run(() =>
        {
            string root = RepoRoot.Find();
            var t = FuzzTargets.Find(parse.GetValue(target))
                ?? throw new UsageException($"unknown target '{parse.GetValue(target)}' (known: {string.Join(", ", FuzzTargets.All.Select(x => x.Name))})");
            string? f = parse.GetValue(fault) is { Length: > 0 } id ? id : null;
            if (f is not null)
            {
                f = PlantedFaults.Find(f)?.Id ?? throw new UsageException($"unknown fault '{f}' (known: {string.Join(", ", PlantedFaults.All.Select(x => x.Id))})");
                if (!t.TakesFaults)
                {
                    throw new UsageException($"target {t.Name} takes no planted fault (physics targets do: {string.Join(", ", FuzzTargets.All.Where(x => x.TakesFaults).Select(x => x.Name))})");
                }
            }

            double m = parse.GetValue(minutes);
            int j = parse.GetValue(jobs);
            int ms = parse.GetValue(timeout);
            if (!double.IsFinite(m) || m <= 0 || m > MaxMinutes || j < 1 || ms < 1)
            {
                throw new UsageException($"--minutes (a number of minutes up to {MaxMinutes}), --jobs and --timeout-ms must be positive (got --minutes {Spec.Values.InputQuote.Line(m.ToString(System.Globalization.CultureInfo.InvariantCulture))})");
            }

            int maxJobs = Math.Max(1, Environment.ProcessorCount);
            if (j > maxJobs)
            {
                throw new UsageException($"--jobs {j}: at most {maxJobs} (one afl-fuzz instance per core of this machine)");
            }

            string name = $"{t.Name}-{f ?? "correct"}";
            var settings = new FuzzSettings(
                root,
                t,
                f,
                Math.Max(1, (int)Math.Round(m * 60)),
                j,
                ms,
                Path.GetFullPath(parse.GetValue(campaign) ?? Path.Combine(root, ".fuzz", "campaigns", name)),
                Path.GetFullPath(parse.GetValue(regressions) ?? Path.Combine(root, "corpus", "regressions")),
                Path.Combine(root, "corpus", "fuzz", t.Name))
            {
                Quiet = parse.GetValue(quiet),
                Fresh = parse.GetValue(fresh),
                UntilCrash = parse.GetValue(untilCrash),
                NoBuild = parse.GetValue(noBuild),
                TriageOnly = parse.GetValue(triageOnly),
            };
            if (parse.GetValue(buildDir) is { Length: > 0 } dir)
            {
                settings = settings with { BuildDir = Path.GetFullPath(dir) };
            }

            // Checked before afl++ is installed or anything is built (issue 28).
            if (settings.NoBuild && !File.Exists(settings.Harness))
            {
                throw new UsageException($"--no-build: no instrumented build in {settings.BuildDir} (run once without --no-build)");
            }

            if (settings.TriageOnly && (settings.Fresh || !Directory.Exists(settings.SyncDir)))
            {
                throw new UsageException(settings.Fresh
                    ? "--triage-only and --fresh exclude each other (--fresh wipes the crashes triage would read)"
                    : $"--triage-only: no campaign to triage in {settings.CampaignDir} (no sync folder)");
            }

            return settings;
        }));
        return command;
    }

    // Not Guard.Run: Ctrl-C must stop afl-fuzz and still triage what it found, so the signal only cancels.
    private static int Run(Func<FuzzSettings> settings)
    {
        using var cts = new CancellationTokenSource();
        void OnSignal(PosixSignalContext context)
        {
            if (!cts.IsCancellationRequested)
            {
                context.Cancel = true; // first signal: stop fuzzing, then triage; a second one ends the process
                Console.Error.WriteLine("[fuzz] stopping afl-fuzz (signal again to abort triage)");
                cts.Cancel();
            }
        }

        using var sigint = PosixSignalRegistration.Create(PosixSignal.SIGINT, OnSignal);
        using var sigterm = PosixSignalRegistration.Create(PosixSignal.SIGTERM, OnSignal);
        try
        {
            return new Campaign(settings(), cts.Token).Run();
        }
        catch (Exception e) when (e is UsageException or CorpusFormatException or IOException or UnauthorizedAccessException)
        {
            Terminal.Error("fuzz", e.Message);
            return ExitCodes.ToolError;
        }
    }
}
