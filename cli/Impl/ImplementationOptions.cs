using System.CommandLine;
using System.Globalization;
using AcPhys.Protocol.Client;

namespace AcPhys.Cli.Impl;

/// <summary>The options that choose an implementation under test, shared by <c>verify</c>, <c>diff</c> and <c>replay</c>.</summary>
internal sealed class ImplementationOptions
{
    /// <summary>The shortest <c>--timeout</c>: below it no answer could arrive (issue 28: 1e-9 was accepted, "within 0 s").</summary>
    public const double MinTimeoutSeconds = 0.1;

    /// <summary>Gets <c>--impl-cmd</c>.</summary>
    public Option<string> Command { get; } = new("--impl-cmd")
    {
        Description = "Test an implementation in another process: this command line is started and spoken to over stdin/stdout, protocol v1 (docs/protocol.md).",
        HelpName = "COMMAND LINE",
    };

    /// <summary>Gets <c>--impl</c>.</summary>
    public Option<string> Assembly { get; } = new("--impl")
    {
        Description = "Test a .NET implementation in process: an assembly with one public class implementing AcPhys.Contract.ICellPhysics.",
        HelpName = "PATH.dll",
    };

    /// <summary>Gets <c>--timeout</c>.</summary>
    public Option<string> Timeout { get; } = new("--timeout")
    {
        Description = $"Seconds to wait for each answer of an --impl-cmd or --impl implementation (default {ProcessAdapterOptions.DefaultTimeout.TotalSeconds}, at least {MinTimeoutSeconds}); a hang past it is exit 2.",
        HelpName = "SECONDS",
    };

    /// <summary>Gets the options, to add to a command.</summary>
    public IEnumerable<Option> All => [Command, Assembly, Timeout];

    /// <summary>Reads and validates the choice.</summary>
    /// <param name="parse">The parse result.</param>
    /// <returns>The choice.</returns>
    /// <exception cref="UsageException">Both were given, the assembly is missing, or the timeout is not a positive number.</exception>
    public ImplementationChoice Read(ParseResult parse)
    {
        string? command = parse.GetValue(Command);
        string? assembly = parse.GetValue(Assembly);
        string? timeoutText = parse.GetValue(Timeout);
        if (command is not null && assembly is not null)
        {
            throw new UsageException("--impl and --impl-cmd exclude each other (one implementation under test at a time)");
        }

        if (command is not null && string.IsNullOrWhiteSpace(command))
        {
            throw new UsageException("--impl-cmd needs a command line, e.g. --impl-cmd \"python3 examples/python/acphys_impl.py\"");
        }

        if (assembly is not null && !File.Exists(assembly))
        {
            throw new UsageException($"--impl: no such file '{assembly}'");
        }

        var timeout = ProcessAdapterOptions.DefaultTimeout;
        if (timeoutText is not null)
        {
            if (!double.TryParse(timeoutText, NumberStyles.Float, CultureInfo.InvariantCulture, out double seconds) || !(seconds >= MinTimeoutSeconds && seconds <= 3600))
            {
                throw new UsageException($"malformed --timeout '{AcPhys.Formats.Values.InputQuote.Line(timeoutText)}': expected seconds, a number from {MinTimeoutSeconds} to 3600");
            }

            if (command is null && assembly is null)
            {
                throw new UsageException("--timeout applies to --impl-cmd and --impl only");
            }

            timeout = TimeSpan.FromSeconds(seconds);
        }

        return new ImplementationChoice(command, assembly is null ? null : Path.GetFullPath(assembly), timeout);
    }
}
