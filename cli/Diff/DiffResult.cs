using AcPhys.Spec.Running;

namespace AcPhys.Cli.Diff;

/// <summary>One divergence class of a check: how many inputs fell in it, of which boundary classes, and its smallest input.</summary>
/// <param name="What">The op and the shape of the difference.</param>
/// <param name="Inputs">The inputs' boundary classes with their counts, most first.</param>
/// <param name="Count">How many generated inputs diverged this way.</param>
/// <param name="Example">The input shrunk within the class (or the first one seen, when <paramref name="Shrunk"/> is false).</param>
/// <param name="Message">Both answers to <paramref name="Example"/>.</param>
/// <param name="Shrunk">Whether <paramref name="Example"/> was shrunk.</param>
internal sealed record DivergenceClass(string What, IReadOnlyList<(string Input, int Count)> Inputs, int Count, object Example, string Message, bool Shrunk);

/// <summary>What one differential check found: every divergence class with its count, most frequent first.</summary>
/// <param name="Check">The check.</param>
/// <param name="Seed">The seed the inputs came from (replays the whole check).</param>
internal sealed record DiffResult(DiffCheck Check, Seed Seed)
{
    /// <summary>Gets the number of inputs compared.</summary>
    public int Cases { get; init; }

    /// <summary>Gets the number of inputs whose answers differ.</summary>
    public int Divergent { get; init; }

    /// <summary>Gets the classes, most inputs first.</summary>
    public IReadOnlyList<DivergenceClass> Classes { get; init; } = [];

    /// <summary>Gets why the implementation was not compared, or null when it was.</summary>
    public string? NotComparedReason { get; init; }

    /// <summary>Gets the time the check took, shrinking included.</summary>
    public TimeSpan Elapsed { get; init; }

    /// <summary>Gets a value indicating whether any input diverged.</summary>
    public bool Differs => Divergent > 0;
}
