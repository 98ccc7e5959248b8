using AcPhys.Protocol.Messages;

namespace AcPhys.Cli.Impl;

/// <summary>The protocol line limit as the tool's commands take it: <see cref="LineLimit"/>, a malformed value a usage error.</summary>
internal static class LineLimitSetting
{
    /// <summary>Reads the limit.</summary>
    /// <returns>The most bytes of one protocol line.</returns>
    /// <exception cref="UsageException">The environment variable is malformed.</exception>
    public static int Read()
    {
        int bytes = LineLimit.FromEnvironment(out string? problem);
        return problem is null ? bytes : throw new UsageException(problem);
    }
}
