using System.Numerics;
using System.Text;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat.Container;
using AcPhys.Props.Support;
using AcPhys.Spec.Capture;

namespace AcPhys.Props.Capture;

/// <summary>
/// The corpus cottage straddling the A9B3/A9B4 line (corpus/seeds/cottage-a9b3-a9b4-in-and-out.json: room 1 at x 144..150,
/// y −4..2 of A9B4 with its door at y = 2, room 2 west of it through x = 144) written once as a dat pair by the tool's
/// own writer (<see cref="SceneContainers"/>, what <c>scene to-dat</c> runs), and captures checked over it.
/// </summary>
internal static class CaptureIndoorFixture
{
    private static readonly Lazy<(string Cell, string Portal)> Files = new(() =>
    {
        string dir = Path.Combine(Path.GetTempPath(), "acphys-capture-indoor-" + Environment.ProcessId);
        Directory.CreateDirectory(dir);
        string cell = Path.Combine(dir, "cell.dat"), portal = Path.Combine(dir, "portal.dat");
        SceneContainers.Write([CottageScene()], cell, portal);
        return (cell, portal);
    });

    /// <summary>Gets the cottage scene.</summary>
    public static Scene Scene { get; } = CottageScene();

    /// <summary>Gets the dat pair's paths.</summary>
    public static (string Cell, string Portal) Dats => Files.Value;

    /// <summary>Gets the walk in by the north door, west into room 2, back east and out: 69 frames.</summary>
    public static IReadOnlyList<Vector2> InAndOut { get; } =
        [.. SceneCaptureWriter.Moves(14, 0, -0.29f), .. SceneCaptureWriter.Moves(20, -0.31f, 0), .. SceneCaptureWriter.Moves(20, 0.31f, 0), .. SceneCaptureWriter.Moves(14, 0, 0.29f)];

    /// <summary>Checks a native capture over the dat pair (or, with <paramref name="dats"/> false, without it).</summary>
    /// <param name="text">The capture.</param>
    /// <param name="dats">Whether the dat files are given.</param>
    /// <param name="indoor">The declared indoor fidelity.</param>
    /// <returns>The report.</returns>
    public static CaptureReport Check(string text, bool dats = true, IndoorFidelity indoor = default)
    {
        using var reader = CaptureReaders.Open(new MemoryStream(Encoding.UTF8.GetBytes(text)), "indoor.capture", CaptureFormat.Native, new CaptureOptions(null, null));
        if (!dats)
        {
            return new CaptureChecker(CaptureChecker.OutdoorOnly(PickPolicy.Retail, default)).Check(reader);
        }

        using var world = DatWorld.Open(Dats.Cell, Dats.Portal);
        return new CaptureChecker(CaptureChecker.WithDats(new DatScenes(world), PickPolicy.Retail, indoor, default)).Check(reader);
    }

    private static Scene CottageScene() => CorpusJson.ReadFile(Path.Combine(RepoPaths.Corpus, "seeds", "cottage-a9b3-a9b4-in-and-out.json")).SceneWalk!.Scene;

    /// <summary>Returns a count of frames not judged for a reason, 0 when none.</summary>
    /// <param name="report">The report.</param>
    /// <param name="id">The reason id.</param>
    /// <returns>The count.</returns>
    public static long Skipped(CaptureReport report, string id) => report.NotJudged.Where(n => n.Reason.Id == id).Sum(n => n.Count);
}
