namespace AcPhys.Contract;

/// <summary>
/// What a transport between the tool and an implementation negotiated beyond the operations the implementation states
/// (<see cref="ICellPhysics.Ops"/>): how scenes travel, whether queries may be streamed. The checking engine asks this
/// interface, never a transport class (issue 42); an in-process port has no transport and does not implement it.
/// </summary>
public interface ITransport
{
    /// <summary>Gets the capabilities the transport negotiated, by their wire names (for reports), in protocol order.</summary>
    IReadOnlyList<string> Negotiated { get; }

    /// <summary>
    /// Gets a value indicating whether scenes reach the implementation as retail dat records: what it answered about is
    /// then the scene read back from them, which the conformance comparison must use too (docs/protocol.md, "Scenes as
    /// dat records").
    /// </summary>
    bool ScenesAsRecords { get; }

    /// <summary>Gets a value indicating whether <see cref="Streamed{T}"/> streams queries without waiting for each answer.</summary>
    bool Streams { get; }

    /// <summary>
    /// Runs <paramref name="run"/> (one invariant's whole run) through the transport's stream: the result is the one a
    /// query-by-query run gives (docs/protocol.md, "Pipelining"). Without streaming it just runs.
    /// </summary>
    /// <typeparam name="T">The run's result.</typeparam>
    /// <param name="run">The run; it may be called again (what an earlier call reported is to be discarded).</param>
    /// <returns>The result.</returns>
    T Streamed<T>(Func<T> run);
}

/// <summary>The engine's questions to an implementation's transport, answered for one without a transport too.</summary>
public static class Transports
{
    /// <summary>Runs <paramref name="run"/> streamed when <paramref name="impl"/>'s transport streams; else just runs it.</summary>
    /// <typeparam name="T">The run's result.</typeparam>
    /// <param name="impl">The implementation.</param>
    /// <param name="run">The run (see <see cref="ITransport.Streamed{T}"/>).</param>
    /// <returns>The result.</returns>
    public static T Streamed<T>(ICellPhysics impl, Func<T> run) => impl is ITransport { Streams: true } t ? t.Streamed(run) : run();

    /// <summary>Returns whether <paramref name="impl"/> is sent scenes as retail dat records (<see cref="ITransport.ScenesAsRecords"/>).</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>True when its transport sends scenes as records.</returns>
    public static bool ScenesAsRecords(ICellPhysics impl) => impl is ITransport { ScenesAsRecords: true };

    /// <summary>Returns the capabilities <paramref name="impl"/>'s transport negotiated, by wire name; none for an in-process port.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The names.</returns>
    public static IReadOnlyList<string> Negotiated(ICellPhysics impl) => impl is ITransport t ? t.Negotiated : [];
}
