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
            RenderCommand.Create(),
            SceneCommand.Create(),
            BiteCommand.Create(),
            ServeCommand.Create(),
            DiffCommand.Create(),
            FuzzCommand.Create(),
            TradeoffsCommand.Create(),
            BenchCommand.Create(),
        };

        var parse = root.Parse(args);
        if (parse.Errors.Count > 0 && parse.Action is ParseErrorAction)
        {
            // System.CommandLine's own messages, a suggestion for a mistyped verb, then a pointer to the help; exit 2.
            foreach (var error in parse.Errors)
            {
                Console.Error.WriteLine(error.Message);
            }

            if (parse.CommandResult.Command == root && Suggest.Closest(parse.UnmatchedTokens.FirstOrDefault(), root.Subcommands.Select(c => c.Name)) is { } verb)
            {
                Console.Error.WriteLine($"Did you mean '{verb}'?");
            }

            string command = parse.CommandResult.Command == root ? string.Empty : " " + parse.CommandResult.Command.Name;
            Console.Error.WriteLine($"Run 'acphys{command} --help' for usage.");
            return ExitCodes.ToolError;
        }

        return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false, ProcessTerminationTimeout = null });
    }
}
