using System.Diagnostics.CodeAnalysis;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Cli.Diff;

/// <summary>
/// The answers of one implementation to one generated input, as comparable text: what <c>acphys diff</c> puts side by
/// side. Two implementations agree on an input when every op both offer gives the same text.
/// </summary>
internal static class Answers
{
    /// <summary>Returns each LandDefs op's answer to a land case, for the ops in <paramref name="ops"/>.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="c">The case.</param>
    /// <param name="ops">The ops to ask.</param>
    /// <returns>(op call, answer) pairs.</returns>
    public static IReadOnlyList<(string Call, string Answer)> Land(ICellPhysics impl, LandCase c, Op ops)
    {

        var rows = new List<(string, string)>();
        if ((ops & Op.BlockIdToLcoord) != 0)
        {
            rows.Add(($"blockid_to_lcoord({c.Cell})", Ask(() => Lcoord(impl.BlockIdToLcoord(c.Cell, out var lc), lc))));
        }

        if ((ops & Op.GidToLcoord) != 0)
        {
            rows.Add(($"gid_to_lcoord({c.Cell})", Ask(() => Lcoord(impl.GidToLcoord(c.Cell, out var lc), lc))));
        }

        if ((ops & Op.LcoordToGid) != 0)
        {
            rows.Add(($"lcoord_to_gid({c.Lcoord.X}, {c.Lcoord.Y})", Ask(() => impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y).ToString())));
        }

        if ((ops & Op.InboundValidCellId) != 0)
        {
            rows.Add(($"inbound_valid_cellid({c.Cell})", Ask(() => impl.InboundValidCellId(c.Cell) ? "true" : "false")));
        }

        string point = $"{c.Cell}, {Float(c.X)}, {Float(c.Y)}";
        if ((ops & Op.GetOutsideLcoord) != 0)
        {
            rows.Add(($"get_outside_lcoord({point})", Ask(() => Lcoord(impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var lc), lc))));
        }

        if ((ops & Op.AdjustToOutside) != 0)
        {
            rows.Add(($"adjust_to_outside({point})", Ask(() =>
            {
                var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
                return r.Ok ? $"ok {r.Cell} ({Float(r.X)}, {Float(r.Y)})" : "fail";
            })));
        }

        return rows;
    }

    /// <summary>The start of the answer text of a call that threw.</summary>
    public const string Threw = "threw ";

    /// <summary>
    /// Asks one question; an exception other than <see cref="AdapterFailureException"/> (the implementation could not
    /// answer at all) is itself an answer, "threw TYPE", that differs from every real one.
    /// </summary>
    /// <param name="ask">The question.</param>
    /// <param name="answer">The answer, when it came.</param>
    /// <param name="threw">"threw TYPE", when it did not.</param>
    /// <typeparam name="T">The answer's type.</typeparam>
    /// <returns>True when it answered.</returns>
    public static bool TryAsk<T>(Func<T> ask, [NotNullWhen(true)] out T? answer, [NotNullWhen(false)] out string? threw)
    {
        try
        {
            answer = ask()!;
            threw = null;
            return true;
        }
        catch (AdapterFailureException)
        {
            throw;
        }
        catch (Exception e)
        {
            answer = default;
            threw = Threw + e.GetType().Name;
            return false;
        }
    }

    /// <summary>Asks one question whose answer is text; a throw answers "threw TYPE" (<see cref="TryAsk"/>).</summary>
    /// <param name="ask">The question.</param>
    /// <returns>The answer.</returns>
    public static string Ask(Func<string> ask) => TryAsk(ask, out string? text, out string? threw) ? text : threw;

    /// <summary>Formats a list of cells and an optional containing cell.</summary>
    /// <param name="cells">The cells, in insertion order.</param>
    /// <param name="containing">The containing cell, or null when the op has none.</param>
    /// <returns>The text.</returns>
    public static string Cells(IReadOnlyList<CellId> cells, CellId? containing = null) =>
        $"[{string.Join(", ", cells)}]" + (containing is CellId c ? $" containing {(c.IsNone ? "none" : c.ToString())}" : string.Empty);

    /// <summary>Formats a float so that equal values (0 and −0 included) print alike.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The text.</returns>
    public static string Float(float v) => v == 0 ? "0" : FloatText.Format(v);

    private static string Lcoord(bool ok, Lcoord lc) => ok ? $"ok ({lc.X}, {lc.Y})" : "fail";
}
