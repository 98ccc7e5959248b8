using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Pipeline;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Protocol;

/// <summary>
/// ANSWER-LINE-READS-BACK: the line the pipelined transport expects for a guess (each shape of the message table,
/// <see cref="Answers"/>, issue 42) reads back, through the readers the
/// tool applies to a child's answer, as exactly that guess (issue 26). The transport accepts an answer whose text is
/// that line without parsing it, so this is what makes the shortcut the same as the comparison by value.
/// </summary>
public sealed class AnswerLineReadsBack
{
    private static readonly Gen<CellId> Cells = Gen.OneOf(
        Gen.Choose(0, int.MaxValue).Select(v => new CellId((uint)v * 2u + 1u)),
        Gen.Elements(0x00000000u, 0xFFFFFFFFu, 0xA9B40017u, 0x0000FFFFu, 0x01D90100u).Select(v => new CellId(v)));

    private static readonly Gen<FindCellResult> FindCells =
        from cells in Gen.ListOf(Cells).Select(l => l.Take(9).ToArray())
        from containing in Cells
        from loaded in Gen.OneOf(Gen.Constant<bool[]?>(null), Gen.ArrayOf(ArbMap.Default.GeneratorFor<bool>(), cells.Length).Select(a => (bool[]?)a))
        from hits in Gen.Elements<bool?>(null, true, false)
        select new FindCellResult(cells, containing) { Loaded = loaded, HitsInteriorCell = hits };

    private static readonly Gen<float> Floats = Gen.OneOf(
        Gen.Choose(int.MinValue, int.MaxValue).Select(BitConverter.Int32BitsToSingle),
        Gen.Elements(0f, -0f, float.Epsilon, -float.Epsilon, float.MaxValue, float.MinValue, float.PositiveInfinity, float.NegativeInfinity, float.NaN, 1e-45f, 191.99998f, 192f));

    [CiProperty(MaxTest = 3000, DisplayName = "ANSWER-LINE-READS-BACK: a find_cell guess's expected line reads back as the same answer (cells, containing, loaded, hits_interior_cell)")]
    public Property FindCellReadsBack() =>
        Prop.ForAll(FindCells.ToArbitrary(), r =>
            Same(Answers.FindCell, r)
                .Classify(r.Loaded is null, "no loaded")
                .Classify(r.HitsInteriorCell is null, "no hits_interior_cell")
                .Classify(r.Cells.Count == 0, "no cells"));

    [CiProperty(MaxTest = 1000, DisplayName = "ANSWER-LINE-READS-BACK: a find_cell_walk guess's expected line reads back as the same answers, one per query")]
    public Property WalkReadsBack() =>
        Prop.ForAll(Gen.ListOf(FindCells).Select(l => l.Take(6).ToArray()).ToArbitrary(), walk =>
            Same(Answers.Walk(walk.Length), (IReadOnlyList<FindCellResult>)walk)
                .Classify(walk.Length == 0, "empty walk"));

