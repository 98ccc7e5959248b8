using System.Diagnostics;
using System.Text.Json.Nodes;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// mutation/shard.py: the nightly Stryker run's shards cover every core file exactly once, and their merged report is
/// scored and judged as one full run would be (docs/mutation.md, "Shards").
/// </summary>
public sealed class MutationShardTests
{
    private static string Script => Path.Combine(RepoPaths.Root, "mutation", "shard.py");

    [RequiresPythonFact]
    public void ShardsPartitionTheCoreFiles()
    {
        var core = CoreFiles();
        foreach (int n in new[] { 1, 3, 4, 7 })
        {
            var shards = Deal(n);
            Assert.Equal(n, shards.Length);
            Assert.All(shards, files => Assert.NotEmpty(files));
            Assert.Equal(core, shards.SelectMany(f => f).Order(StringComparer.Ordinal).ToArray()); // each file once
        }

        // run.sh asks for one shard at a time: the same files as the deal.
        var one = Python(["files", "2", "4"]);
        Assert.True(one.Exit == 0, one.Output);
        Assert.Equal(Deal(4)[2], one.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries));
    }

    [RequiresPythonFact]
    public void MergedShardsScoreAsOneRun()
    {
        string dir = Temp();
        var core = CoreFiles();

        // Every core file gets 20 mutants: 18 killed, 1 timeout, 1 survived, plus ignored ones that the score leaves out.
        var reports = WriteShards(dir, 3, file => ["Killed", .. Enumerable.Repeat("Killed", 17), "Timeout", "Survived", "Ignored", "CompileError"]);
        var merged = Python(["merge", Path.Combine(dir, "out"), .. reports]);

        Assert.True(merged.Exit == 0, merged.Output);
        Assert.Contains($"score 95.00 % (killed {18 * core.Length} timeout {core.Length} survived {core.Length} nocoverage 0)", merged.Output, StringComparison.Ordinal);
        var report = JsonNode.Parse(File.ReadAllText(Path.Combine(dir, "out", "mutation-report.json")))!;
        Assert.Equal(core, report["files"]!.AsObject().Select(p => p.Key).Order(StringComparer.Ordinal).ToArray());
        Assert.Contains("Score **95.00 %**", File.ReadAllText(Path.Combine(dir, "out", "mutation-report.md")), StringComparison.Ordinal);
    }

    [RequiresPythonFact]
    public void MergedScoreBelowTheBreakThresholdFails()
    {
        string dir = Temp();
        var reports = WriteShards(dir, 2, file => [.. Enumerable.Repeat("Killed", 18), "Survived", "NoCoverage"]); // 90 %
        var merged = Python(["merge", Path.Combine(dir, "out"), .. reports]);

        Assert.True(merged.Exit == 3, merged.Output);
        Assert.Contains("90.00 % is below the break threshold 95 %", merged.Output, StringComparison.Ordinal);
    }

    [RequiresPythonFact]
    public void MergeRefusesARepeatedMissingOrUnstampedShard()
    {
        string dir = Temp();
        var reports = WriteShards(dir, 3, file => ["Killed"]);
        string outDir = Path.Combine(dir, "out");

        var twice = Python(["merge", outDir, reports[0], reports[1], reports[2], reports[0]]);
        Assert.True(twice.Exit == 2, twice.Output);
        Assert.Contains("shard 0 of 3 twice", twice.Output, StringComparison.Ordinal);

        var missing = Python(["merge", outDir, reports[0], reports[2]]);
        Assert.True(missing.Exit == 2, missing.Output);
        Assert.Contains("no report of shard 1 of 3", missing.Output, StringComparison.Ordinal);

        string plain = Path.Combine(dir, "plain.json");
        var node = JsonNode.Parse(File.ReadAllText(reports[1]))!.AsObject();
        node.Remove("acphysShard");
        File.WriteAllText(plain, node.ToJsonString());
        var unstamped = Python(["merge", outDir, reports[0], plain, reports[2]]);
        Assert.True(unstamped.Exit == 2, unstamped.Output);
        Assert.Contains("is not a shard's report", unstamped.Output, StringComparison.Ordinal);

        Assert.False(File.Exists(Path.Combine(outDir, "mutation-report.json")), "a refused merge wrote a report");
    }

    [RequiresPythonFact]
    public void ABadShardIsRefusedBeforeStrykerStarts()
    {
        foreach (var (spec, why) in new[] { ("4/4", "need 0 <= K < N"), ("x/2", "--shard needs K/N"), ("1", "--shard needs K/N") })
        {
            var run = Exec("bash", [Path.Combine(RepoPaths.Root, "mutation", "run.sh"), "--shard", spec]);
            Assert.True(run.Exit == 2, run.Output);
            Assert.Contains(why, run.Output, StringComparison.Ordinal);
            Assert.DoesNotContain("mutation: stryker on core/", run.Output, StringComparison.Ordinal);
        }
    }

    /// <summary>
    /// Writes n shard reports as run.sh --shard leaves them: Stryker lists every core file in every report, so a file a
    /// shard does not own carries decoy mutants (all "Survived": a merge that took them would score lower).
    /// </summary>
    private static string[] WriteShards(string dir, int n, Func<string, string[]> statuses)
    {
        var paths = new string[n];
        var shards = Deal(n);
        var core = CoreFiles();
        for (int k = 0; k < n; k++)
        {
            var files = new JsonObject();
            foreach (string file in core)
            {
                var mutants = new JsonArray();
                int id = 0;
                foreach (string status in shards[k].Contains(file) ? statuses(file) : ["Survived", "Survived", "Survived"])
                {
                    mutants.Add(new JsonObject { ["id"] = (id++).ToString(System.Globalization.CultureInfo.InvariantCulture), ["status"] = status });
                }

                files[file] = new JsonObject { ["language"] = "cs", ["source"] = "", ["mutants"] = mutants };
            }

            paths[k] = Path.Combine(dir, $"shard-{k}.json");
            File.WriteAllText(paths[k], new JsonObject { ["schemaVersion"] = "2", ["thresholds"] = new JsonObject { ["high"] = 97, ["low"] = 95 }, ["files"] = files }.ToJsonString());
            var stamp = Python(["stamp", paths[k], k.ToString(System.Globalization.CultureInfo.InvariantCulture), n.ToString(System.Globalization.CultureInfo.InvariantCulture)]);
            Assert.True(stamp.Exit == 0, stamp.Output);
        }

        return paths;
    }

    private static string[] CoreFiles()
    {
        var git = Exec("git", ["-C", RepoPaths.Root, "ls-files", "core/*.cs"]);
        Assert.True(git.Exit == 0, git.Output);
        return git.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries).Order(StringComparer.Ordinal).ToArray();
    }

    private static string[][] Deal(int n)
    {
        var run = Python(["deal", n.ToString(System.Globalization.CultureInfo.InvariantCulture)]);
        Assert.True(run.Exit == 0, run.Output);
        var rows = run.Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(line => line.Split('\t')).ToArray();
        return Enumerable.Range(0, n).Select(k => rows.Where(r => r[0] == k.ToString(System.Globalization.CultureInfo.InvariantCulture)).Select(r => r[1]).ToArray()).ToArray();
    }

    private static string Temp() => Directory.CreateTempSubdirectory("acphys-shard-").FullName;

    private static (int Exit, string Stdout, string Output) Python(IEnumerable<string> args) => Exec("python3", [Script, .. args]);

    private static (int Exit, string Stdout, string Output) Exec(string file, IEnumerable<string> args)
    {
        var info = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in args)
        {
            info.ArgumentList.Add(a);
        }

        using var p = Process.Start(info)!;
        var stdout = p.StandardOutput.ReadToEndAsync();
        var stderr = p.StandardError.ReadToEndAsync();
        if (!p.WaitForExit(TimeSpan.FromMinutes(1)))
        {
            p.Kill(entireProcessTree: true);
            return (-1, "", $"{file} timed out");
        }

        return (p.ExitCode, stdout.Result, $"{file} {string.Join(' ', info.ArgumentList)} -> {p.ExitCode}\n{stdout.Result}\n{stderr.Result}");
    }
}
