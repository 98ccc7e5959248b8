using System.Security.Cryptography;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// CAPTURE-CHECK: <c>acphys capture check</c> as a process, on captures an independent writer made
/// (examples/python/acphys_capture.py walking the Python example port, clean and with its clamp-106 bug): a clean
/// capture exits 0, a frozen one 1 with <c>first divergence: frame N</c> at the first frame past the line, in both formats;
/// the minimised walk's printed replay line exits 1, and re-asking the port exits 1 with the bug and 0 without it;
/// a hostile capture is exit 2 naming file and line; the input is never modified.
/// </summary>
public sealed class CaptureCheckTests
{
    // From y = 1.95 by −0.1 at x = 150 in 0xA9B40031: frame 20 (0-based) is the first at y < 0, in block A9B3.
    private static readonly string[] Walk = ["--start", "0xA9B40031", "150", "1.95", "--step", "0", "-0.1", "--frames", "40"];

    [RequiresPythonFact(DisplayName = "CAPTURE-CHECK: native captures from the Python port — clean exit 0, frozen exit 1 at the first frame past the line; the printed replay line exits 1; re-asking the port exits 1 with the bug, 0 without")]
    public void NativeCleanAndFrozen()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-").FullName;
        string clean = Write(dir, "clean.tsv", []);
        string frozen = Write(dir, "frozen.tsv", ["--bug", "clamp-106"]);
        string hash = Hash(frozen);

        var ok = Acphys.Run(["capture", "check", clean, "--quiet"]);
        Assert.True(ok.Exit == 0, ok.ToString());
        Assert.DoesNotContain("first divergence", ok.Out, StringComparison.Ordinal);

        string minimised = Path.Combine(dir, "min");
        var bad = Acphys.Run(["capture", "check", frozen, "--quiet", "--minimise", minimised]);
        Assert.True(bad.Exit == 1, bad.ToString());
        Assert.Contains("\nfirst divergence: frame 20\n", bad.Out, StringComparison.Ordinal);
        Assert.Contains("cell 0xA9B40031 held for 20 frames", bad.Out, StringComparison.Ordinal);
        Assert.Equal(hash, Hash(frozen));

        string[] lines = [.. bad.Out.Split('\n').Select(l => l.Trim()).Where(l => l.Contains(" replay ", StringComparison.Ordinal))];
        string replay = lines.First(l => l.EndsWith(".json", StringComparison.Ordinal));
        var recorded = Acphys.Run(Words(replay));
        Assert.True(recorded.Exit == 1, $"{replay}\n{recorded}");
        Assert.Contains("VIOLATED FIND-CELL-CONFORMANCE", recorded.Out, StringComparison.Ordinal);

        string file = Words(replay)[1];
        var buggy = Acphys.Run(["replay", file, "--impl-cmd", Acphys.PythonExample + " --bug clamp-106"]);
        Assert.True(buggy.Exit == 1, buggy.ToString());
        var fixedPort = Acphys.Run(["replay", file, "--impl-cmd", Acphys.PythonExample]);
        Assert.True(fixedPort.Exit == 0, fixedPort.ToString());

        var reasked = Acphys.Run(["capture", "check", clean, "--quiet", "--impl-cmd", Acphys.PythonExample + " --bug clamp-106"]);
        Assert.True(reasked.Exit == 1, reasked.ToString()); // the log is clean; the port asked again is not
        Assert.Contains("\nfirst divergence: frame ", reasked.Out, StringComparison.Ordinal);
    }

    [RequiresPythonFact(DisplayName = "CAPTURE-CHECK: acdream logs from the Python port — clean exit 0, frozen exit 1 at the first probe frame past the line; other log lines ignored")]
    public void AcdreamCleanAndFrozen()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-").FullName;
        string clean = Write(dir, "clean.log", ["--format", "acdream"]);
        string frozen = Write(dir, "frozen.log", ["--format", "acdream", "--bug", "clamp-106"]);
        string[] options = ["--format", "acdream", "--world-origin", "0xA9B4", "--radius", "0.48", "--quiet"];
        var ok = Acphys.Run(["capture", "check", clean, .. options]);
        Assert.True(ok.Exit == 0, ok.ToString());
        Assert.Contains("other log lines", ok.Out, StringComparison.Ordinal);
        var cells = Acphys.Run(["capture", "check", frozen, "--format", "acdream", "--world-origin", "0xA9B4", "--quiet"]);
        Assert.True(cells.Exit == 1, cells.ToString());
        Assert.Contains("\nfirst divergence: frame 21\n", cells.Out, StringComparison.Ordinal); // probe frames count from 1: the 21st is the first past the line

        // With the radius the cellset lines' candidates are judged too: the clamped list first misses 0xA9B30038 at y = 0.45 < r.
        var sets = Acphys.Run(["capture", "check", frozen, .. options]);
        Assert.True(sets.Exit == 1, sets.ToString());
        Assert.Contains("\nfirst divergence: frame 16\n", sets.Out, StringComparison.Ordinal);
        Assert.Contains("[candidates-missing]", sets.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "CAPTURE-CHECK: a hostile capture is exit 2 naming the file and line; bad options are exit 2")]
    public void HostileIsExitTwo()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-").FullName;
        string nan = Path.Combine(dir, "nan.tsv");
        File.WriteAllText(nan, "# radius: 0.48\n0\t0xA9B40031\t150.000\t1.000\t0.000\n1\t0xA9B40031\tNaN\t0.9\t0.000\n");
        var run = Acphys.Run(["capture", "check", nan, "--quiet"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains($"{nan}:3: x: expected a finite decimal number", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal);

        string binary = Path.Combine(dir, "binary.tsv");
        File.WriteAllBytes(binary, [0x30, 0x09, 0x00, 0xFF, 0x0A]);
        Assert.Equal(2, Acphys.Run(["capture", "check", binary]).Exit);
        Assert.Equal(2, Acphys.Run(["capture", "check", nan, "--format", "acdream"]).Exit); // no --world-origin
        Assert.Equal(2, Acphys.Run(["capture", "check", Path.Combine(dir, "missing.tsv")]).Exit);
    }

    private static string[] Words(string printed) => [.. printed.Split(' ', StringSplitOptions.RemoveEmptyEntries).Skip(1)]; // "acphys replay FILE ..." without the program

    private static string Write(string dir, string name, string[] more) => PythonCapture.Write(dir, name, Walk.Concat(more));

    private static string Hash(string path) => Convert.ToHexString(SHA256.HashData(File.ReadAllBytes(path)));
}
