namespace AcPhys.Fuzz;

/// <summary>A named fuzz target.</summary>
/// <param name="Name">The name given on the command line (<c>--target</c> of fuzz/run.sh).</param>
/// <param name="Description">One line for <c>list</c>.</param>
/// <param name="Create">Builds the test for a fault id (null: the correct core); throws <see cref="ArgumentException"/> for an unknown fault.</param>
/// <param name="Seeds">Initial inputs for afl-fuzz's <c>-i</c> directory, by file name.</param>
internal sealed record FuzzTarget(
    string Name,
    string Description,
    Func<string?, Action<ReadOnlySpan<byte>>> Create,
    IReadOnlyDictionary<string, byte[]> Seeds);
