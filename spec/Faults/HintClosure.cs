namespace AcPhys.Spec.Faults;

/// <summary>
/// What a port's transit closure does at a load hint (facts §4 step 4a: skip the null entry, walk on, bound = the
/// count re-read each time), with issue 27's defects: stop there, skip the next entry too, or shrink the bound.
/// </summary>
internal static class HintClosure
{
    /// <summary>Returns the closure's loop bound.</summary>
    /// <param name="count">The array's current count.</param>
    /// <param name="hints">Load hints met so far.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>The bound.</returns>
    public static int Bound(int count, int hints, IndoorDefect defect) => defect == IndoorDefect.ClosureBoundMinusHints ? count - hints : count;

    /// <summary>Handles a load hint at index i: true to stop the closure.</summary>
    /// <param name="i">The loop index (the skip-after defect advances it once more).</param>
    /// <param name="hints">Load hints met so far.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>Whether the closure stops here.</returns>
    public static bool StopsAt(ref int i, ref int hints, IndoorDefect defect)
    {
        hints++;
        if (defect == IndoorDefect.ClosureSkipsAfterHint)
        {
            i++;
        }

        return defect == IndoorDefect.ClosureBreaksAtHint;
    }
}
