using System.Text.Json;
using AcPhys.Core;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Protocol;

/// <summary>
/// The answer line a conforming child writes for a guessed answer, byte for byte as <c>acphys serve</c> writes it
/// (ProtocolServer). The pipelined transport compares a child's answer with this line first: equal text reads as the
/// guess (the reader of each shape reads back exactly what was written: <c>ANSWER-LINE-READS-BACK</c>), so the answer
/// need not be parsed; any other text is parsed and compared by value as before (issue 26: parsing every answer was
/// 17 µs of the reader thread's time per answer).
/// </summary>
internal static class ExpectedAnswer
{
    /// <summary>Writes the answer line of a guessed answer.</summary>
    /// <param name="guess">The guess: an answer as the tool's calls return it.</param>
    /// <returns>The line, or null for a shape without a canonical line (it is then compared by value only).</returns>
    /// <remarks>Only where reading the line gives the guess back exactly: a NaN reads back as the one NaN the reader
    /// makes, whatever its payload was, and a <c>loaded</c> not parallel to <c>cells</c> is refused by the reader, so such
    /// guesses get no line.</remarks>
    public static string? Line(object? guess) => Fields(guess) is { } fields ? Wire.Line(fields) : null;

    /// <summary>Whether <paramref name="answer"/> is the expected line of <paramref name="guess"/>, byte for byte.</summary>
    /// <param name="answer">The child's answer line, its UTF-8 bytes.</param>
    /// <param name="guess">The guess.</param>
    /// <returns>True when the bytes are the same; false says nothing (compare by value).</returns>
    public static bool Is(ReadOnlySpan<byte> answer, object? guess) => guess switch
    {
        // The two big shapes are matched character by character against the text Wire.WriteFindCell writes, with no
        // line written (issue 26: writing a walk's answer to compare it was half the reader thread's time).
        FindCellResult r => Parallel(r) && new Match(answer).FindCellObject(r).AtEnd,
        IReadOnlyList<FindCellResult> walk => walk.All(Parallel) && new Match(answer).Walk(walk).AtEnd,
        _ => Fields(guess) is { } fields && Wire.LineIs(answer, fields),
    };

    // The fields of the guess's line, or null where reading it back would not give the guess (see Line).
    private static Action<Utf8JsonWriter>? Fields(object? guess) => guess switch
    {
        FindCellResult r => Parallel(r) ? w => Wire.WriteFindCell(w, r) : null,
        IReadOnlyList<FindCellResult> walk => walk.All(Parallel) ? w => WalkWire.WriteAnswer(w, walk) : null,
        IReadOnlyList<CellId> cells => w => Wire.WriteCells(w, "cells", cells),
        AdjustResult a => float.IsNaN(a.X) || float.IsNaN(a.Y) ? null : w => Adjust(w, a),
        ValueTuple<bool, int, int> lcoord => w => Lcoord(w, lcoord),
        CellId id => w => Wire.WriteCell(w, "cell", id),
        bool ok => w => w.WriteBoolean("ok", ok), // inbound_valid_cellid, unload_scene
        string sceneId => w => w.WriteString("scene_id", sceneId), // load_scene
        _ => null,
    };

    private static bool Parallel(FindCellResult r) => r.Loaded is null || r.Loaded.Count == r.Cells.Count;

    private static void Adjust(Utf8JsonWriter w, AdjustResult a)
    {
        w.WriteBoolean("ok", a.Ok);
        Wire.WriteCell(w, "cell", a.Cell);
        Wire.WriteFloat(w, "x", a.X);
        Wire.WriteFloat(w, "y", a.Y);
    }

    private static void Lcoord(Utf8JsonWriter w, (bool Ok, int X, int Y) l)
    {
        w.WriteBoolean("ok", l.Ok);
        w.WriteNumber("x", l.X);
        w.WriteNumber("y", l.Y);
    }

    // A cursor over an answer line that consumes the expected text piece by piece; after the first difference every
    // step fails (Ok false), so a chain of steps needs no checks in between.
    private ref struct Match(ReadOnlySpan<byte> text)
    {
        private readonly ReadOnlySpan<byte> text = text;
        private int at;
        private bool ok = true;

        public readonly bool AtEnd => ok && at == text.Length;

        public Match Walk(IReadOnlyList<FindCellResult> steps)
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

        public Match FindCellObject(FindCellResult r)
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
}
