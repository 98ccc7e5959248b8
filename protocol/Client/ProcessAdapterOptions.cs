using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;
namespace AcPhys.Protocol.Client;

/// <summary>How a <see cref="ProcessAdapter"/> runs its child.</summary>
public sealed record ProcessAdapterOptions
{
    /// <summary>Gets the default per-request timeout.</summary>
    public static TimeSpan DefaultTimeout { get; } = TimeSpan.FromSeconds(10);

    /// <summary>Gets the per-request timeout.</summary>
    public TimeSpan Timeout { get; init; } = DefaultTimeout;

    /// <summary>Gets the least time the handshake is given (start-up of a runtime can be slow on a loaded CI machine); the larger of this and <see cref="Timeout"/> applies.</summary>
    public TimeSpan HandshakeTimeout { get; init; } = TimeSpan.FromSeconds(30);

    /// <summary>Gets the most bytes of one answer line (<see cref="LineLimit"/>); a longer answer stops the run with an error naming the limit.</summary>
    public int MaxLineBytes { get; init; } = BoundedLineReader.DefaultMaxBytes;

    /// <summary>Gets where each line the child writes to stderr goes (null: kept only for error messages).</summary>
    public Action<string>? StderrSink { get; init; }
}
