using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Capture;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Judging;
using Xunit.Abstractions;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-SEED: the seed's geometry (facts §8: 0xA9B40031 at (150, −0.5) belongs to 0xA9B30038) as a capture — the
/// planted clamp-106 walking south over the A9B4/A9B3 line is found at the first frame past the line, in both formats,
/// and minimised to at most 3 frames whose replay fails on the recorded answers and on the fault, and holds on the reference.
/// </summary>
public sealed class CaptureSeedTests(ITestOutputHelper output)
{
    // From y = 1.95 by −0.1: frame 19 at y = 0.05, frame 20 at y = −0.05 — the first frame past the line.
    private static readonly CaptureWriter.Plan South = new(0xA9B40031, 150, 1.95f, 0, -0.1f, 40, [(0, 0, 0, 0.48f)]);
    private const int FirstPastTheLine = 20;

    [Fact(DisplayName = "CAPTURE-SEED: a frozen native capture (cells only) is found at the first frame past the line, 0xA9B40031 held where the reference has 0xA9B30038")]
    public void FrozenNativeCaptureFoundAtTheLine()
    {
        var report = CaptureRunner.Check(CellsOnly(CaptureWriter.Native(PlantedFaults.Create("clamp-106"), South, candidates: false)));
        var span = Assert.Single(report.Spans);
        output.WriteLine(span.Describe());
        Assert.Equal(FirstPastTheLine, report.FirstDivergence);
        Assert.Equal("cell-held-across-block-line", span.Cause);
        Assert.Equal(new CellId(0xA9B40031), span.PortCell);
        Assert.Equal(new CellId(0xA9B30038), span.ReferenceCell);
        Assert.Equal(South.Frames - FirstPastTheLine, report.Divergent);
        Assert.Equal(South.Frames - 1, span.LastNumber);
        Assert.InRange(span.Moved, 1.85, 1.95); // frames 20 to 39: 19 moves of 0.1 m
    }

    [Fact(DisplayName = "CAPTURE-SEED: the same walk recorded from the reference is 0 divergent, native and acdream")]
    public void ReferenceCaptureAgrees()
    {
        var native = CaptureRunner.Check(CaptureWriter.Native(ReferenceAdapter.Instance, South));
        var log = CaptureRunner.Check(CaptureWriter.Acdream(ReferenceAdapter.Instance, South, 0xA9B4), format: CaptureFormat.Acdream, options: new CaptureOptions(new LandblockId(0xA9B4), 0.48f));
        Assert.Equal(0, native.Divergent);
        Assert.Equal(0, log.Divergent);
        Assert.True(native.Judged >= South.Frames - 2 && log.Judged >= South.Frames - 2, $"judged {native.Judged} native, {log.Judged} acdream");
    }

    [Fact(DisplayName = "CAPTURE-SEED: a frozen acdream log is found at the first frame past the line (frame numbers count probe frames from 1), its other lines ignored and counted")]
    public void FrozenAcdreamLogFoundAtTheLine()
    {
        string log = CaptureWriter.Acdream(PlantedFaults.Create("clamp-106"), South, 0xA9B4);
        using var reader = CaptureReaders.Open(new MemoryStream(System.Text.Encoding.UTF8.GetBytes(log)), "test.log", CaptureFormat.Acdream, new CaptureOptions(new LandblockId(0xA9B4), null));
        var report = new CaptureChecker(CaptureChecker.OutdoorOnly(PickPolicy.Retail, default)).Check(reader);
        Assert.Equal(FirstPastTheLine + 1, report.FirstDivergence);
        Assert.Equal("cell-held-across-block-line", report.Spans[0].Cause);
        Assert.Equal(South.Frames + 1, report.Ignored); // "acdream starting" and one "[net] tick" per frame
    }

    [Fact(DisplayName = "CAPTURE-SEED: the finding is minimised to at most 3 frames; its replay fails on the recorded answers (exit 1) and on clamp-106, and holds on the reference")]
    public void MinimisedWalkReplays()
    {
        var report = CaptureRunner.Check(CellsOnly(CaptureWriter.Native(PlantedFaults.Create("clamp-106"), South, candidates: false)));
        var least = new CaptureMinimiser(PickPolicy.Retail, default, null).Minimise(report.Spans[0], "frozen.capture");
        Assert.NotNull(least);
        output.WriteLine(CorpusJson.Write(least.Entry));
        Assert.InRange(least.Frames, 1, 3);
        var entry = CorpusJson.Read(CorpusJson.Write(least.Entry), "minimised"); // as replay reads it
        Assert.NotNull(entry.Recorded);
        Assert.Equal(CaseReplay.Violated, CaseReplay.Of(entry, new RecordedPhysics(entry.Walk!, entry.Recorded, ReferenceAdapter.Instance)).ExitCode);
        Assert.Equal(CaseReplay.Violated, CaseReplay.Of(entry, PlantedFaults.Create("clamp-106")).ExitCode);
        Assert.Equal(CaseReplay.Holds, CaseReplay.Of(entry, ReferenceAdapter.Instance).ExitCode);
    }

    [Fact(DisplayName = "CAPTURE-SEED: a capture re-asked of the port (--impl) finds clamp-106 without trusting the log, and the reference with a lying log clean")]
    public void ReaskedPortReplacesTheLog()
    {
        string lying = CellsOnly(CaptureWriter.Native(ReferenceAdapter.Instance, South, candidates: false)); // the log says all is well
        using var reader = CaptureReaders.Open(new MemoryStream(System.Text.Encoding.UTF8.GetBytes(lying)), "t", CaptureFormat.Native, new CaptureOptions(null, null));
        var report = new CaptureChecker(CaptureChecker.OutdoorOnly(PickPolicy.Retail, default), PlantedFaults.Create("clamp-106")).Check(reader);
        Assert.True(report.Divergent > 0);
        string frozen = CellsOnly(CaptureWriter.Native(PlantedFaults.Create("clamp-106"), South, candidates: false));
        using var again = CaptureReaders.Open(new MemoryStream(System.Text.Encoding.UTF8.GetBytes(frozen)), "t", CaptureFormat.Native, new CaptureOptions(null, null));
        Assert.Equal(0, new CaptureChecker(CaptureChecker.OutdoorOnly(PickPolicy.Retail, default), ReferenceAdapter.Instance).Check(again).Divergent);
    }

    // The body as one radius header (the writer's # body line names the same sphere).
    private static string CellsOnly(string capture) => capture.Replace("# body: [{\"x\":0,\"y\":0,\"z\":0,\"r\":0.48}]", "# radius: 0.48", StringComparison.Ordinal);
}
