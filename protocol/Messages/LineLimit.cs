using AcPhys.Protocol.Child;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The per-line size limit of protocol v1 in this tool: <see cref="BoundedLineReader.DefaultMaxBytes"/> (1 MiB), or
/// the number of bytes the environment variable <see cref="Variable"/> sets. The tool reads and validates it once with
/// its other settings (spec's <c>ToolEnvironment</c>) and passes the number down; this assembly reads no environment.
/// </summary>
public static class LineLimit
{
    /// <summary>The environment variable that overrides the limit (bytes, 1 to 1 GiB).</summary>
    public const string Variable = "ACPHYS_MAX_LINE";

    /// <summary>Returns the limit in force.</summary>
    /// <param name="bytes">The limit the environment sets, or null when it sets none.</param>
    /// <returns>The limit in bytes.</returns>
    public static int OrDefault(int? bytes) => bytes ?? BoundedLineReader.DefaultMaxBytes;
}
