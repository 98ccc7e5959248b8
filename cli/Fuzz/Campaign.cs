using System.Globalization;
using System.Text;
using AcPhys.Cli.Impl;
using AcPhys.Formats.Corpus;
using AcPhys.Fuzz.Targets;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// One <c>acphys fuzz</c> run, start to end: afl-fuzz present, harness built and instrumented, seeds (built-in and
/// the target's growing corpus, <c>corpus/fuzz/TARGET</c>), the afl-fuzz instances, triage into regressions, the
/// seed corpus grown with new coverage, and a summary (also written to the campaign's <c>summary.txt</c>).
/// </summary>
/// <param name="s">The settings.</param>
/// <param name="stop">Cancelled by Ctrl-C / SIGTERM: afl-fuzz stops, triage still runs.</param>
internal sealed class Campaign(FuzzSettings s, CancellationToken stop)
{
    private Subject subject = Subject.Reference;
    private PortWatch watch = PortWatch.None;
    private (IReadOnlyList<string> Assemblies, int Probes)? port;

    /// <summary>Runs the campaign.</summary>
    /// <returns>0 nothing found, 1 findings, 2 the campaign could not run, 6 an in-process port hung outside afl-fuzz (<see cref="ExitCodes.PortHung"/>).</returns>
    public int Run()
    {
        subject = OpenSubject();
        try
        {
            return RunWith();
        }
        catch (PortHangException hang)
        {
            return Hung(hang);
        }
        finally
        {
            subject.Dispose();
        }
    }

    // The implementation seeds and triage run against, in acphys: the reference (or a fault), the port's own adapter
    // assembly (not the instrumented copy), or one child over protocol v1. A target the port cannot be fuzzed on is refused.
    private Subject OpenSubject()
    {
        if (!s.Port.IsExternal)
        {
            return Subject.Of(s.Fault);
        }

        var opened = s.Port.Command is { } cmd
            ? PortSubject.Served(cmd, s.Port.Timeout, LineLimitSetting.Read(AcPhys.Spec.Running.ToolEnvironment.Process), line => Say("[impl] " + line))
            : PortSubject.InProcess(s.Port.AssemblyPath!, (watch = new PortWatch(s.PortCaseLimit)).Beat);
        try
        {
            if (PortSubject.Refusal(s.Target, opened) is { } why)
            {
                throw new UsageException(why);
            }

            Say($"implementation: {opened.Label}; tested for {string.Join(", ", s.Target.TestedFor(opened.Shared()))}");

            return opened;
        }
        catch
        {
            opened.Dispose();
            throw;
        }
    }

