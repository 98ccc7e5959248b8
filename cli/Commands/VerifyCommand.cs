using System.CommandLine;
using System.Diagnostics;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Verify;
using AcPhys.Contract;
using AcPhys.Protocol.Client;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>verify</c> verb: runs every invariant of the catalogue against the bundled reference core (or the reference with a
/// planted fault) and reports each with its cases, boundary coverage, verdict and, on failure, a replay line.
/// </summary>
internal static class VerifyCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var profile = new Option<string>("--profile")
        {
            Description = "Budget: pr (5,000 cases per invariant, fixed seeds, exhaustive sweeps) or nightly (200,000, fresh seeds). Default: $ACPHYS_PROFILE, else pr.",
        };
        profile.AcceptOnlyFromAmong("pr", "nightly");
        var only = new Option<string[]>("--only")
        {
            Description = "Run only these invariants (comma-separated or repeated; see: acphys invariants).",
            HelpName = "ID[,ID...]",
        };
        var except = new Option<string[]>("--except")
        {
            Description = "Leave out these invariants (comma-separated or repeated), e.g. the conformance ones to see what the independent invariants catch.",
            HelpName = "ID[,ID...]",
        };
        var scope = new Option<string>("--scope")
        {
            Description = "Run the retail invariants (what retail does), the hardening ones (rules beyond retail that protect a port), or all (default).",
            HelpName = "retail|hardening|all",
        };
        var seed = new Option<string>("--seed")
        {
            Description = "Use this seed for every invariant (no exhaustive sweeps); a failure's replay seed reproduces it.",
            HelpName = "seed,gamma[,size]",
        };
        var baseSeed = new Option<string>("--base-seed")
        {
            Description = "Derive every invariant's seed from this base (replays a whole nightly run; default: the profile's).",
            HelpName = "N",
        };
        var fault = new Option<string>("--fault")
        {
            Description = "Switch on a planted fault in the reference, to show the suite catches it (see: acphys faults).",
            HelpName = "FAULT",
        };
        var quiet = new Option<bool>("--quiet", "-q") { Description = "Print only failures and the summary line (for CI logs)." };
        var classes = new Option<bool>("--classes") { Description = "Also print how often each boundary class was hit." };

        var pick = new Option<string>("--pick")
        {
            Description = "The pick policy of the bundled reference: retail (default) or current-first (acdream's hysteresis).",
            HelpName = "POLICY",
        };
        var fidelity = new Option<string>("--fidelity")
        {
            Description = "Documented deviations of the bundled reference (comma-separated: ace, double, ace-early-return, ...; see docs/protocol.md).",
            HelpName = "NAMES",
        };
        var cases = new Option<int?>("--cases")
        {
            Description = "Generated cases per invariant, instead of the profile's (e.g. a small budget for a slow --impl-cmd).",
            HelpName = "N",
        };
        var maxClasses = new Option<int?>("--max-classes")
        {
            Description = "Failure classes each failing invariant searches for within its budget (default 4; 1 stops each invariant at its first failure: fastest when you only need caught or not).",
            HelpName = "N",
        };
        var minTested = new Option<int?>("--min-tested")
        {
            Description = "The fewest invariants that must be tested (not NOT TESTED) for the run to pass (default 1: a run that tested nothing never passes; exit 4).",
            HelpName = "N",
        };
        var jobs = new Option<int?>("--jobs", "-j")
        {
            Description = "Invariants run at once (default: one per processor for the bundled reference and its planted faults; --impl / --impl-cmd run one at a time). The report is the same for any N.",
            HelpName = "N",
        };
        var sweeps = new Option<bool>("--sweeps") { Description = "Also run the exhaustive sweeps against an --impl-cmd implementation (millions of round trips; off by default there)." };
        var junit = new Option<string>("--junit") { Description = "Also write the results as JUnit XML (one testcase per invariant) to this file.", HelpName = "FILE" };
        var markdown = new Option<string>("--markdown") { Description = "Also write a markdown summary fit for a PR comment to this file.", HelpName = "FILE" };
        var implOptions = new ImplementationOptions();
        var datWorld = new DatWorldStage();
        var command = new Command("verify", "Run the invariant catalogue against the reference core, a planted fault, or your implementation (--impl, --impl-cmd), and report.")
        {
            profile, only, except, scope, seed, baseSeed, fault, quiet, classes, pick, fidelity, cases, maxClasses, sweeps, junit, markdown, minTested, jobs,
        };
        foreach (var option in implOptions.All.Concat(datWorld.All))
        {
            command.Options.Add(option);
        }

        command.SetAction(parse => Guard.Run("verify", () =>
        {
            OutputPath.Check("--junit", parse.GetValue(junit));
            OutputPath.Check("--markdown", parse.GetValue(markdown));
            OutputPath.CheckDistinct([("--junit", parse.GetValue(junit)), ("--markdown", parse.GetValue(markdown))], parse.GetValue(implOptions.Assembly) is string dll ? [dll] : []);
            if (ToolEnvironment.Process.FailureFolder is { } failures)
            {
                OutputPath.CheckFolder("ACPHYS_FAILURES", failures); // named by the user: a path problem is exit 3 before the run
            }

            var settings = VerifySettings.Parse(
                parse.GetValue(profile) ?? DefaultProfile(), parse.GetValue(only), parse.GetValue(seed), parse.GetValue(baseSeed), parse.GetValue(fault), parse.GetValue(except), parse.GetValue(scope))
                with
            {
                Quiet = parse.GetValue(quiet),
                ShowClasses = parse.GetValue(classes),
                Pick = PickNames.TryParse(parse.GetValue(pick), out var policy)
                    ? policy
                    : throw new UsageException($"unknown pick policy '{parse.GetValue(pick)}' (known: retail, current-first)"),
                Fidelity = Impl.ReferenceChoice.ParseFidelity(parse.GetValue(fidelity)),
                Implementation = implOptions.Read(parse),
                CasesOverride = parse.GetValue(cases),
                MaxClasses = parse.GetValue(maxClasses) ?? CatalogueRunner.MaxClasses,
                JunitPath = parse.GetValue(junit),
                MarkdownPath = parse.GetValue(markdown),
                MinTested = parse.GetValue(minTested) ?? 1,
                Jobs = parse.GetValue(jobs),
            };
            return Run(WithBudget(settings, parse.GetValue(sweeps)), datWorld.Read(parse));
        }));
        return command;
    }

    private const int MaxJobs = 64;

    private static string DefaultProfile() => ToolEnvironment.Process.ProfileName ?? "pr";

    private static VerifySettings WithBudget(VerifySettings settings, bool sweeps)
    {
        if (settings.Implementation.IsExternal && (settings.Fault is not null || settings.Pick != AcPhys.Core.PickPolicy.Retail || settings.Fidelity != default))
        {
            throw new UsageException("--fault, --pick and --fidelity configure the bundled reference; they do not apply to --impl / --impl-cmd (an implementation declares its mode in hello)");
        }

        if (sweeps && !settings.Implementation.IsProcess)
        {
            throw new UsageException("--sweeps applies to --impl-cmd (the in-process profiles sweep already)");
        }

        if (settings.MaxClasses is < 1 or > CatalogueRunner.MaxClasses)
        {
            throw new UsageException($"--max-classes must be between 1 and {CatalogueRunner.MaxClasses} (got {settings.MaxClasses})");
        }

        if (settings.MinTested < 1 || settings.MinTested > InvariantCatalogue.All.Count)
        {
            throw new UsageException($"--min-tested must be between 1 and {InvariantCatalogue.All.Count} (got {settings.MinTested})");
        }

        if (settings.Jobs is int j && j is < 1 or > MaxJobs)
        {
            throw new UsageException($"--jobs must be between 1 and {MaxJobs} (got {j})");
        }

        if (settings.Jobs > 1 && settings.Implementation.IsExternal)
        {
            throw new UsageException("--jobs applies to the bundled reference and its planted faults: --impl / --impl-cmd run one invariant at a time (a port's code need not be thread-safe)");
        }

        if (settings.CasesOverride is int n && n is < 1 or > 10_000_000)
        {
            throw new UsageException($"--cases must be between 1 and 10,000,000 (got {n})");
        }

        var profile = settings.Profile;
        if (settings.CasesOverride is int cases)
        {
            profile = profile with { CasesPerInvariant = cases };
        }

        if (settings.Implementation.IsProcess && !sweeps)
        {
            profile = profile with { Exhaustive = false }; // millions of round trips: opt in with --sweeps
        }

        return settings with { Profile = profile };
    }

    private static int Run(VerifySettings settings, DatWorldStage.Request? datWorld)
    {
        if (!settings.Implementation.IsExternal)
        {
            // A fault with --pick / --fidelity: the faulty answers under that declaration (a declaration never turns a bug green, issue 41).
            ICellPhysics reference = settings.Fault is not null
                ? Impl.ReferenceChoice.Declared(PlantedFaults.Create(settings.Fault.Id), settings.Pick, settings.Fidelity)
                : Impl.ReferenceChoice.Create(settings.Pick, settings.Fidelity);
            return Run(settings, reference, datWorld);
        }

        var (impl, owned) = settings.Implementation.Open(settings.Quiet ? null : line => Console.Error.WriteLine("[impl] " + line));
        using (owned)
        {
            return Run(settings, impl, datWorld);
        }
    }

    private static int Run(VerifySettings settings, ICellPhysics impl, DatWorldStage.Request? datWorld)
    {
        if (datWorld is { Block: not null })
        {
            // The replay of a dat-world finding: that block's walks alone, no catalogue.
            return DatWorldStage.Run(datWorld, settings, impl) ? ExitCodes.Ok : ExitCodes.Violated;
        }

        int exit = Run(settings, impl);
        if (datWorld is null)
        {
            return exit;
        }

        bool held = DatWorldStage.Run(datWorld, settings, impl);
        return held ? exit : ExitCodes.Violated;
    }

    private static int Run(VerifySettings settings, ICellPhysics impl)
    {
        var report = new VerifyReport(settings, impl);
        if (!settings.Quiet)
        {
            report.WriteHeader();
        }

        report.WriteUnknownOps();

        var stopwatch = Stopwatch.StartNew();
        var finished = new List<InvariantResult>();
        Guard.OnStop(() =>
        {
            lock (finished)
            {
                report.WritePartialSummary([.. finished], Total(settings), stopwatch.Elapsed);
            }
        });
        var results = RunWithProgress(impl, settings, r =>
        {
            lock (finished)
            {
                finished.Add(r);
            }
        });
        stopwatch.Stop();

        if (!settings.Quiet)
        {
            report.WriteTable(results);
            if (settings.ShowClasses)
            {
                report.WriteClasses(results);
            }

            report.WriteNotTested(results);
        }

        report.WriteFailures(results);
        FindingsText.Write(results);
        report.WriteSummary(results, stopwatch.Elapsed);
        if (!settings.Quiet && impl is ProcessAdapter { Pipelines: true } piped)
        {
            // How the pipelined transport fared (docs/protocol.md, "Pipelining"): a replayed run is one where an answer
            // differed from the reference's in the declared mode, so it was asked again where it differed.
            Console.Error.WriteLine($"verify: pipeline: {piped.PipelineCounts.Runs} invariant runs streamed, {piped.PipelineCounts.Replays} replayed from the first differing answer");
            foreach (string why in piped.PipelineDifferences)
            {
                Console.Error.WriteLine("  differed: " + why);
            }
        }

        report.WriteFiles(results, stopwatch.Elapsed);
        if (results.Any(r => r.Status == ResultStatus.Failed))
        {
            return ExitCodes.Violated;
        }

        return report.WriteTooFewTested(results) ? ExitCodes.TooFewTested : ExitCodes.Ok;
    }

    private static int Total(VerifySettings settings) => settings.Only.Count == 0 ? InvariantCatalogue.All.Count : settings.Only.Count;

    private static IReadOnlyList<InvariantResult> RunWithProgress(ICellPhysics impl, VerifySettings settings, Action<InvariantResult> finished)
    {
        var only = settings.Only.Count == 0 ? null : settings.Only;
        IReadOnlyList<InvariantResult> results = [];
        ProgressBars.Run($"verify {impl.Name}", Total(settings), advance =>
        {
            results = CatalogueRunner.RunCatalogue(impl, settings.Profile, VerifyWorkers.For(settings, impl), only, settings.FixedSeed, settings.MaxClasses, result =>
            {
                finished(result);
                advance($"{result.Invariant.Id} {VerifyReport.Verdict(result.Status)}");
            });
        },
        enabled: !settings.Quiet);
        return results;
    }
}
