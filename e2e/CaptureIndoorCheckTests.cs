using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// CAPTURE-INDOOR-CHECK: <c>acphys capture check --cell-dat --portal-dat</c> as a process, on indoor captures an
/// independent writer made (examples/python/acphys_capture.py --cottage: cells read off the cottage's geometry) over the
/// cottage written as dat files by <c>acphys scene to-dat</c>: clean exit 0 with every frame judged; a port holding its land
/// cell indoors exit 1 at the first frame inside; without the dats the indoor frames are counted as not judged; bad
/// dat options exit 2, a damaged dat file exit 5.
/// </summary>
public sealed class CaptureIndoorCheckTests
{
    [RequiresPythonFact(DisplayName = "CAPTURE-INDOOR-CHECK: the cottage capture over its dat files — clean exit 0 (67 of 67 judged), the held land cell exit 1 at frame 5, without dats the 58 indoor frames not judged")]
    public void IndoorCaptureOverDatFiles()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-indoor-").FullName;
        string cell = Path.Combine(dir, "cell.dat"), portal = Path.Combine(dir, "portal.dat");
        var dat = Acphys.Run(["scene", "to-dat", Path.Combine(RepoPaths.Root, "corpus", "seeds", "cottage-a9b3-a9b4-in-and-out.json"), "--cell", cell, "--portal", portal]);
        Assert.True(dat.Exit == 0, dat.ToString());
        string clean = PythonCapture.Write(dir, "clean.tsv", ["--cottage"]);
        string held = PythonCapture.Write(dir, "held.tsv", ["--cottage", "--cottage-bug"]);
        string[] dats = ["--cell-dat", cell, "--portal-dat", portal, "--quiet"];

        var ok = Acphys.Run(["capture", "check", clean, .. dats]);
        Assert.True(ok.Exit == 0, ok.ToString());
        Assert.Contains("frames read 67, judged 67, not judged 0, divergent 0", ok.Out, StringComparison.Ordinal);
        Assert.Contains("1 landblock scene extracted", ok.Out, StringComparison.Ordinal);

        var bad = Acphys.Run(["capture", "check", held, .. dats]);
        Assert.True(bad.Exit == 1, bad.ToString());
        Assert.Contains("\nfirst divergence: frame 5\n", bad.Out, StringComparison.Ordinal); // y = 1.85: the first frame inside room 1
        Assert.Contains("[cell-held-outside]", bad.Out, StringComparison.Ordinal);
        Assert.Contains("cell 0xA9B40031 held for 17 frames", bad.Out, StringComparison.Ordinal);

        var without = Acphys.Run(["capture", "check", clean, "--quiet"]);
        Assert.True(without.Exit == 0, without.ToString());
        Assert.Contains("not judged         58  indoor-no-dats:", without.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "CAPTURE-INDOOR-CHECK: --cell-dat without --portal-dat, a missing dat file, dats with --impl-cmd are exit 2; a damaged dat file is exit 5")]
    public void BadDatOptions()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-indoor-").FullName;
        string capture = Path.Combine(dir, "c.tsv");
        File.WriteAllText(capture, "# radius: 0.5\n0\t0xA9B40031\t147.100\t3.100\t0.000\n");
        string junk = Path.Combine(dir, "junk.dat");
        File.WriteAllBytes(junk, new byte[1024]);
        Assert.Equal(2, Acphys.Run(["capture", "check", capture, "--cell-dat", junk]).Exit);
        var missing = Acphys.Run(["capture", "check", capture, "--cell-dat", junk, "--portal-dat", Path.Combine(dir, "none.dat")]);
        Assert.True(missing.Exit == 2, missing.ToString());
        Assert.Contains("--portal-dat", missing.Err, StringComparison.Ordinal);
        Assert.Equal(2, Acphys.Run(["capture", "check", capture, "--cell-dat", junk, "--portal-dat", junk, "--impl-cmd", "true"]).Exit);
        var damaged = Acphys.Run(["capture", "check", capture, "--cell-dat", junk, "--portal-dat", junk]);
        Assert.True(damaged.Exit == 5, damaged.ToString());
        Assert.DoesNotContain("   at ", damaged.Err, StringComparison.Ordinal);
    }
}
