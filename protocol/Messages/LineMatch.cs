using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// A cursor over an answer line that consumes the expected text piece by piece; after the first difference every
/// step fails, so a chain of steps needs no checks in between: the find_cell and walk answers' match without writing
/// their line (issue 26: writing a walk's answer to compare it was half the reader thread's time).
/// </summary>
/// <param name="text">The answer line's UTF-8 bytes.</param>
internal ref struct LineMatch(ReadOnlySpan<byte> text)
{
    private readonly ReadOnlySpan<byte> text = text;
    private int at;
    private bool ok = true;

    public readonly bool AtEnd => ok && at == text.Length;

    public LineMatch Walk(IReadOnlyList<FindCellResult> steps)
    {
        Lit("{\"steps\":["u8);
        for (int i = 0; i < steps.Count && ok; i++)
        {
            if (i > 0)
            {
                Lit(","u8);
            }

            FindCellObject(steps[i]);
        }

        Lit("]}"u8);
        return this;
    }

    public LineMatch FindCellObject(FindCellResult r)
    {
        Lit("{\"cells\":["u8);
        for (int i = 0; i < r.Cells.Count && ok; i++)
        {
            if (i > 0)
            {
                Lit(","u8);
            }

            Cell(r.Cells[i]);
        }

        Lit("],\"containing\":"u8);
        if (r.Containing.IsNone)
        {
            Lit("null"u8);
        }
        else
        {
            Cell(r.Containing);
        }

        if (r.Loaded is { } loaded)
        {
            Lit(",\"loaded\":["u8);
            for (int i = 0; i < loaded.Count && ok; i++)
            {
                if (i > 0)
                {
                    Lit(","u8);
                }

                Lit(loaded[i] ? "true"u8 : "false"u8);
            }

            Lit("]"u8);
        }

        if (r.HitsInteriorCell is bool hits)
        {
            Lit(hits ? ",\"hits_interior_cell\":true"u8 : ",\"hits_interior_cell\":false"u8);
        }

        Lit("}"u8);
        return this;
    }

    private void Lit(ReadOnlySpan<byte> expected)
    {
        ok = ok && text[at..].StartsWith(expected);
        at += ok ? expected.Length : 0;
    }

    // A cell id as Wire writes it (Wire.CellText), quoted.
    private void Cell(CellId id)
    {
        Span<byte> cell = stackalloc byte[Wire.CellTextBytes];
        var expected = Wire.CellText(id, cell);
        ok = ok && text.Length - at >= expected.Length + 2 && text[at] == (byte)'"' && text[at + expected.Length + 1] == (byte)'"'
            && expected.SequenceEqual(text.Slice(at + 1, expected.Length));
        at += ok ? expected.Length + 2 : 0;
    }
}
