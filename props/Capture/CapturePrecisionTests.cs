using System.Globalization;
using System.Numerics;
using System.Text;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-PRECISION: a log that rounds to millimetres at cell lines is never a false alarm — a port answering exactly
/// as the reference at its true positions, 0.4 mm either side of a 24 m line, printed to 3 decimals (so on the line), is
/// judged 0 divergent, those frames not judged with the reason; the same frames printed to full float32 precision are judged.
/// </summary>
public sealed class CapturePrecisionTests
{
    [Fact(DisplayName = "CAPTURE-PRECISION: positions 24k ± 0.0004 printed to 3 decimals are not judged, never divergent; the reference at the printed point would differ")]
    public void RoundingAtCellLinesIsNoFalseAlarm()
    {
        var (text, differsAtPrinted) = Capture(3);
        var report = CaptureRunner.Check(text);
        Assert.Equal(0, report.Divergent);
        var nearLine = report.NotJudged.Single(n => n.Reason.Id == "near-cell-line").Count;
        Assert.True(nearLine >= differsAtPrinted && differsAtPrinted > 0, $"{nearLine} frames not judged near a line; {differsAtPrinted} frames whose printed point the reference answers otherwise");
    }

    [Fact(DisplayName = "CAPTURE-PRECISION: the same frames printed to 9 decimals are judged and agree")]
    public void FullPrecisionIsJudged()
    {
        var report = CaptureRunner.Check(Capture(9).Text);
        Assert.Equal(0, report.Divergent);
        Assert.Equal(0, report.NotJudgedTotal);
        Assert.True(report.CornerChecks > 0); // near a line: the corners decided
    }

    // x = 24k ± 0.0004 (k = 1..7) and y = 24k ± 0.0004 in block A9B4, each frame answered by the reference at its true
    // position from the cell the previous frame left it in; how many printed points the reference answers otherwise.
    private static (string Text, int DiffersAtPrinted) Capture(int decimals)
    {
        var text = new StringBuilder("# frame: block\n# radius: 0.48\n");
        var before = CellId.None;
        int n = 0, differs = 0;
        foreach (int k in Enumerable.Range(1, 7))
        {
            foreach (float d in new[] { -0.0004f, 0.0004f })
            {
                foreach (bool onX in new[] { true, false })
                {
                    var p = onX ? new Vector3((24 * k) + d, 100, 0) : new Vector3(100, (24 * k) + d, 0);
                    var from = new CellId(0xA9B40001 + (uint)((int)(p.X / 24) * 8) + (uint)(int)(p.Y / 24));
                    var truth = ReferenceAdapter.Instance.FindCell(from, p, [new Sphere(p, 0.48f)], before);
                    var cell = truth.Containing;
                    string F(float v) => v.ToString("F" + decimals, CultureInfo.InvariantCulture);
                    var printed = new Vector3(float.Parse(F(p.X), CultureInfo.InvariantCulture), float.Parse(F(p.Y), CultureInfo.InvariantCulture), 0);
                    if (ReferenceAdapter.Instance.FindCell(from, printed, [new Sphere(printed, 0.48f)], before).Containing != cell)
                    {
                        differs++;
                    }

                    text.Append(CultureInfo.InvariantCulture, $"{n++}\t0x{cell.Value:X8}\t{F(p.X)}\t{F(p.Y)}\t0.000\n");
                    before = cell;
                }
            }
        }

        return (text.ToString(), differs);
    }
}
