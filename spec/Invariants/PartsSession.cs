using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// How the parts invariants indoors ask a scene walk's parts queries (<see cref="ScenePartsQueries"/>) of one kind: query
/// by query through <see cref="ICellPhysics.FindCellParts"/>, or — when the implementation declares ace-keeps-stale-cells,
/// whose array lives for one walk (facts §4 step 1, §7 #6) — the whole walk at once through
/// <see cref="ICellPhysics.FindCellPartsWalk"/>, so the answers are the ones its walk gives.
/// </summary>
internal static class PartsSession
{
    /// <summary>Asks a walk's parts queries of one kind, in order (query by query lazily, or the walk at once under stale cells).</summary>
    /// <param name="impl">The implementation (or the reference in its declared mode).</param>
    /// <param name="w">The scene walk.</param>
    /// <param name="loadCells">True for the transition kind.</param>
    /// <returns>Each query with its answer and, under a declared ace-keeps-stale-cells, the cells of the previous answer.</returns>
    public static IEnumerable<PartsAnswer> Ask(ICellPhysics impl, SceneWalk w, bool loadCells)
    {
        var queries = ScenePartsQueries.Of(w);
        if (!impl.Indoor.AceKeepsStaleCells)
        {
            foreach (var (index, parts) in queries)
            {
                yield return new PartsAnswer(index, parts, impl.FindCellParts(w.Scene, parts, loadCells), null);
            }

            yield break;
        }

        var answers = impl.FindCellPartsWalk(w.Scene, [.. queries.Select(q => (IReadOnlyList<Part>)q.Parts)], loadCells);
        if (answers.Count != queries.Count)
        {
            throw new InvalidOperationException($"{impl.Name} answered {answers.Count} of the walk's {queries.Count} parts queries");
        }

        IReadOnlySet<CellId> previous = new HashSet<CellId>(); // the walk's array starts empty
        for (int i = 0; i < answers.Count; i++)
        {
            yield return new PartsAnswer(queries[i].Index, queries[i].Parts, answers[i], previous);
            previous = answers[i].Cells.ToHashSet();
        }
    }
}
