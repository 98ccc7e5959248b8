using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Capture;

/// <summary>
/// Imports the probe lines of an acdream-family client (<c>ACDREAM_PROBE_CELL=1</c>, <c>ACDREAM_PROBE_CELLSET=1</c>), as
/// printed, into frames: <c>[cell-transit] 0xOLD -&gt; 0xNEW pos=(x,y,z) reason=R</c> and
/// <c>[cellset-build] seed=0xSEED sphere=(x,y,z) count=N ids=0x…,0x…</c>, positions in the client's world frame whose
/// origin (0, 0) is the south-west corner of the landblock <c>--world-origin</c> names. Every other line is ignored and counted.
/// </summary>
/// <remarks>
/// A cellset line is the query of one frame: the seed is the cell the port asked from (its cell before the frame), the
/// ids its candidates. The cell after that frame is the next line's: a transit at the same position names it (new), else
/// the next cellset line's seed; after the last cellset line it is unknown (the frame judges its candidates only). A
/// transit line on its own is a frame whose cell changed from old to new (docs/ports.md, "Your own sessions").
/// </remarks>
internal sealed class AcdreamCaptureReader : CaptureLineReader
{
    private static readonly byte[] Transit = "[cell-transit]"u8.ToArray();
    private static readonly byte[] Cellset = "[cellset-build]"u8.ToArray();

    private readonly double originX;
    private readonly double originY;
    private readonly CellId[][] buffers = [new CellId[CaptureText.MaxCandidates], new CellId[CaptureText.MaxCandidates]];
    private readonly Queue<CaptureFrame> ready = new(2);
    private int spare;
    private CaptureFrame? pending;
    private long ordinal;

    /// <summary>Initializes a new instance of the <see cref="AcdreamCaptureReader"/> class.</summary>
    /// <param name="stream">The log (owned).</param>
    /// <param name="source">The file name for messages.</param>
    /// <param name="origin">The landblock whose south-west corner is the client's world (0, 0).</param>
    /// <param name="radius">The body's radius (<c>--radius</c>), or null: the lines name none.</param>
    public AcdreamCaptureReader(Stream stream, string source, LandblockId origin, float? radius)
        : base(stream, source)
    {
        originX = LandDefs.BlockLength * (double)(origin.Value >> 8);
        originY = LandDefs.BlockLength * (double)(origin.Value & 0xFF);
        Header = new CaptureHeader(CaptureFrameKind.World, radius is { } r ? [new BodySphere(default, r)] : []);
    }

    /// <inheritdoc/>
    public override CaptureHeader Header { get; }

    /// <inheritdoc/>
    public override bool Read(out CaptureFrame frame)
    {
        while (ready.Count == 0)
        {
            if (!LineSource.Next(out var line))
            {
                if (pending is { } last)
                {
                    pending = null;
                    ready.Enqueue(last); // its cell after the frame is unknown: candidates only
                    break;
                }

                frame = default;
                return false;
            }

            int t = line.IndexOf(Transit);
            int c = t >= 0 ? -1 : line.IndexOf(Cellset);
            if (t < 0 && c < 0)
            {
                Ignored++;
                continue;
            }

            if (LineSource.Unterminated)
            {
                throw LineSource.Error(LineSource.Number, "truncated last line: a probe line with no line end (was the log cut off while it was written?)");
            }

            if (t >= 0)
            {
                OnTransit(line[(t + Transit.Length)..]);
            }
            else
            {
                OnCellset(line[(c + Cellset.Length)..]);
            }
        }

        frame = ready.Dequeue();
        return true;
    }

    private void OnTransit(ReadOnlySpan<byte> s)
    {
        const string Expected = "[cell-transit] 0xOLD -> 0xNEW pos=(x,y,z) reason=R";
        s = s.TrimStart((byte)' ');
        if (s.Length < 24 || !CaptureText.TryCell(s[..10], out var old) || !s[10..].StartsWith(" -> "u8) || !CaptureText.TryCell(s[14..24], out var now))
        {
            throw LineSource.Error(LineSource.Number, $"expected {Expected}, got \"{CaptureText.Quote(s)}\"");
        }

        var p = Point(s[24..].TrimStart((byte)' '), "pos="u8, Expected, out _);
        if (pending is { } q)
        {
            pending = null;
            if (q.Position.X == p.X && q.Position.Y == p.Y && q.Before == old)
            {
                ready.Enqueue(q with { Cell = now }); // the transit of the cellset's own frame
                return;
            }

            ready.Enqueue(q); // its cell after the frame is unknown: candidates only
        }

        ready.Enqueue(new CaptureFrame(++ordinal, LineSource.Number, now, p, float.NaN) { Before = old });
    }

