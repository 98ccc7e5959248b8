using System.CommandLine;
using System.Runtime.InteropServices;
using AcPhys.Cli.Fuzz;
using AcPhys.Cli.Impl;
using AcPhys.Formats;
using AcPhys.Fuzz.Targets;
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
        var instrument = new Option<string[]>("--instrument")
        {
            Description = "With --impl: the assemblies beside the adapter to instrument (default: the adapter's and the port's own projects in its .deps.json; never the framework, packages or AcPhys.*).",
            HelpName = "NAME",
            AllowMultipleArgumentsPerToken = true,
        };
        var implOptions = new ImplementationOptions();
        var command = new Command("fuzz", "Run an AFL++ campaign on a fuzz target (the reference, a planted fault, or a port: --impl / --impl-cmd), then triage crashes into minimised regressions with replay lines.")
        {
            minutes, jobs, target, fault, quiet, timeout, campaign, regressions, fresh, untilCrash, buildDir, noBuild, triageOnly, instrument,
        };
        foreach (var option in implOptions.All)
        {
            command.Options.Add(option);
        }

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

            var port = implOptions.Read(parse);
            if (port.IsExternal && f is not null)
            {
                throw new UsageException("--fault configures the bundled reference; it does not apply to --impl / --impl-cmd");
            }

            if (port.IsExternal && t.Kind != TargetKind.Physics)
            {
                throw new UsageException($"target {t.Name} fuzzes the suite's own readers, not an implementation (--impl / --impl-cmd take a physics target: {string.Join(", ", FuzzTargets.All.Where(x => x.TakesFaults).Select(x => x.Name))})");
            }

            string[] named = parse.GetValue(instrument) ?? [];
            if (named.Length > 0 && port.AssemblyPath is null)
            {
                throw new UsageException("--instrument names assemblies of an --impl port");
            }

            double m = parse.GetValue(minutes);
            int j = parse.GetValue(jobs);
            // A child's answers must time out inside afl-fuzz's -t, so a hang is the harness's finding, not a killed
            // harness: --impl-cmd defaults to -t 5000 ms and a 2 s answer timeout (docs/fuzzing.md).
            bool timeoutGiven = parse.GetResult(timeout) is { Implicit: false };
            int ms = port.IsProcess && !timeoutGiven ? 5000 : parse.GetValue(timeout);
            if (port.IsProcess)
            {
                if (parse.GetValue(implOptions.Timeout) is null)
                {
                    port = port with { Timeout = TimeSpan.FromMilliseconds(Math.Max(100, ms * 2 / 5)) };
                }
                else if (port.Timeout.TotalMilliseconds >= ms)
                {
                    throw new UsageException($"--timeout {port.Timeout.TotalSeconds:0.###} s must be below --timeout-ms {ms} (afl-fuzz's limit per input), so a hung child is a finding and not a killed harness");
                }
            }
            if (!double.IsFinite(m) || m <= 0 || m > MaxMinutes || j < 1 || ms < 1)
            {
                throw new UsageException($"--minutes (a number of minutes up to {MaxMinutes}), --jobs and --timeout-ms must be positive (got --minutes {AcPhys.Formats.Values.InputQuote.Line(m.ToString(System.Globalization.CultureInfo.InvariantCulture))})");
            }

            int maxJobs = Math.Max(1, Environment.ProcessorCount);
            if (j > maxJobs)
            {
                throw new UsageException($"--jobs {j}: at most {maxJobs} (one afl-fuzz instance per core of this machine)");
            }

            string name = $"{t.Name}-{CampaignKey(f, port)}";
            var settings = new FuzzSettings(
                root,
                t,
                f,
                Math.Max(1, (int)Math.Round(m * 60)),
                j,
                ms,
                Path.GetFullPath(parse.GetValue(campaign) ?? Path.Combine(root, ".fuzz", "campaigns", name)),
                Path.GetFullPath(parse.GetValue(regressions) ?? (port.IsExternal ? "acphys-regressions" : Path.Combine(root, "corpus", "regressions"))),
                Path.Combine(root, "corpus", "fuzz", t.Name))
            {
                Quiet = parse.GetValue(quiet),
                Fresh = parse.GetValue(fresh),
                UntilCrash = parse.GetValue(untilCrash),
                NoBuild = parse.GetValue(noBuild),
                TriageOnly = parse.GetValue(triageOnly),
                Port = port,
                Instrument = named,
            };
            if (parse.GetValue(buildDir) is { Length: > 0 } dir)
            {
                settings = settings with { BuildDir = Path.GetFullPath(dir) };
            }
            else if (port.AssemblyPath is not null)
            {
                settings = settings with { BuildDir = Path.Combine(root, ".fuzz", "build-impl") }; // the suite's assemblies uninstrumented
            }
            else if (port.Command is not null)
            {
                settings = settings with { BuildDir = Path.Combine(root, ".fuzz", "build-cmd") }; // the wire code uninstrumented (HarnessBuild.For)
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

    // The campaign folder's key: the fault, the correct core, or the port (its file or command word and a hash of
    // the full path or command line), so each implementation resumes its own queue night after night.
    private static string CampaignKey(string? fault, ImplementationChoice port)
    {
        if (!port.IsExternal)
        {
            return fault ?? "correct";
        }

        string full = port.Command ?? port.AssemblyPath!;
        string hash = Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(System.Text.Encoding.UTF8.GetBytes(full)))[..8];
        string word = port.Command is { } c ? Path.GetFileName(c.Split(' ', StringSplitOptions.RemoveEmptyEntries).FirstOrDefault() ?? "cmd") : Path.GetFileNameWithoutExtension(full);
        string slug = new([.. word.Select(ch => char.IsAsciiLetterOrDigit(ch) || ch is '-' or '_' or '.' ? ch : '_').Take(32)]);
        return $"{(port.Command is null ? "impl" : "cmd")}-{slug}-{hash}";
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
        catch (Exception e) when (e is UsageException or InputFormatException or IOException or UnauthorizedAccessException
            or AcPhys.Spec.Adapters.AdapterLoadException or AcPhys.Contract.AdapterFailureException)
        {
            Terminal.Error("fuzz", e.Message);
            return ExitCodes.ToolError;
        }
    }
}
