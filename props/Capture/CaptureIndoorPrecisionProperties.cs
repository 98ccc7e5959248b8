using System.Numerics;
using AcPhys.Contract;
using AcPhys.Props.Mutation;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-INDOOR-PRECISION: a port answering exactly as the reference, its capture printed to millimetres (or to
/// centimetres), is never divergent indoors — walks in and out of the cottage's door and between its rooms, with moves
/// that put the body within fractions of a millimetre of its portal planes, faces and the r-bands around them.
/// </summary>
public sealed class CaptureIndoorPrecisionProperties
{
    [FixedSeedProperty(0xCA97_0050, MaxTest = 150, DisplayName = "CAPTURE-INDOOR-PRECISION: the reference's walks through the cottage, rounded to the printed decimals, are never divergent (frames the rounding could decide are not judged)")]
    public Property RoundedReferenceCaptureNeverDiverges() =>
        Prop.ForAll(Walks.ToArbitrary(), w =>
        {
            string text = SceneCaptureWriter.Native(ReferenceAdapter.Instance, CaptureIndoorFixture.Scene, 0xA9B40031, w.X, w.Y, w.Moves, out var cells, w.Decimals);
            var report = CaptureIndoorFixture.Check(text);
            int indoor = cells.Count(c => (c & 0xFFFF) >= 0x100);
            long near = CaptureIndoorFixture.Skipped(report, "near-cell-face") + CaptureIndoorFixture.Skipped(report, "near-portal-plane") + CaptureIndoorFixture.Skipped(report, "near-cell-line");
            return (report.Divergent == 0)
                .Label($"divergent {report.Divergent}, first {report.FirstDivergence}: {string.Join("; ", report.Spans.Select(s => s.Describe()))}")
                .Classify(indoor > 0, "went indoors")
                .Classify(cells.Contains(0xA9B40101u), "reached room 2")
                .Classify(near > 0, "some frame near a plane, not judged")
                .Classify(w.Decimals == 2, "printed to centimetres")
                .Collect(report.Judged == 0 ? "judged none" : report.Judged * 4 >= report.Read * 3 ? "judged ≥ 75%" : "judged < 75%");
        });

    // From north of the door, moves mostly south and west (into room 1, on into room 2), some back; step lengths
    // that land on and beside the planes at x = 144, 150 and y = 2 (±0.4 mm, and r + 0.01 = 0.51 from them).
    private static Gen<(float X, float Y, int Decimals, Vector2[] Moves)> Walks { get; } =
        from x in Gen.Elements(144.6f, 145.5f, 147.1f, 148.49f, 149.49f, 149.5004f)
        from y in Gen.Elements(2.51f, 2.5102f, 3f, 4.2f, 2.0004f)
        from decimals in Gen.Frequency((4, Gen.Constant(3)), (1, Gen.Constant(2)))
        from moves in Gen.ArrayOf(Move, 40)
        select (x, y, decimals, moves);

    private static Gen<Vector2> Move { get; } =
        from dir in Gen.Frequency((4, Gen.Constant(new Vector2(0, -1))), (3, Gen.Constant(new Vector2(-1, 0))), (1, Gen.Constant(new Vector2(1, 0))), (1, Gen.Constant(new Vector2(0, 1))))
        from len in Gen.Elements(0.1f, 0.25f, 0.3f, 0.49f, 0.5f, 0.51f, 0.0004f, 0.0006f)
        select dir * len;
}
