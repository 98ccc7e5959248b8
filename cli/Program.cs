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
        if (AcPhys.Spec.Running.ToolEnvironment.Process.WireProfile)
        {
            AcPhys.Formats.Values.WireProfileSwitch.Enable(); // the served path's stopwatch breakdown (docs/protocol.md, "Speed")
        }

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
            CaptureCommand.Create(),
        };

        var parse = root.Parse(args);
        if (parse.Errors.Count > 0 && parse.Action is ParseErrorAction)
        {
            // A clear message per error (unknown verb first, with a suggestion), then a pointer to the help; exit 2.
            bool atRoot = parse.CommandResult.Command == root;
            string? unknownVerb = atRoot ? parse.UnmatchedTokens.FirstOrDefault(t => !t.StartsWith('-')) : null;
            if (unknownVerb is not null)
            {
                string shown = unknownVerb.Length > 64 ? unknownVerb[..64] + "…" : unknownVerb;
                Console.Error.WriteLine($"unknown command '{shown}'" + (Suggest.Closest(unknownVerb, root.Subcommands.Select(c => c.Name)) is { } verb ? $"; did you mean '{verb}'?" : string.Empty));
            }

            foreach (var error in parse.Errors)
            {
                if (unknownVerb is not null && (error.Message.StartsWith("Required command", StringComparison.Ordinal) || error.Message.Contains($"'{unknownVerb}'", StringComparison.Ordinal)))
                {
                    continue; // said above, better
                }

                Console.Error.WriteLine(ParseErrors.Explain(error.Message));
            }

            // The whole command path (issue 28: "tradeoffs accuracy --seed x" pointed to "acphys accuracy --help").
            string command = string.Empty;
            for (var c = parse.CommandResult; c is not null && c.Command != root; c = c.Parent as System.CommandLine.Parsing.CommandResult)
            {
                command = " " + c.Command.Name + command;
            }

            Console.Error.WriteLine($"Run 'acphys{command} --help' for usage.");
            return ExitCodes.ToolError;
        }

        return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false, ProcessTerminationTimeout = null });
    }
}
