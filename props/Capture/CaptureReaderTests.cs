using System.Text;
using AcPhys.Core;
using AcPhys.Formats;
using AcPhys.Formats.Capture;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-FORMAT: the readers take the documented formats (fields, headers, the precision printed) and refuse every
/// malformed or hostile input with the file, the line and what was expected — never a crash or a silent frame.
/// </summary>
public sealed class CaptureReaderTests
{
    public static TheoryData<string, string, int, string> Hostile => new()
    {
        { "huge line", "# frame: block\n" + new string('9', 70_000) + "\n", 2, "longer than 65,536 bytes" },
        { "NaN", "0\t0xA9B40031\tNaN\t1.000\t0.000\n", 1, "x: expected a finite decimal number" },
        { "infinity", "0\t0xA9B40031\t150.000\tInfinity\t0.000\n", 1, "y: expected a finite decimal number" },
        { "exponent", "0\t0xA9B40031\t1.5e2\t1.000\t0.000\n", 1, "x: expected a finite decimal number" },
        { "truncated last line", "0\t0xA9B40031\t150.000\t1.000\t0.000\n1\t0xA9B40031\t150.000\t0.9", 2, "truncated last line" },
        { "NUL byte", "0\t0xA9B40031\t150.000\t1.0\0\t0.000\n", 1, "NUL byte" },
        { "not UTF-8", "# caf\u00e9\n0\t0xA9B4\u00ff0031\t150.000\t1.000\t0.000\n", 2, "not valid UTF-8" },
        { "too few fields", "0\t0xA9B40031\t150.000\t1.000\n", 1, "got 4 fields" },
        { "spaces, not tabs", "0 0xA9B40031 150.000 1.000 0.000\n", 1, "got 1 field" },
        { "bad cell", "0\tA9B40031\t150.000\t1.000\t0.000\n", 1, "cell: expected a cell id" },
        { "frames out of order", "5\t0xA9B40031\t150.000\t1.000\t0.000\n5\t0xA9B40031\t150.000\t1.000\t0.000\n", 2, "expected frame numbers that increase" },
        { "negative frame", "-1\t0xA9B40031\t150.000\t1.000\t0.000\n", 1, "frame: expected a frame number" },
        { "header after a frame", "0\t0xA9B40031\t150.000\t1.000\t0.000\n# radius: 0.5\n", 2, "a header after the first frame" },
        { "bad frame header", "# frame: local\n", 1, "expected \"block\" or \"world\"" },
        { "negative radius header", "# radius: -0.5\n", 1, "radius must be ≥ 0" },
        { "bad body header", "# body: [{\"x\":0}]\n", 1, "# body[0]: expected" },
        { "negative radius column", "0\t0xA9B40031\t150.000\t1.000\t0.000\t-1\n", 1, "radius: radius must be ≥ 0" },
        { "block frame without a cell", "0\t-\t150.000\t1.000\t0.000\n", 1, "a block-frame position needs its cell" },
        { "bad candidate", "0\t0xA9B40031\t150.000\t1.000\t0.000\t-\t0xA9B40031,0xZZ\n", 1, "candidate 2: expected a cell id" },
        { "too many decimals", "0\t0xA9B40031\t150.0000000000001\t1.000\t0.000\n", 1, "x: expected a finite decimal number" },
    };

    public static TheoryData<string, string, int, string> HostileLogs => new()
    {
        { "count mismatch", "[cellset-build] seed=0xA9B40031 sphere=(1.000,2.000,0.000) count=3 ids=0xA9B40031,0xA9B30038\n", 1, "count=3 but 2 ids listed" },
        { "malformed transit", "log\n[cell-transit] 0xA9B40031 => 0xA9B30038 pos=(1.000,2.000,0.000) reason=x\n", 2, "expected [cell-transit]" },
        { "NaN position", "[cell-transit] 0xA9B40031 -> 0xA9B30038 pos=(NaN,2.000,0.000) reason=x\n", 1, "x: expected a finite decimal number" },
        { "two coordinates", "[cellset-build] seed=0xA9B40031 sphere=(1.000,2.000) count=0 ids=\n", 1, "expected three coordinates" },
        { "truncated probe line", "[cellset-build] seed=0xA9B40031 sphere=(1.000,2.000,0.000) count=1 ids=0xA9B4", 1, "truncated last line" },
    };

    [Theory(DisplayName = "CAPTURE-FORMAT: a hostile or malformed native capture is refused naming the file, the line and what was expected")]
    [MemberData(nameof(Hostile))]
    public void NativeRefused(string what, string text, int line, string expected)
    {
        var e = Assert.Throws<InputFormatException>(() => ReadAll(text, CaptureFormat.Native));
        Assert.StartsWith($"t.capture:{line}: ", e.Message, StringComparison.Ordinal);
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
        Assert.True(e.Message.Length < 400, what + ": " + e.Message.Length + " characters");
    }

    [Theory(DisplayName = "CAPTURE-FORMAT: a malformed acdream probe line is refused naming the file, the line and what was expected")]
    [MemberData(nameof(HostileLogs))]
    public void AcdreamRefused(string what, string text, int line, string expected)
    {
        var e = Assert.Throws<InputFormatException>(() => ReadAll(text, CaptureFormat.Acdream));
        Assert.StartsWith($"t.capture:{line}: ", e.Message, StringComparison.Ordinal);
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
        Assert.NotEmpty(what);
    }