    private int RunWith()
    {
        if (s.Fresh && Directory.Exists(s.CampaignDir))
        {
            Directory.Delete(s.CampaignDir, recursive: true);
        }

        Directory.CreateDirectory(s.LogDir);

        // A port's --triage-only needs neither afl-fuzz nor the harness: triage runs the port in acphys.
        bool fuzzes = !(s.TriageOnly && s.Port.IsExternal);
        if (fuzzes)
        {
            AflTools.Ensure(Say);
            if (AflTools.Which("setpriv") is null)
            {
                throw new UsageException("setpriv (util-linux) is needed to stop afl-fuzz when acphys dies; install util-linux");
            }

            HarnessBuild.Ensure(s, Say, stop);
            if (s.Port.AssemblyPath is not null)
            {
                port = PortCopy.Ensure(s, Say, stop);
            }
        }

        var (seeds, seedCrashes) = PrepareSeeds();
        string? dictionary = fuzzes ? WriteDictionary() : null;
        bool resumed = Directory.Exists(Path.Combine(s.SyncDir, "main", "queue"));
        Say($"campaign: target {s.Target.Name}, {s.Subject}, {s.Jobs} job(s), {s.Seconds} s, "
            + $"{(resumed ? "resuming " + s.SyncDir : "new sync folder " + s.SyncDir)}");

        IReadOnlyList<InstanceStats> stats = [];
        TimeSpan wall = TimeSpan.Zero;
        TimeSpan? firstCrashWall = seedCrashes > 0 ? TimeSpan.Zero : null;
        string stopped = "every seed fails";
        if (s.TriageOnly)
        {
            stopped = "--triage-only";
            stats = Directory.Exists(s.SyncDir) ? Directory.EnumerateDirectories(s.SyncDir).Order(StringComparer.Ordinal).Select(InstanceStats.Read).ToList() : [];
        }
        else if (Directory.EnumerateFiles(seeds).Any())
        {
            (stats, wall, var first, stopped) = new CampaignRunner(s, stop).Run(seeds, dictionary, new ProgressView(s.Quiet));
            firstCrashWall ??= first;
            if (stats.All(x => x.Execs == 0))
            {
                throw new UsageException($"afl-fuzz did not run; see {s.LogDir}/afl-main.log");
            }
        }
        else
        {
            Say("every seed fails on this implementation: the fault is found before fuzzing; afl-fuzz not started");
        }

        var crashFiles = Directory.Exists(s.SyncDir)
            ? Directory.EnumerateDirectories(s.SyncDir).SelectMany(d => InstanceStats.CrashFiles(d)).ToList()
            : [];
        crashFiles.AddRange(Directory.EnumerateFiles(Path.Combine(s.CampaignDir, "seed-crashes")));
        Say($"triage: {crashFiles.Count} crash input(s)");
        var groups = new CrashTriage(s, subject, watch).Run(crashFiles);
        var hangFiles = Directory.Exists(s.SyncDir) ? Directory.EnumerateDirectories(s.SyncDir).SelectMany(InstanceStats.HangFiles).ToList() : [];
        if (new HangTriage(s, CancellationToken.None).Run(hangFiles) is { } hang)
        {
            Say($"triage: {hangFiles.Count} hang input(s) of the in-process port");
            groups = [.. groups, hang];
        }

        string cmin = GrowSeedCorpus();
        string summary = Summary(stats, wall, firstCrashWall, stopped, seedCrashes, groups, cmin);
        AtomicFile.WriteAllText(Path.Combine(s.CampaignDir, "summary.txt"), summary);
        Console.Out.Write(summary);
        return groups.Any(g => g.Written is not null) ? ExitCodes.Violated : ExitCodes.Ok;
    }

    private (string Dir, int Crashing) PrepareSeeds()
    {
        string dir = Path.Combine(s.CampaignDir, "seeds");
        string crashes = Path.Combine(s.CampaignDir, "seed-crashes");
        foreach (string d in new[] { dir, crashes })
        {
            if (Directory.Exists(d))
            {
                Directory.Delete(d, recursive: true);
            }

            Directory.CreateDirectory(d);
        }

        var all = s.Target.Seeds.Select(kv => (Name: kv.Key, Data: kv.Value)).ToList();
        if (Directory.Exists(s.SeedCorpusDir))
        {
            all.AddRange(Directory.EnumerateFiles(s.SeedCorpusDir).Where(f => !Path.GetFileName(f).StartsWith('.')).Order(StringComparer.Ordinal)
                .Select(f => (Name: "corpus-" + Path.GetFileName(f), Data: File.ReadAllBytes(f))));
        }

        int crashing = 0;
        foreach (var (name, data) in all)
        {
            string input = name.StartsWith("corpus-", StringComparison.Ordinal)
                ? "seed " + Shown(Path.Combine(s.SeedCorpusDir, name["corpus-".Length..]))
                : $"built-in seed '{name}'";
            bool fails = watch.Run(input, data, () => s.Target.Classify(data, subject)) is not null;
            crashing += fails ? 1 : 0;
            File.WriteAllBytes(Path.Combine(fails ? crashes : dir, name), data);
        }

        Say($"seeds: {all.Count} ({s.Target.Seeds.Count} built in, {all.Count - s.Target.Seeds.Count} from {Path.GetRelativePath(s.Root, s.SeedCorpusDir)}), {crashing} fail already");
        return (dir, crashing);
    }

