namespace AcPhys.Spec.Generators;

/// <summary>
/// The one hand-written shrink loop (FsCheck shrinks the properties' own failures): greedily as FsCheck does, take the
/// first simpler candidate that still fails and start again from it, until none does or the budget of candidates is
/// spent. Deterministic: a shrinker gives its candidates in a fixed order. Used by <c>acphys diff</c> (a divergence
/// class) and the fuzz targets (a finding's invariant).
/// </summary>
public static class GreedyShrink
{
    /// <summary>Shrinks a failing case.</summary>
    /// <typeparam name="T">The case type.</typeparam>
    /// <param name="start">The failing case.</param>
    /// <param name="candidates">The shrinker: simpler candidates of a case.</param>
    /// <param name="stillFails">Whether a candidate still fails the same way (the caller keeps what it learns of the last one that did).</param>
    /// <param name="budget">Most candidates tried in all.</param>
    /// <returns>The simplest failing case found (<paramref name="start"/> when no candidate fails).</returns>
    public static T Run<T>(T start, Func<T, IEnumerable<T>> candidates, Func<T, bool> stillFails, int budget)
    {
        ArgumentNullException.ThrowIfNull(candidates);
        ArgumentNullException.ThrowIfNull(stillFails);
        var current = start;
        int spent = 0;
        bool progressed = true;
        while (progressed && spent < budget)
        {
            progressed = false;
            foreach (var candidate in candidates(current))
            {
                if (++spent > budget)
                {
                    break;
                }

                if (stillFails(candidate))
                {
                    (current, progressed) = (candidate, true);
                    break;
                }
            }
        }

        return current;
    }
}