    [Fact(DisplayName = "CAPTURE-FORMAT: the native reader reads every column, the headers and the decimals printed (CRLF too)")]
    public void NativeReadsTheDocumentedColumns()
    {
        const string Text = "# a comment\r\n# frame: world\r\n# body: [{\"x\":0,\"y\":0,\"z\":0.5,\"r\":0.5},{\"x\":0,\"y\":0,\"z\":1.2,\"r\":0.4}]\r\n\r\n7\t0xA9B40031\t32598.25\t34561\t-0.125\t0.48\t0xA9B40031,0xA9B30038\r\n9\t-\t32598.250\t34560.9\t0\t-\tnone\r\n";
        var frames = ReadAll(Text, CaptureFormat.Native, out var header, out long ignored);
        Assert.Equal(CaptureFrameKind.World, header.Frame);
        Assert.Equal(2, header.Body.Count);
        Assert.Equal(1.2f, header.Body[1].Offset.Z);
        Assert.Equal(4, ignored); // the comment, two headers and the blank line
        var (a, b) = (frames[0], frames[1]);
        Assert.Equal((7L, 5L, new CellId(0xA9B40031)), (a.Frame.Number, a.Frame.Line, a.Frame.Cell));
        Assert.Equal((32598.25, 34561.0, -0.125), (a.Frame.Position.X, a.Frame.Position.Y, a.Frame.Position.Z));
        Assert.Equal((2, 0, 3), (a.Frame.Position.DecimalsX, a.Frame.Position.DecimalsY, a.Frame.Position.DecimalsZ));
        Assert.Equal(0.48f, a.Frame.Radius);
        Assert.Equal([new CellId(0xA9B40031), new CellId(0xA9B30038)], a.Candidates);
        Assert.True(b.Frame.Cell.IsNone);
        Assert.True(float.IsNaN(b.Frame.Radius));
        Assert.True(b.Frame.HasCandidates);
        Assert.Empty(b.Candidates);
        Assert.Equal((0.005, 0.5, 0.0005), (a.Frame.Position.HalfX, a.Frame.Position.HalfY, b.Frame.Position.HalfX));
    }

    [Fact(DisplayName = "CAPTURE-FORMAT: the acdream importer pairs a cellset line with the transit of its frame, moves positions into the map's frame and counts other lines")]
    public void AcdreamPairsLines()
    {
        const string Text = "boot\n[cellset-build] seed=0xA9B40031 sphere=(150.000,0.100,0.000) count=2 ids=0xA9B40031,0xA9B30038\nnoise\n"
            + "[cellset-build] seed=0xA9B40031 sphere=(150.000,-0.100,0.000) count=2 ids=0xA9B30038,0xA9B40031\n"
            + "[cell-transit] 0xA9B40031 -> 0xA9B30038 pos=(150.000,-0.100,0.000) reason=moved\n"
            + "12:00:01 [cell-transit] 0xA9B30038 -> 0xA9B30030 pos=(140.500,-3.000,0.000) reason=moved\n";
        var frames = ReadAll(Text, CaptureFormat.Acdream, out var header, out long ignored);
        Assert.Equal(CaptureFrameKind.World, header.Frame);
        Assert.Equal(2, ignored);
        Assert.Equal(3, frames.Count);
        Assert.Equal((1L, 2L, new CellId(0xA9B40031), new CellId(0xA9B40031)), (frames[0].Frame.Number, frames[0].Frame.Line, frames[0].Frame.Before, frames[0].Frame.Cell)); // the next cellset's seed
        Assert.Equal((new CellId(0xA9B40031), new CellId(0xA9B30038)), (frames[1].Frame.Before, frames[1].Frame.Cell)); // its own frame's transit
        Assert.Equal([new CellId(0xA9B30038), new CellId(0xA9B40031)], frames[1].Candidates);
        Assert.Equal((new CellId(0xA9B30038), new CellId(0xA9B30030), false), (frames[2].Frame.Before, frames[2].Frame.Cell, frames[2].Frame.HasCandidates));
        Assert.Equal(((192.0 * 0xA9) + 150, (192.0 * 0xB4) - 0.1), (frames[1].Frame.Position.X, frames[1].Frame.Position.Y));
    }

    private static List<(CaptureFrame Frame, CellId[] Candidates)> ReadAll(string text, CaptureFormat format) => ReadAll(text, format, out _, out _);

    private static List<(CaptureFrame Frame, CellId[] Candidates)> ReadAll(string text, CaptureFormat format, out CaptureHeader header, out long ignored)
    {
        var bytes = Encoding.UTF8.GetBytes(text).Select(b => b).ToArray();
        bytes = Replace(bytes, Encoding.UTF8.GetBytes("\u00ff"), [0xFF]); // a raw 0xFF byte, not UTF-8
        using var reader = CaptureReaders.Open(new MemoryStream(bytes), "t.capture", format, new CaptureOptions(new LandblockId(0xA9B4), null));
        var frames = new List<(CaptureFrame, CellId[])>();
        while (reader.Read(out var f))
        {
            frames.Add((f, f.Candidates.ToArray()));
        }

        header = reader.Header;
        ignored = reader.Ignored;
        return frames;
    }

    private static byte[] Replace(byte[] bytes, byte[] what, byte[] with)
    {
        var list = new List<byte>(bytes.Length);
        for (int i = 0; i < bytes.Length; i++)
        {
            if (i + what.Length <= bytes.Length && bytes.AsSpan(i, what.Length).SequenceEqual(what))
            {
                list.AddRange(with);
                i += what.Length - 1;
            }
            else
            {
                list.Add(bytes[i]);
            }
        }

        return [.. list];
    }
}
