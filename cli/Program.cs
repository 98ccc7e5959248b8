using System.CommandLine;
using System.CommandLine.Invocation;
using AcPhys.Cli.Commands;

namespace AcPhys.Cli;

/// <summary>Entry point of <c>acphys</c>: the verbs, parse errors as exit 2, and the invocation policy.</summary>
internal static class Program
{
    /// <summary>Parses the command line and runs the chosen verb.</summary>
    /// <param name="args">The arguments.</param>
    /// <returns>The exit code (docs/cli.md).</returns>
    public static int Main(string[] args)
    {
        var root = new RootCommand("acphys: verify cell-membership physics against its invariants (AcPhysVerify).")
        {
            VerifyCommand.Create(),
            InvariantsCommand.Create(),
            FaultsCommand.Create(),
            ReplayCommand.Create(),
        };

        var parse = root.Parse(args);
        if (parse.Action is ParseErrorAction errors)
        {
            // System.CommandLine's own message (with its typo corrections), then a pointer to the help; exit 2, not its 1.
            errors.ShowHelp = false;
            errors.Invoke(parse);
            string verb = parse.CommandResult.Command == root ? string.Empty : " " + parse.CommandResult.Command.Name;
            Console.Error.WriteLine($"Run 'acphys{verb} --help' for usage.");
            return ExitCodes.ToolError;
        }

        return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false, ProcessTerminationTimeout = null });
    }
}
