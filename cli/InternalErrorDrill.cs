namespace AcPhys.Cli;

/// <summary>
/// A drill for the internal-error path (issue 19): with <c>ACPHYS_INTERNAL_ERROR_DRILL=VERB</c> the command VERB fails
/// at once with an internal error, so a test can show what a user sees of a bug (one line, exit 70) and what a
/// developer sees with <c>ACPHYS_DEBUG=1</c> (the stack trace). Unset, it does nothing.
/// </summary>
internal static class InternalErrorDrill
{
    /// <summary>The environment variable naming the command to fail.</summary>
    public const string Variable = AcPhys.Spec.Running.ToolEnvironment.InternalErrorDrillVariable;

    /// <summary>Throws when the drill names <paramref name="verb"/>.</summary>
    /// <param name="verb">The command about to run.</param>
    /// <exception cref="InvalidOperationException">The drill names this command.</exception>
    public static void Check(string verb)
    {
        if (AcPhys.Spec.Running.ToolEnvironment.Process.InternalErrorDrill == verb)
        {
            throw new InvalidOperationException($"internal error drill ({Variable}={verb})");
        }
    }
}
