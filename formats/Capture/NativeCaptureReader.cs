using AcPhys.Core;

namespace AcPhys.Formats.Capture;

/// <summary>
/// Reads the native capture format (docs/corpus-format.md, "Captures"): one frame a line,
/// <c>frame TAB cell TAB x TAB y TAB z [TAB radius] [TAB candidates]</c>; <c>#</c> lines are comments, and before the first
/// frame the headers <c># frame: block|world</c>, <c># radius: r</c> and <c># body: [...]</c>. Streamed: one line in memory.
/// </summary>
internal sealed class NativeCaptureReader : CaptureLineReader
{
    private const string FrameExpected = "expected a frame: frame, cell, x, y, z [, radius] [, candidates], tab-separated";

    private readonly CellId[] candidates = new CellId[CaptureText.MaxCandidates];
    private long lastNumber = -1;
    private bool first;
    private CaptureFrame firstFrame;
    private CaptureFrameKind kind;

    /// <summary>Initializes a new instance of the <see cref="NativeCaptureReader"/> class and reads the header.</summary>
    /// <param name="stream">The input (owned).</param>
    /// <param name="source">The file name for messages.</param>
    /// <exception cref="InputFormatException">A malformed header or first frame.</exception>
    public NativeCaptureReader(Stream stream, string source)
        : base(stream, source)
    {
        var frame = CaptureFrameKind.Block;
        IReadOnlyList<AcPhys.Formats.Cases.BodySphere> body = [];
        try
        {
            while (LineSource.Next(out var line))
            {
                if (line.IsEmpty || line[0] == (byte)'#')
                {
                    Ignored++;
                    if (HeaderValue(line, "frame"u8, out var v))
                    {
                        frame = v.SequenceEqual("block"u8) ? CaptureFrameKind.Block
                            : v.SequenceEqual("world"u8) ? CaptureFrameKind.World
                            : throw LineSource.Error(LineSource.Number, $"# frame: expected \"block\" or \"world\", got \"{CaptureText.Quote(v)}\"");
                    }
                    else if (HeaderValue(line, "radius"u8, out v))
                    {
                        body = CaptureBodyHeader.Radius(v, out string? problem);
                        Refuse(problem);
                    }
                    else if (HeaderValue(line, "body"u8, out v))
                    {
                        body = CaptureBodyHeader.Body(v, out string? problem);
                        Refuse(problem);
                    }

                    continue;
                }

                kind = frame;
                firstFrame = Parse(line);
                first = true;
                break;
            }
        }
        catch
        {
            LineSource.Dispose();
            throw;
        }

        Header = new CaptureHeader(frame, body);
    }

    /// <inheritdoc/>
    public override CaptureHeader Header { get; }

    /// <inheritdoc/>
    public override bool Read(out CaptureFrame frame)
    {
        if (first)
        {
            first = false;
            frame = firstFrame;
            return true;
        }

        while (LineSource.Next(out var line))
        {
            if (line.IsEmpty || line[0] == (byte)'#')
            {
                Ignored++;
                if (HeaderValue(line, "frame"u8, out _) || HeaderValue(line, "radius"u8, out _) || HeaderValue(line, "body"u8, out _))
                {
                    throw LineSource.Error(LineSource.Number, "a header after the first frame (headers # frame:, # radius:, # body: come before every frame)");
                }

                continue;
            }

            frame = Parse(line);
            return true;
        }

        frame = default;
        return false;
    }

    // "# key: value" (spaces around the colon allowed).
    private static bool HeaderValue(ReadOnlySpan<byte> line, ReadOnlySpan<byte> key, out ReadOnlySpan<byte> value)
    {
        value = default;
        if (line.IsEmpty)
        {
            return false;
        }

        var rest = line[1..].TrimStart((byte)' ');
        if (!rest.StartsWith(key))
        {
            return false;
        }

        rest = rest[key.Length..].TrimStart((byte)' ');
        if (rest.IsEmpty || rest[0] != (byte)':')
        {
            return false;
        }

        value = rest[1..].Trim((byte)' ');
        return true;
    }

    private void Refuse(string? problem)
    {
        if (problem is not null)
        {
            throw LineSource.Error(LineSource.Number, problem);
        }
    }

    private CaptureFrame Parse(ReadOnlySpan<byte> line)
    {
        long at = LineSource.Number;
        if (LineSource.Unterminated)
        {
            throw LineSource.Error(at, "truncated last line: no line end (was the capture cut off while it was written?)");
        }

        Span<Range> f = stackalloc Range[8];
        int n = CaptureText.Split(line, f, (byte)'\t');
        if (n < 5 || n > 7)
        {
            throw LineSource.Error(at, $"{FrameExpected}; got {n} field{(n == 1 ? string.Empty : "s")}");
        }

        var number = line[f[0]];
        if (!System.Buffers.Text.Utf8Parser.TryParse(number, out long frame, out int used) || used != number.Length || frame < 0)
        {
            throw LineSource.Error(at, $"frame: expected a frame number (an integer ≥ 0), got \"{CaptureText.Quote(number)}\"");
        }

        if (frame <= lastNumber)
        {
            throw LineSource.Error(at, $"frame {frame} after frame {lastNumber}: expected frame numbers that increase");
        }

        lastNumber = frame;
        var cellText = line[f[1]];
        CellId cell = CellId.None;
        if (!(cellText.SequenceEqual("-"u8) || CaptureText.TryCell(cellText, out cell)))
        {
            throw LineSource.Error(at, $"cell: expected {CaptureText.CellExpected} (or - when the port reported none), got \"{CaptureText.Quote(cellText)}\"");
        }

        if (cell.IsNone && kind == CaptureFrameKind.Block)
        {
            throw LineSource.Error(at, "cell: a block-frame position needs its cell (- and 0x00000000 are allowed only with # frame: world)");
        }

        var p = new PrintedPoint(Coordinate(line[f[2]], "x", at, out byte dx), Coordinate(line[f[3]], "y", at, out byte dy), Coordinate(line[f[4]], "z", at, out byte dz), dx, dy, dz);
        float radius = float.NaN;
        if (n >= 6 && !line[f[5]].SequenceEqual("-"u8))
        {
            double r = Coordinate(line[f[5]], "radius", at, out _);
            if (AcPhys.Formats.Values.SphereRadius.Problem((float)r) is { } bad)
            {
                throw LineSource.Error(at, "radius: " + bad);
            }

            radius = (float)r;
        }

        var result = new CaptureFrame(frame, at, cell, p, radius);
        if (n == 7 && !line[f[6]].SequenceEqual("-"u8))
        {
            var list = line[f[6]];
            int count = 0;
            if (!list.SequenceEqual("none"u8) && CaptureText.TryCells(list, candidates, out count) is { } problem)
            {
                throw LineSource.Error(at, "candidates: " + problem + " (expected ids separated by commas, \"none\" for an empty list, or -)");
            }

            result = result with { HasCandidates = true, Candidates = candidates.AsMemory(0, count) };
        }

        return result;
    }

    private double Coordinate(ReadOnlySpan<byte> field, string name, long at, out byte decimals) =>
        CaptureText.TryNumber(field, out double v, out decimals)
            ? v
            : throw LineSource.Error(at, $"{name}: expected {CaptureText.NumberExpected}, got \"{CaptureText.Quote(field)}\"");
}
