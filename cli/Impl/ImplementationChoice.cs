using System.Globalization;
using AcPhys.Contract;
using AcPhys.Protocol.Client;

namespace AcPhys.Cli.Impl;

/// <summary>
/// Which implementation a verb runs against: the bundled reference (with its planted faults), an assembly loaded in
/// process (<c>--impl</c>), or a child process speaking protocol v1 (<c>--impl-cmd</c>).
/// </summary>
/// <param name="Command">The <c>--impl-cmd</c> command line, or null.</param>
/// <param name="AssemblyPath">The <c>--impl</c> assembly, or null.</param>
/// <param name="Timeout">The per-request timeout for <c>--impl-cmd</c>.</param>
internal sealed record ImplementationChoice(string? Command, string? AssemblyPath, TimeSpan Timeout)
{
    /// <summary>Gets the bundled reference (nothing chosen).</summary>
    public static ImplementationChoice Reference { get; } = new(null, null, ProcessAdapterOptions.DefaultTimeout);

    /// <summary>Gets a value indicating whether an implementation other than the bundled reference was chosen.</summary>
    public bool IsExternal => Command is not null || AssemblyPath is not null;

    /// <summary>Gets a value indicating whether the implementation runs in another process (every query is a round trip).</summary>
    public bool IsProcess => Command is not null;

    /// <summary>Opens the chosen implementation.</summary>
    /// <param name="stderrSink">Where a child's stderr lines go (null: captured only).</param>
    /// <returns>The implementation and what to dispose when done.</returns>
    /// <exception cref="AdapterFailureException">A child could not be started or failed the handshake.</exception>
    /// <exception cref="UsageException">The assembly cannot be loaded or holds no adapter.</exception>
    public (ICellPhysics Impl, IDisposable? Owned) Open(Action<string>? stderrSink)
    {
        if (Command is not null)
        {
            var adapter = ProcessAdapter.Start(Command, new ProcessAdapterOptions { Timeout = Timeout, StderrSink = stderrSink, MaxLineBytes = LineLimitSetting.Read(AcPhys.Spec.Running.ToolEnvironment.Process) });
            return (adapter, adapter);
        }

        if (AssemblyPath is not null)
        {
            var impl = WatchedAdapter.Load(AssemblyPath, Timeout); // the same --timeout as a child (issue 28)
            return (impl, impl);
        }

        throw new InvalidOperationException("no external implementation chosen");
    }

    /// <summary>Returns the command-line words that choose this implementation again (for replay lines).</summary>
    /// <returns>The words, unquoted.</returns>
    public IReadOnlyList<string> Words()
    {
        var words = new List<string>();
        if (Command is not null)
        {
            words.AddRange(["--impl-cmd", Command]);
        }

        if (AssemblyPath is not null)
        {
            words.AddRange(["--impl", AssemblyPath]);
        }

        if (IsExternal && Timeout != ProcessAdapterOptions.DefaultTimeout)
        {
            words.AddRange(["--timeout", Timeout.TotalSeconds.ToString("0.###", CultureInfo.InvariantCulture)]);
        }

        return words;
    }
}
