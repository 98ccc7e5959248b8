using System.Security.Cryptography;
using AcPhys.Cli.Verify;
using AcPhys.Formats.Corpus;
using AcPhys.Fuzz.Targets;
using AcPhys.Protocol.Client;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Judging;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Turns a campaign's crash files into regressions: re-runs every crash, groups them by (invariant ID, signature),
/// shrinks the smallest input of each group with the properties' shrinker, and writes
/// <c>&lt;INVARIANT&gt;-&lt;hash&gt;.json</c> atomically after checking that <c>acphys replay</c> reproduces it. Findings that
/// are not invariant violations (parser targets, stray exceptions) keep their smallest raw input.
/// </summary>
/// <param name="s">The settings.</param>
/// <param name="subject">The implementation the campaign fuzzed, opened in acphys (a port's own assembly or one child).</param>
/// <param name="watch">Bounds each case an in-process port runs (<see cref="PortWatch"/>).</param>
internal sealed class CrashTriage(FuzzSettings s, Subject subject, PortWatch watch)
{
    /// <summary>Gets the folder where raw inputs of non-physics findings and the triage report go.</summary>
    public string TriageDir => Path.Combine(s.CampaignDir, "triage");

    /// <summary>Triages crash files.</summary>
    /// <param name="crashFiles">The inputs that crashed.</param>
    /// <returns>The groups, biggest first.</returns>
    public IReadOnlyList<TriageGroup> Run(IReadOnlyList<string> crashFiles)
    {
        var findings = new List<(string File, byte[] Data, Finding Finding)>();
        int gone = 0;
        foreach (string file in crashFiles)
        {
            byte[] data = File.ReadAllBytes(file);
            if (watch.Run($"crash input {file}", data, () => s.Target.Classify(data, subject)) is { } finding)
            {
                findings.Add((file, data, finding));
            }
            else
            {
                gone++;
            }
        }

        var groups = new List<TriageGroup>();
        foreach (var g in findings.GroupBy(f => (f.Finding.Key, f.Finding.Signature)).OrderByDescending(g => g.Count()))
        {
            var smallest = g.OrderBy(f => f.Data.Length).ThenBy(f => f.File, StringComparer.Ordinal).First();
            groups.Add(Settle(g.Key.Key, g.Key.Signature, g.Count(), smallest.File, smallest.Data, smallest.Finding));
        }

        if (gone > 0)
        {
            groups.Add(new TriageGroup("(does not reproduce)", "the input passes when run again", gone, string.Empty, null, null, false, false));
        }

        return groups;
    }

    private TriageGroup Settle(string key, string signature, int count, string file, byte[] data, Finding finding)
    {
        string origin = $"afl {s.Target.Name} {Path.GetFileName(Path.GetDirectoryName(Path.GetDirectoryName(file)))}/{Path.GetFileName(file)} hex:{Hex(data)}";
        if (finding.IsViolation && watch.Run($"a shrink candidate of crash input {file}", null, () => s.Target.Minimise(finding, subject, origin)) is { } entry)
        {
            string path = Path.Combine(s.RegressionsDir, FailureFile.NameFor(entry));
            bool known = File.Exists(path);
            bool reproduces = Reproduces(entry);
            if (!known && reproduces)
            {
                AtomicFile.WriteAllText(path, CorpusJson.Write(entry));
            }

            return new TriageGroup(key, signature, count, file, path, ReplayCommand(path), reproduces, known);
        }

        // No stored case format: keep the smallest raw input, named by its content; a parser's goes to
        // <regressions>/parsers, which props (ParserRegressions) replays on every test run; a port's crash, hang or
        // exception to <regressions>/crashes (a finding of its own kind: the port could not answer the case at all).
        string folder = s.Target.Kind == TargetKind.Parser ? Path.Combine(s.RegressionsDir, "parsers")
            : s.Port.IsExternal ? Path.Combine(s.RegressionsDir, "crashes")
            : TriageDir;
        string raw = Path.Combine(folder, $"{s.Target.Name}-{key}-{Convert.ToHexStringLower(SHA256.HashData(data))[..8]}.bin");
        bool had = File.Exists(raw);
        AtomicFile.WriteAllBytes(raw, data);
        string replay = $"{HarnessEnvironment()}{s.Harness} replay {s.Target.Name} {raw}";
        return new TriageGroup(key, signature, count, file, raw, replay, true, had);
    }

    // The file must fail the same way in `acphys replay` under the campaign's fault: the same judges (Judges) find the
    // invariant the finding names.
    private bool Reproduces(CorpusEntry entry)
    {
        try
        {
            return watch.Run("the shrunk case " + AcPhys.Formats.Values.InputQuote.Line(entry.Title, 80), null, () => CaseReplay.Reproduces(entry, subject.Fresh()));
        }
        catch (AcPhys.Contract.AdapterFailureException)
        {
            subject.Discard();
            return false;
        }
    }

    // The harness replays a raw input against what the campaign ran: the planted fault, or the port (its own assembly).
    private string HarnessEnvironment() =>
        s.Port.Command is { } cmd ? $"{PortSubject.CommandVariable}={ReplayLine.Quote(cmd)} "
        : s.Port.AssemblyPath is { } dll ? $"{PortSubject.ImplVariable}={ReplayLine.Quote(dll)} "
        : s.Fault is null ? string.Empty : $"ACPHYS_FAULT={s.Fault} ";

    private string ReplayCommand(string path)
    {
        string rel = Path.GetRelativePath(s.Root, path);
        var words = new List<string> { ReplayLine.Program, "replay", rel.StartsWith("..", StringComparison.Ordinal) ? path : rel };
        if (s.Fault is not null)
        {
            words.AddRange(["--fault", s.Fault]);
        }

        words.AddRange((s.Port with { Timeout = ProcessAdapterOptions.DefaultTimeout }).Words()); // --impl PATH / --impl-cmd COMMAND: the port that fails it (replay waits the default 10 s per answer)

        return string.Join(' ', words.Select(ReplayLine.Quote));
    }

    private static string Hex(byte[] data) => data.Length <= 128 ? Convert.ToHexStringLower(data) : Convert.ToHexStringLower(data.AsSpan(0, 128)) + "…";
}

/// <summary>One group of crashes with the same invariant ID (or exception type) and signature.</summary>
/// <param name="Key">Invariant ID or exception type.</param>
/// <param name="Signature">The masked message.</param>
/// <param name="Count">How many crash files.</param>
/// <param name="Smallest">The smallest crash file.</param>
/// <param name="Written">The regression (or raw input) file, or null.</param>
/// <param name="Replay">The command that replays it, or null.</param>
/// <param name="Reproduces">Whether the written file was seen to reproduce.</param>
/// <param name="Known">Whether the file existed before (a known finding).</param>
internal sealed record TriageGroup(string Key, string Signature, int Count, string Smallest, string? Written, string? Replay, bool Reproduces, bool Known);
