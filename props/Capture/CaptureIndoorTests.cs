using System.Globalization;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Faults;
using Xunit.Abstractions;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-INDOOR: a capture through a building's door and back, over the user's dat files (the corpus cottage written by
/// the tool's own dat writer), written from the documented format by the tests' own client loop: the reference's capture
/// is 0 divergent with indoor frames judged; a planted indoor fault is found at the first frame its cell leaves the
/// reference's; frames on a portal plane within the printed precision are not judged, never divergent; without the dats
/// every indoor frame is not judged and counted.
/// </summary>
public sealed class CaptureIndoorTests(ITestOutputHelper output)
{
    [Fact(DisplayName = "CAPTURE-INDOOR: the reference's capture in by the door, through both rooms and out is 0 divergent, its env-cell frames judged in the dat scene")]
    public void ReferenceCaptureAgreesIndoors()
    {
        string text = SceneCaptureWriter.Native(ReferenceAdapter.Instance, CaptureIndoorFixture.Scene, 0xA9B40031, 147.1f, 5.03f, CaptureIndoorFixture.InAndOut, out var cells);
        var report = CaptureIndoorFixture.Check(text);
        Print(report);
        Assert.Contains(0xA9B40100u, cells);
        Assert.Contains(0xA9B40101u, cells);
        Assert.Equal(0xA9B40031u, cells[^1]); // out again
        Assert.Equal(0, report.Divergent);
        Assert.Equal(CaptureIndoorFixture.InAndOut.Count + 1, report.Read);
        int indoorFrames = cells.Count(c => (c & 0xFFFF) >= 0x100);
        Assert.True(report.Judged >= report.Read - 6 && indoorFrames >= 30, $"judged {report.Judged} of {report.Read}; {indoorFrames} frames indoors");
        Assert.Equal(0, CaptureIndoorFixture.Skipped(report, "indoor-no-dats"));
    }

    [Theory(DisplayName = "CAPTURE-INDOOR: a planted indoor fault's capture is divergent from the first frame its cell leaves the reference's (outdoor-wins holds the land cell on the way in, no-exit-transit the room on the way out)")]
    [InlineData("outdoor-wins", "cell-held-outside")]
    [InlineData("no-exit-transit", "cell-held-indoors")]
    public void PlantedIndoorFaultFoundAtTheRightFrame(string fault, string cause)
    {
        SceneCaptureWriter.Native(ReferenceAdapter.Instance, CaptureIndoorFixture.Scene, 0xA9B40031, 147.1f, 5.03f, CaptureIndoorFixture.InAndOut, out var want);
        string text = SceneCaptureWriter.Native(PlantedFaults.Create(fault), CaptureIndoorFixture.Scene, 0xA9B40031, 147.1f, 5.03f, CaptureIndoorFixture.InAndOut, out var got);
        int first = Enumerable.Range(0, want.Count).First(i => want[i] != got[i]);
        var report = CaptureIndoorFixture.Check(text);
        Print(report);
        Assert.Equal(first, report.FirstDivergence);
        Assert.Equal(cause, report.Spans[0].Cause);
        Assert.Equal(new CellId(got[first]), report.Spans[0].PortCell);
        Assert.Equal(new CellId(want[first]), report.Spans[0].ReferenceCell);
    }

    [Fact(DisplayName = "CAPTURE-INDOOR: frames on the door's plane (printed 2.000, 1.9999, 2.0001), reported outside or inside, are not judged, never divergent; the frames between them are judged")]
    public void FramesOnAPortalPlaneAreNotJudged()
    {
        var lines = new List<string> { "# frame: block", "# body: [{\"x\":0,\"y\":0,\"z\":0.6,\"r\":0.5},{\"x\":0,\"y\":0,\"z\":1.3,\"r\":0.5}]" };
        int n = 0;
        void Frame(uint cell, string y) => lines.Add(string.Create(CultureInfo.InvariantCulture, $"{n++}\t0x{cell:X8}\t147.100\t{y}\t0.000"));
        Frame(0xA9B40031, "3.000");
        foreach (string y in new[] { "2.000", "1.9999", "2.0001" })
        {
            Frame(0xA9B40031, y); // on the plane, still outside
            Frame(0xA9B40100, y); // on the plane, inside
            Frame(0xA9B40100, "1.000");
            Frame(0xA9B40100, y); // back on it from inside
            Frame(0xA9B40031, y); // and out
            Frame(0xA9B40031, "3.000");
        }

        var report = CaptureIndoorFixture.Check(string.Join('\n', lines) + "\n");
        Print(report);
        Assert.Equal(0, report.Divergent);
        long onPlane = CaptureIndoorFixture.Skipped(report, "near-cell-face") + CaptureIndoorFixture.Skipped(report, "near-portal-plane");
        Assert.Equal(12, onPlane);
        Assert.Equal(7, report.Judged); // the frames at y = 3 and y = 1
    }

    [Fact(DisplayName = "CAPTURE-INDOOR: without the dat files every indoor frame is not judged (indoor-no-dats, counted), the open-land frames are")]
    public void WithoutDatsIndoorFramesAreNotJudged()
    {
        string text = SceneCaptureWriter.Native(ReferenceAdapter.Instance, CaptureIndoorFixture.Scene, 0xA9B40031, 147.1f, 5.03f, CaptureIndoorFixture.InAndOut, out var cells);
        var report = CaptureIndoorFixture.Check(text, dats: false);
        Print(report);
        int indoorOrAcross = Enumerable.Range(0, cells.Count).Count(i => (cells[i] & 0xFFFF) >= 0x100 || (i > 0 && (cells[i - 1] & 0xFFFF) >= 0x100));
        Assert.Equal(indoorOrAcross, CaptureIndoorFixture.Skipped(report, "indoor-no-dats"));
        Assert.Equal(report.Read - indoorOrAcross, report.Judged); // the open-land frames, none near a line
        Assert.Equal(0, report.Divergent);
    }

    [Fact(DisplayName = "CAPTURE-INDOOR: an indoor frame the dats do not hold (another block's env cell), the first frame indoors, and a capture without a body are not judged, with their reasons")]
    public void FramesTheDatsCannotJudgeSayWhy()
    {
        const string body = "# body: [{\"x\":0,\"y\":0,\"z\":0.6,\"r\":0.5}]\n";
        var missing = CaptureIndoorFixture.Check("# frame: block\n" + body + "0\t0xA9B40031\t147.100\t3.000\t0.000\n1\t0xA9B40177\t147.100\t1.000\t0.000\n2\t0x12340100\t10.000\t10.000\t0.000\n");
        Assert.Equal(2, CaptureIndoorFixture.Skipped(missing, "not-in-dats"));
        var first = CaptureIndoorFixture.Check("# frame: block\n" + body + "0\t0xA9B40100\t147.100\t1.000\t0.000\n");
        Assert.Equal(1, CaptureIndoorFixture.Skipped(first, "indoor-no-previous-cell"));
        var nobody = CaptureIndoorFixture.Check("# frame: block\n0\t0xA9B40031\t147.100\t3.000\t0.000\n1\t0xA9B40100\t147.100\t1.000\t0.000\n");
        Assert.Equal(1, CaptureIndoorFixture.Skipped(nobody, "indoor-no-body"));
        Assert.Equal(0, missing.Divergent + first.Divergent + nobody.Divergent);
    }

    private void Print(AcPhys.Spec.Capture.CaptureReport r)
    {
        output.WriteLine($"read {r.Read}, judged {r.Judged}, divergent {r.Divergent}, first {r.FirstDivergence}; not judged: {string.Join(", ", r.NotJudged.Select(n => $"{n.Reason.Id} {n.Count}"))}");
        foreach (var s in r.Spans)
        {
            output.WriteLine($"  [{s.Cause}] frames {s.First.Number}-{s.LastNumber}: {s.Describe()}");
        }
    }
}
