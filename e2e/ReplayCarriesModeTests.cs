using AcPhys.Contract;
using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;

namespace AcPhys.E2E;

/// <summary>
/// Issue 41, "replay carries the mode": a failure found in a declared mode, pick or fault prints a verify line and writes
/// a case file that both carry every option that changed the verdict (<c>--fidelity</c>, <c>--pick</c>, <c>--fault</c>; for a
/// served port, its command line), so the printed line and <c>acphys replay FILE</c> both exit 1 again.
/// </summary>
public sealed class ReplayCarriesModeTests
{
    private const string Fault = "close-is-outside"; // caught by FIND-CELL-CONFORMANCE within a few cases

    /// <summary>Gets every fidelity name a port can declare (each switch, double, ace).</summary>
    public static TheoryData<string> Declarations
    {
        get
        {
            var data = new TheoryData<string>();
            foreach (string name in FidelityNames.Known)
            {
                data.Add(name);
            }

            return data;
        }
    }

    [Theory(DisplayName = "REPLAY-CARRIES-MODE: a failure found with a declared fidelity replays to exit 1 from its printed line (which names the declaration) and from its case file (which stores it)")]
    [MemberData(nameof(Declarations))]
    public void DeclaredFidelityReplays(string name)
    {
        var (line, file, env) = Fail(["--fault", Fault, "--fidelity", name, "--only", "FIND-CELL-CONFORMANCE", "--cases", "100"], "FIND-CELL-CONFORMANCE");
        Assert.Contains($"--fidelity {name}", line, StringComparison.Ordinal);
        Assert.Contains($"--fault {Fault}", line, StringComparison.Ordinal);
        var mode = CorpusJson.ReadFile(file).Mode;
        Assert.NotNull(mode);
        Assert.Equal([name], mode.Fidelity);
        Assert.Equal(Fault, mode.Fault);
        ReplaysToExit1(line, file, env, "FIND-CELL-CONFORMANCE");
    }

    [Fact(DisplayName = "REPLAY-CARRIES-MODE: a failure found with --pick current-first replays to exit 1 from its line and its file; without the pick the same seed tests nothing (HYSTERESIS applies to current-first only)")]
    public void PickReplays()
    {
        var (line, file, env) = Fail(["--fault", "clamp-106", "--pick", "current-first", "--only", "HYSTERESIS", "--cases", "300"], "HYSTERESIS");
        Assert.Contains("--pick current-first", line, StringComparison.Ordinal);
        Assert.Equal("current-first", CorpusJson.ReadFile(file).Mode?.Pick);
        ReplaysToExit1(line, file, env, "HYSTERESIS");

        string[] withoutPick = [.. Words(line).Where(w => w is not "--pick" and not "current-first")];
        var dropped = Acphys.Run(withoutPick, env);
        Assert.NotEqual(1, dropped.Exit); // the mode is what made it fail: the line must carry it
    }

    [Fact(DisplayName = "REPLAY-CARRIES-MODE: a fault found alone replays from its case file without --fault (the file stores it)")]
    public void FaultReplays()
    {
        var (line, file, env) = Fail(["--fault", Fault, "--only", "FIND-CELL-CONFORMANCE", "--cases", "100"], "FIND-CELL-CONFORMANCE");
        Assert.Contains($"--fault {Fault}", line, StringComparison.Ordinal);
        Assert.Equal(Fault, CorpusJson.ReadFile(file).Mode?.Fault);
        ReplaysToExit1(line, file, env, "FIND-CELL-CONFORMANCE");
    }

    [Fact(DisplayName = "REPLAY-CARRIES-MODE: a failure of a port served with a declaration (acphys serve --fault F --fidelity X) replays to exit 1 from both printed lines, the command carrying the declaration")]
    public void ServedDeclarationReplays()
    {
        string port = $"{Acphys.ServeCommand} --fault {Fault} --fidelity ace-keeps-stale-cells";
        var (line, file, env) = Fail(["--impl-cmd", port, "--only", "FIND-CELL-CONFORMANCE", "--cases", "100", "--timeout", "60"], "FIND-CELL-CONFORMANCE");
        Assert.Contains("--fidelity ace-keeps-stale-cells", line, StringComparison.Ordinal);
        ReplaysToExit1(line, file, env, "FIND-CELL-CONFORMANCE", ["--impl-cmd", port, "--timeout", "60"]);
    }