    // An in-process port did not return on one case outside afl-fuzz: the thread inside it cannot be stopped, so the
    // campaign stops here (acphys ends, and the thread with it). The input is confirmed as afl's hangs are, in a child
    // acphys that can be killed (HangTriage), and written to REGRESSIONS/hangs/ with its replay line.
    private int Hung(PortHangException hang)
    {
        var b = new StringBuilder();
        var inv = CultureInfo.InvariantCulture;
        b.AppendLine(inv, $"fuzz summary: target {s.Target.Name}, {s.Subject}: stopped, the port hung outside afl-fuzz");
        b.AppendLine(inv, $"  - {HangTriage.Key}: the port did not return within {hang.Limit.TotalSeconds:0.###} s (5x --timeout-ms, at least 5 s) on {hang.Input}");
        if (hang.Bytes is { } data)
        {
            string dir = Path.Combine(s.CampaignDir, "hung");
            Directory.CreateDirectory(dir);
            string file = Path.Combine(dir, Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(data))[..16]);
            File.WriteAllBytes(file + ".tmp", data);
            File.Move(file + ".tmp", file, overwrite: true);
            var group = new HangTriage(s, CancellationToken.None).Run([file], _ => $"acphys fuzz {s.Target.Name}: {hang.Input}");
            if (group is { Written: { } written })
            {
                b.AppendLine(inv, $"      {(group.Known ? "known" : "new")}: {Shown(written)} ({group.Signature})");
                b.AppendLine(inv, $"      replay: {group.Replay}");
            }
            else
            {
                b.AppendLine(inv, $"      not written: {group?.Signature ?? "the input is not a case of this target"}");
            }
        }
        else
        {
            b.AppendLine("      not written: the case that hung is a shrink candidate, not one input");
        }

