using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The reference's trace of one scene walk, kept while the walk lives (issue 51): every scene judge of a case runs the
/// same walk, so a fuzz input or a replayed case judged by twenty invariants asked the reference twenty times for the
/// same answers. Only the reference is remembered — deterministic, and without state between walks unless it keeps
/// stale cells (facts §7 #6) — so a port or a planted fault is still asked every time, and a stateful one still shows
/// its state.
/// </summary>
internal static class SceneWalkMemo
{
    private static readonly ConditionalWeakTable<SceneWalk, List<(ReferenceAdapter Impl, bool LoadCells, IReadOnlyList<WalkStep> Trace)>> Traces = [];

    /// <summary>Returns the trace of a walk: remembered for the reference, run afresh for any other implementation.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="sw">The scene walk.</param>
    /// <param name="loadCells">The kind of scene query.</param>
    /// <param name="run">Runs the walk.</param>
    /// <returns>The trace.</returns>
    public static IReadOnlyList<WalkStep> Of(ICellPhysics impl, SceneWalk sw, bool loadCells, Func<IReadOnlyList<WalkStep>> run)
    {
        if (impl is not ReferenceAdapter reference || reference.Indoor.AceKeepsStaleCells)
        {
            return run();
        }

        var traces = Traces.GetValue(sw, _ => []);
        lock (traces)
        {
            foreach (var (i, l, t) in traces)
            {
                if (ReferenceEquals(i, reference) && l == loadCells)
                {
                    return t;
                }
            }
        }

        var trace = run();
        lock (traces)
        {
            traces.Add((reference, loadCells, trace));
        }

        return trace;
    }
}
