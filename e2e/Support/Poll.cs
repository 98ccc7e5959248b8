using System.Diagnostics;

namespace AcPhys.E2E.Support;

/// <summary>Polls a condition every 100 ms until it holds or a limit passes (signal and process tests).</summary>
internal static class Poll
{
    /// <summary>Waits until the condition holds.</summary>
    /// <param name="limit">How long to wait at most.</param>
    /// <param name="condition">The condition.</param>
    /// <returns>True when it held within the limit (checked once more at the end).</returns>
    public static bool Until(TimeSpan limit, Func<bool> condition)
    {
        var clock = Stopwatch.StartNew();
        while (clock.Elapsed < limit)
        {
            if (condition())
            {
                return true;
            }

            Thread.Sleep(100);
        }

        return condition();
    }
}