    [Theory(DisplayName = "REPLAY-CARRIES-MODE: a parts failure found under the declared ace-box-side-pairing (facts §7 #14) replays to exit 1 from its printed line and its case file, in process and served")]
    [InlineData(false)]
    [InlineData(true)]
    public void BoxSidePairingReplays(bool served)
    {
        const string Invariant = "PARTS-INDOOR-CONFORMANCE";
        const string PartsFault = "parts-order-lost"; // caught by PARTS-INDOOR-CONFORMANCE alone, within a few hundred cases
        string port = $"{Acphys.ServeCommand} --fault {PartsFault} --fidelity ace-box-side-pairing";
        string[] options = served
            ? ["--impl-cmd", port, "--only", Invariant, "--cases", "300", "--timeout", "60"]
            : ["--fault", PartsFault, "--fidelity", "ace-box-side-pairing", "--only", Invariant, "--cases", "300"];
        var (line, file, env) = Fail(options, Invariant);
        Assert.Contains("--fidelity ace-box-side-pairing", line, StringComparison.Ordinal);
        if (!served)
        {
            Assert.Equal(["ace-box-side-pairing"], CorpusJson.ReadFile(file).Mode?.Fidelity);
        }

        ReplaysToExit1(line, file, env, Invariant, served ? ["--impl-cmd", port, "--timeout", "60"] : null);
    }

    [Fact(DisplayName = "REPLAY-CARRIES-MODE: ACE's box-side pairing served undeclared (ace-box-side-undeclared) fails PARTS-INDOOR-CONFORMANCE and replays to exit 1 from its line and its file")]
    public void BoxSideUndeclaredReplays()
    {
        var (line, file, env) = Fail(["--fault", "ace-box-side-undeclared", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "300"], "PARTS-INDOOR-CONFORMANCE");
        Assert.Contains("--fault ace-box-side-undeclared", line, StringComparison.Ordinal);
        ReplaysToExit1(line, file, env, "PARTS-INDOOR-CONFORMANCE");
    }

    // Runs a failing verify; returns its printed replay line (without the program), its case file and the environment.
    private static (string Line, string File, Dictionary<string, string> Env) Fail(string[] options, string invariant)
    {
        string dir = Directory.CreateTempSubdirectory("acphys-mode-").FullName;
        var env = new Dictionary<string, string> { ["ACPHYS_FAILURES"] = dir };
        var verify = Acphys.Run(["verify", .. options, "--max-classes", "1"], env);
        Assert.True(verify.Exit == 1, verify.ToString());
        string line = verify.Out.Split('\n').Select(l => l.Trim()).First(l => l.StartsWith("replay     acphys verify ", StringComparison.Ordinal))["replay     acphys ".Length..];
        string file = Assert.Single(Directory.GetFiles(dir, invariant + "-*.json"));
        return (line, file, env);
    }

    private static void ReplaysToExit1(string line, string file, Dictionary<string, string> env, string invariant, string[]? implWords = null)
    {
        var again = Acphys.Run(Words(line), env);
        Assert.True(again.Exit == 1, $"{line}\n{again}");
        Assert.Contains($"FAIL {invariant}", again.Out, StringComparison.Ordinal);

        var replay = Acphys.Run(["replay", file, .. implWords ?? []], env);
        Assert.True(replay.Exit == 1, $"replay {file}\n{replay}");
        Assert.Contains($"VIOLATED {invariant}", replay.Out, StringComparison.Ordinal);
    }

    // The words of a printed line (a quoted --impl-cmd kept whole).
    private static string[] Words(string line)
    {
        var words = new List<string>();
        var current = new System.Text.StringBuilder();
        bool quoted = false;
        foreach (char c in line)
        {
            if (c == '\'')
            {
                quoted = !quoted;
            }
            else if (c == ' ' && !quoted)
            {
                words.Add(current.ToString());
                current.Clear();
            }
            else
            {
                current.Append(c);
            }
        }

        words.Add(current.ToString());
        return [.. words.Where(w => w.Length > 0)];
    }
}
