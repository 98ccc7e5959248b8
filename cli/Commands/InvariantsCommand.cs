using System.CommandLine;
using AcPhys.Spec.Invariants;
using Spectre.Console;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>invariants</c> verb: lists every invariant's ID, statement and source, as a table or as markdown.</summary>
internal static class InvariantsCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var markdown = new Option<bool>("--markdown") { Description = "Print the markdown of docs/invariants.md (regenerate it with: ./acphys invariants --markdown > docs/invariants.md)." };
        var command = new Command("invariants", "List every invariant: ID, statement and the spec section it rests on.") { markdown };
        command.SetAction(parse => Guard.Run("invariants", () => parse.GetValue(markdown) ? PrintMarkdown() : PrintTable()));
        return command;
    }

    private static int PrintTable()
    {
        var table = new Table().AddColumns("ID", "Scope", "Statement", "Source");
        foreach (var invariant in InvariantCatalogue.All)
        {
            table.AddRow(new Text(invariant.Id), new Text(invariant.Scope is { } scope ? InvariantScope.Name(scope) : "-"), new Text(invariant.Statement), new Text(invariant.Source));
        }

        Terminal.Out.Write(table);
        Terminal.Line($"{InvariantCatalogue.All.Count} invariants");
        return ExitCodes.Ok;
    }

    private static int PrintMarkdown()
    {
        // Exactly the text of docs/invariants.md (a props test keeps the file equal to InvariantDocs.Markdown()).
        Console.Out.Write(InvariantDocs.Markdown());
        return ExitCodes.Ok;
    }
}