    private void OnCellset(ReadOnlySpan<byte> s)
    {
        const string Expected = "[cellset-build] seed=0xSEED sphere=(x,y,z) count=N ids=0x…,0x…";
        s = s.TrimStart((byte)' ');
        if (!s.StartsWith("seed="u8) || s.Length < 15 || !CaptureText.TryCell(s[5..15], out var seed))
        {
            throw LineSource.Error(LineSource.Number, $"expected {Expected}, got \"{CaptureText.Quote(s)}\"");
        }

        var p = Point(s[15..].TrimStart((byte)' '), "sphere="u8, Expected, out var rest);
        rest = rest.TrimStart((byte)' ');
        int space = rest.IndexOf((byte)' ');
        if (!rest.StartsWith("count="u8) || space < 0
            || !System.Buffers.Text.Utf8Parser.TryParse(rest[6..space], out int count, out int used) || used != space - 6 || count < 0)
        {
            throw LineSource.Error(LineSource.Number, $"count: expected count=N (an integer ≥ 0) in {Expected}, got \"{CaptureText.Quote(rest)}\"");
        }

        var ids = rest[(space + 1)..].TrimEnd((byte)' ');
        if (!ids.StartsWith("ids="u8))
        {
            throw LineSource.Error(LineSource.Number, $"ids: expected ids=0x…,0x… in {Expected}, got \"{CaptureText.Quote(ids)}\"");
        }

        var buffer = buffers[spare];
        if (CaptureText.TryCells(ids[4..], buffer, out int n) is { } problem)
        {
            throw LineSource.Error(LineSource.Number, "ids: " + problem);
        }

        if (n != count)
        {
            throw LineSource.Error(LineSource.Number, $"count={count} but {n} id{(n == 1 ? string.Empty : "s")} listed: expected as many ids as the count");
        }

        if (pending is { } q)
        {
            ready.Enqueue(q with { Cell = seed }); // the port asked this frame from the cell the previous one left it in
        }

        spare ^= 1;
        pending = new CaptureFrame(++ordinal, LineSource.Number, CellId.None, p, float.NaN) { Before = seed, HasCandidates = true, Candidates = buffer.AsMemory(0, n) };
    }

    // "name(x,y,z)" then the rest; x, y moved from the client's world frame into the map's.
    private PrintedPoint Point(ReadOnlySpan<byte> s, ReadOnlySpan<byte> name, string expected, out ReadOnlySpan<byte> rest)
    {
        int close = s.IndexOf((byte)')');
        if (!s.StartsWith(name) || s.Length <= name.Length || s[name.Length] != (byte)'(' || close < 0)
        {
            throw LineSource.Error(LineSource.Number, $"expected {expected}, got \"{CaptureText.Quote(s)}\"");
        }

        var inner = s[(name.Length + 1)..close];
        Span<Range> f = stackalloc Range[4];
        if (CaptureText.Split(inner, f, (byte)',') != 3)
        {
            throw LineSource.Error(LineSource.Number, $"{System.Text.Encoding.ASCII.GetString(name)}: expected three coordinates (x,y,z), got \"{CaptureText.Quote(inner)}\"");
        }

        rest = s[(close + 1)..];
        var x = Coordinate(inner[f[0]], "x");
        var y = Coordinate(inner[f[1]], "y");
        var z = Coordinate(inner[f[2]], "z");
        return new PrintedPoint(x.V + originX, y.V + originY, z.V, x.D, y.D, z.D);
    }

    private (double V, byte D) Coordinate(ReadOnlySpan<byte> field, string name) =>
        CaptureText.TryNumber(field, out double v, out byte d)
            ? (v, d)
            : throw LineSource.Error(LineSource.Number, $"{name}: expected {CaptureText.NumberExpected}, got \"{CaptureText.Quote(field)}\"");
}
