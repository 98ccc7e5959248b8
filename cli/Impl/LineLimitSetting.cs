using AcPhys.Protocol.Messages;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Impl;

/// <summary>The protocol line limit as the tool's commands take it: <see cref="LineLimit"/> from the settings, a malformed value a usage error.</summary>
internal static class LineLimitSetting
{
    /// <summary>Reads the limit.</summary>
    /// <param name="settings">The tool's settings.</param>
    /// <returns>The most bytes of one protocol line.</returns>
    /// <exception cref="UsageException">The environment variable is malformed.</exception>
    public static int Read(ToolEnvironment settings) =>
        settings.Problem(ToolEnvironment.MaxLineVariable) is { } problem ? throw new UsageException(problem) : LineLimit.OrDefault(settings.MaxLineBytes);
}