    [CiProperty(MaxTest = 3000, DisplayName = "ANSWER-LINE-READS-BACK: an adjust_to_outside guess reads back bit for bit (-0, subnormals, infinities); a NaN gets no expected line")]
    public Property AdjustReadsBack() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(ArbMap.Default.GeneratorFor<bool>(), Cells), Gen.Zip(Floats, Floats)).ToArbitrary(), t =>
        {
            var r = new AdjustResult(t.Item1.Item1, t.Item1.Item2, t.Item2.Item1, t.Item2.Item2);
            bool nan = float.IsNaN(r.X) || float.IsNaN(r.Y);
            string? line = Answers.Adjust.ExpectedLine(r);
            return (nan ? line is null : Same(Answers.Adjust, r))
                .Classify(nan, "NaN: compared by value");
        });

    [CiProperty(MaxTest = 2000, DisplayName = "ANSWER-LINE-READS-BACK: lcoord, cell, cell-list, ok and scene_id guesses read back as themselves")]
    public Property SmallAnswersReadBack() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(Cells, Gen.Choose(-5000, 5000)), Gen.Zip(ArbMap.Default.GeneratorFor<bool>(), Gen.ListOf(Cells).Select(l => l.Take(12).ToArray()))).ToArbitrary(), t =>
        {
            var (cell, n) = t.Item1;
            var (ok, cells) = t.Item2;
            var lcoord = (ok, n, -n);
            string id = "t" + n.ToString(System.Globalization.CultureInfo.InvariantCulture) + (ok ? "\"\\é" : string.Empty);
            return Same(Answers.Lcoord, lcoord)
                && Same(Answers.Cell, cell)
                && Answers.Cell.ExpectedLine(cell) == "{\"cell\":\"" + AcPhys.Core.Text.CellIdText.Format(cell) + "\"}" // the text cell ids have everywhere
                && Same(Answers.Cells, (IReadOnlyList<CellId>)cells)
                && Same(Answers.Ok, ok)
                && Same(Answers.SceneId, id);
        });

    [CiProperty(MaxTest = 3000, DisplayName = "ANSWER-LINE-READS-BACK: the character matcher accepts an answer exactly when it is the guess's written line (pairs of find_cell answers and walks, and one-character edits)")]
    public Property MatcherIsTheWrittenLine() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(FindCells, FindCells), Gen.Zip(Gen.Choose(0, 1000), Gen.Elements('0', 'F', 'f', '"', ',', 'x', ' '))).ToArbitrary(), t =>
        {
            var ((a, b), (at, c)) = t;
            string la = Answers.FindCell.ExpectedLine(a)!, lb = Answers.FindCell.ExpectedLine(b)!;
            var edited = la.ToCharArray();
            edited[at % edited.Length] = c;
            string le = new(edited);
            IReadOnlyList<FindCellResult> walk = [a, b], other = [b, a];
            string lw = Answers.Walk(2).ExpectedLine(walk)!, lo = Answers.Walk(2).ExpectedLine(other)!;
            return (Is(Answers.FindCell, la, a) && Is(Answers.FindCell, lb, b) && Is(Answers.Walk(2), lw, walk)
                    && Is(Answers.FindCell, lb, a) == (lb == la)
                    && Is(Answers.FindCell, le, a) == (le == la)
                    && Is(Answers.Walk(2), lo, walk) == (lo == lw)
                    && !Is(Answers.FindCell, la + " ", a) && !Is(Answers.FindCell, la[..^1], a))
                .Classify(lb == la, "same answer drawn twice")
                .Classify(le == la, "edit left the line as it was");
        });

    [Fact(DisplayName = "ANSWER-LINE-READS-BACK: a find_cell guess whose loaded is not parallel to its cells gets no expected line (the reader refuses that answer)")]
    public void UnparallelLoadedHasNoLine()
    {
        var r = new FindCellResult([new CellId(0xA9B40017u)], CellId.None) { Loaded = [true, false] };
        Assert.Null(Answers.FindCell.ExpectedLine(r));
        Assert.NotNull(Answers.FindCell.ExpectedLine(r with { Loaded = [true] }));
    }

    // The shape's expected line is read as the transport reads an answer (Wire.Parse, strict, then the shape's own
    // read), compared as the slow path compares, and matched by the shape's own match: write, read and match agree.
    private static bool Same<T>(Answer<T> shape, T guess)
    {
        if (shape.ExpectedLine(guess) is not { } line)
        {
            return false;
        }

        using var doc = Wire.Parse(line);
        return SameAnswer.Of(shape.Read(doc.RootElement), guess) && Is(shape, line, guess);
    }

    // The transport compares the answer's UTF-8 bytes.
    private static bool Is<T>(Answer<T> shape, string line, T guess) => shape.Is(System.Text.Encoding.UTF8.GetBytes(line), guess);
}
