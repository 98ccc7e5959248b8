using System.Globalization;
using System.Reflection;
using System.Security.Cryptography;
using System.Text.RegularExpressions;
using AcPhys.Cli.Verify;
using AcPhys.Formats.Corpus;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Turns the inputs afl-fuzz kept as hangs of an in-process port (<c>--impl</c>) into a finding of its own kind,
/// HANG, as a child's crash or hang is ADAPTER-FAILURE for <c>--impl-cmd</c>. A hang cannot be run again inside acphys
/// (a thread that never returns cannot be stopped), so each candidate, smallest first, is decoded into a case file and
/// replayed by a child <c>acphys replay FILE --impl PORT --timeout T</c>, whose watchdog stops it with exit 2 when a
/// call does not return. The first input that hangs the child is written to <c>REGRESSIONS/hangs/</c> with the replay
/// line that names the port (exit 2 there, the port still hangs; exit 0 on the reference); an input that completes
/// when run again was slow, not hung, and is counted as not reproducing (a false alarm is the worst outcome).
/// </summary>
/// <param name="s">The settings.</param>
/// <param name="stop">Cancelled to stop the replay child (the campaign passes none: triage runs to its end after Ctrl-C, and the child dies with acphys).</param>
internal sealed partial class HangTriage(FuzzSettings s, CancellationToken stop)
{
    /// <summary>The key of a hang finding.</summary>
    public const string Key = "HANG";

    // Each try may wait its timeout: a few of the smallest hangs are enough, they are one finding.
    private const int MaxTries = 3;

    /// <summary>Gets the most one call of the port may take in the replay child: 5× afl-fuzz's -t, at least 5 s.</summary>
    public TimeSpan Limit => s.PortCaseLimit;

    /// <summary>Triages the hang files of an in-process port's campaign.</summary>
    /// <param name="hangFiles">The inputs afl-fuzz kept as hangs (or one input that hung acphys's own watch, <see cref="PortWatch"/>).</param>
    /// <param name="originOf">How the stored case names where an input came from; null: afl's <c>INSTANCE/hangs/FILE</c>.</param>
    /// <returns>The HANG group, a not-reproduced group, or null when there is nothing to triage.</returns>
    public TriageGroup? Run(IReadOnlyList<string> hangFiles, Func<string, string>? originOf = null)
    {
        if (s.Port.AssemblyPath is not { } dll || hangFiles.Count == 0)
        {
            return null;
        }

        Directory.CreateDirectory(Path.Combine(s.CampaignDir, "triage"));
        foreach (string file in hangFiles.OrderBy(f => new FileInfo(f).Length).ThenBy(f => f, StringComparer.Ordinal).Take(MaxTries))
        {
            byte[] data = File.ReadAllBytes(file);
            string origin = originOf?.Invoke(file) ?? $"afl {s.Target.Name} {Path.GetFileName(Path.GetDirectoryName(Path.GetDirectoryName(file)))}/hangs/{Path.GetFileName(file)}";
            if (s.Target.AsEntry(data, $"{Key}: the port does not return within {Limit.TotalSeconds:0.###} s", origin) is not { } entry)
            {
                return null;
            }

            string json = CorpusJson.Write(entry);
            string candidate = Path.Combine(s.CampaignDir, "triage", "hang-candidate.json");
            AtomicFile.WriteAllText(candidate, json);
            var (code, output) = Replay(candidate, dll);
            if (code == ExitCodes.ToolError && NoReturn().Match(output) is { Success: true } m)
            {
                string path = Path.Combine(s.RegressionsDir, "hangs", $"{s.Target.Name}-{Key}-{Convert.ToHexStringLower(SHA256.HashData(data))[..8]}.json");
                bool known = File.Exists(path);
                Directory.CreateDirectory(Path.GetDirectoryName(path)!);
                AtomicFile.WriteAllText(path, json);
                File.Delete(candidate);
                return new TriageGroup(Key, m.Value, hangFiles.Count, file, path, LineFor(path, dll), true, known);
            }

            File.Delete(candidate);
        }

        return new TriageGroup(Key + " (does not reproduce)", $"every input tried returned within {Limit.TotalSeconds:0.###} s when run again (slow, not hung)", hangFiles.Count, string.Empty, null, null, false, false);
    }

    // acphys itself as the child (the apphost, or dotnet and the entry assembly), in a guarded process group.
    private (int Code, string Output) Replay(string file, string dll)
    {
        string host = Environment.ProcessPath ?? "dotnet";
        string[] prefix = Path.GetFileNameWithoutExtension(host) == "dotnet" ? [Assembly.GetEntryAssembly()!.Location] : [];
        string seconds = Limit.TotalSeconds.ToString("0.###", CultureInfo.InvariantCulture);
        return GuardedChild.Run(host, [.. prefix, "replay", file, "--impl", dll, "--timeout", seconds], null, stop);
    }

    private string LineFor(string path, string dll)
    {
        string rel = Path.GetRelativePath(s.Root, path);
        return string.Join(' ', new[] { ReplayLine.Program, "replay", rel.StartsWith("..", StringComparison.Ordinal) ? path : rel, "--impl", dll }.Select(ReplayLine.Quote));
    }

    [GeneratedRegex(@"did not return from [^\n]*? within")]
    private static partial Regex NoReturn();
}