        b.AppendLine(inv, $"  campaign folder: {s.CampaignDir}");
        AtomicFile.WriteAllText(Path.Combine(s.CampaignDir, "summary.txt"), b.ToString());
        Console.Out.Write(b.ToString());
        Terminal.Error("fuzz", $"{HangTriage.Key}: {hang.Message}; the campaign was stopped (exit {ExitCodes.PortHung})");
        return ExitCodes.PortHung;
    }

    private string? WriteDictionary()
    {
        if (s.Target.Dictionary.Count == 0)
        {
            return null;
        }

        string path = Path.Combine(s.CampaignDir, "dictionary.txt");
        var (code, output) = AflTools.Run(s.Harness, "dict", s.Target.Name, path);
        if (code != 0)
        {
            throw new UsageException($"harness dict failed: {output.Trim()}");
        }

        return path;
    }

    // Only correct-core campaigns feed the seed corpus: their queue is what the real code does.
    private string GrowSeedCorpus()
    {
        if (s.Port.IsExternal)
        {
            return "seed corpus: unchanged (a port's queue stays in its campaign folder; only correct-core campaigns feed corpus/fuzz)";
        }

        if (s.Fault is not null || s.Target.Kind == AcPhys.Fuzz.Targets.TargetKind.Smoke || !Directory.Exists(s.SyncDir))
        {
            return "seed corpus: unchanged (only correct-core campaigns of physics and parser targets feed it)";
        }

        var queues = Directory.EnumerateDirectories(s.SyncDir).Select(d => Path.Combine(d, "queue")).Where(Directory.Exists).ToArray();
        var (code, output) = AflTools.Run(s.Harness, ["cmin", s.Target.Name, s.SeedCorpusDir, .. queues], new Dictionary<string, string> { ["ACPHYS_FAULT"] = string.Empty });
        return code == 0 ? "seed corpus: " + output.Trim() : $"seed corpus: cmin failed ({code}): {output.Trim()}";
    }

    private string Summary(IReadOnlyList<InstanceStats> stats, TimeSpan wall, TimeSpan? firstCrashWall, string stopped, int seedCrashes, IReadOnlyList<TriageGroup> groups, string cmin)
    {
        var b = new StringBuilder();
        var inv = CultureInfo.InvariantCulture;
        b.AppendLine(inv, $"fuzz summary: target {s.Target.Name}, {s.Subject}, {s.Jobs} job(s), -V {s.Seconds} s, stopped by {stopped}, wall {wall.TotalSeconds:F0} s");
        b.AppendLine(inv, $"  machine: {Environment.ProcessorCount} cores, load average {LoadAverage()}");
        b.AppendLine(inv, $"  {"instance",-8} {"execs",12} {"exec/s",8} {"paths",6} {"crashes",7} {"hangs",5} {"stability",9}  first crash (afl time@execs)");
        foreach (var x in stats)
        {
            string first = x.FirstCrashMs is long ms ? $"{ms / 1000.0:F3} s @ {x.FirstCrashExecs}" : "-";
            b.AppendLine(inv, $"  {x.Name,-8} {x.Execs,12} {x.ExecsPerSec,8:F0} {x.Paths,6} {x.Crashes,7} {x.Hangs,5} {x.Stability,9}  {first}");
        }

        if (stats.Count > 1)
        {
            b.AppendLine(inv, $"  {"total",-8} {stats.Sum(x => x.Execs),12} {stats.Sum(x => x.ExecsPerSec),8:F0}");
        }

        if (s.Port.IsExternal)
        {
            b.AppendLine(inv, $"  implementation: {subject.Label}; invariants tested (the rest not tested, as in the gate): {string.Join(", ", s.Target.TestedFor(subject.Shared()))}");
        }

        if (port is { } p)
        {
            long edges = stats.Count == 0 ? 0 : stats.Max(x => EdgesFound(x.Name));
            b.AppendLine(inv, $"  port coverage: {edges} afl edge(s) reached (edges_found; only the port is instrumented) over {p.Probes} probe(s) (instrumented blocks) in {string.Join(", ", p.Assemblies)}");
        }
        else if (s.Port.Command is not null)
        {
            b.AppendLine("  coverage: the harness side's (codec, oracle, reference and wire code in acphys's own assemblies); the port's own branches are not seen over protocol");
        }

        var firstAfl = stats.Where(x => x.FirstCrashMs is not null).OrderBy(x => x.FirstCrashMs).FirstOrDefault();
        string afl = firstAfl is not null
            ? $"{firstAfl.FirstCrashMs / 1000.0:F3} s afl time @ {firstAfl.FirstCrashExecs} execs ({firstAfl.Name}); wall {firstCrashWall?.TotalSeconds:F1} s from start"
            : stats.Count > 0 ? "none" : "not fuzzed";
        string firstCrash = seedCrashes > 0 ? $"0 (found by {seedCrashes} seed(s) before fuzzing); afl from the passing seeds: {afl}" : afl;
        b.AppendLine($"  time to first crash: {firstCrash}");
        b.AppendLine(inv, $"  findings: {groups.Where(g => g.Written is not null).Sum(g => g.Count)} crash input(s) in {groups.Count(g => g.Written is not null)} group(s)");
        foreach (var g in groups)
        {
            b.AppendLine(inv, $"  - {g.Key} x{g.Count}: {g.Signature}");
            if (g.Written is not null)
            {
                b.AppendLine(inv, $"      {(g.Known ? "known" : "new")}: {Shown(g.Written)}{(g.Reproduces ? string.Empty : "  (NOT reproduced by replay: not written)")}");
                b.AppendLine(inv, $"      replay: {g.Replay}");
            }
        }

        b.AppendLine(inv, $"  {cmin}");
        b.AppendLine(inv, $"  campaign folder: {s.CampaignDir} (the next run resumes its queue; --fresh starts over)");
        return b.ToString();
    }

    // afl-fuzz's own count of map entries (edges) seen by an instance.
    private long EdgesFound(string instance)
    {
        string stats = Path.Combine(s.SyncDir, instance, "fuzzer_stats");
        if (!File.Exists(stats))
        {
            return 0;
        }

        foreach (string line in File.ReadAllLines(stats))
        {
            var parts = line.Split(':', 2, StringSplitOptions.TrimEntries);
            if (parts.Length == 2 && parts[0] == "edges_found" && long.TryParse(parts[1], NumberStyles.Integer, CultureInfo.InvariantCulture, out long n))
            {
                return n;
            }
        }

        return 0;
    }

    private string Shown(string path) => Path.GetRelativePath(s.Root, path) is var rel && !rel.StartsWith("..", StringComparison.Ordinal) ? rel : path;

    private static string LoadAverage()
    {
        try
        {
            return string.Join(' ', File.ReadAllText("/proc/loadavg").Split(' ').Take(3));
        }
        catch (IOException)
        {
            return "unknown";
        }
    }

    private void Say(string line)
    {
        if (!s.Quiet)
        {
            Console.Error.WriteLine("[fuzz] " + line);
        }
    }
}
