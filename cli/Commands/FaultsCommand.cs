using System.CommandLine;
using AcPhys.Spec.Faults;
using Spectre.Console;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>faults</c> verb: lists the planted faults and the invariants expected to catch each.</summary>
internal static class FaultsCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var command = new Command("faults", "List the planted faults (deliberate defects the suite must catch; use one with verify/replay --fault).");
        command.SetAction(_ => Guard.Run("faults", Run));
        return command;
    }

    private static int Run()
    {
        var table = new Table().AddColumns("Fault", "What it breaks", "Expected catchers");
        foreach (var fault in PlantedFaults.All)
        {
            table.AddRow(new Text(fault.Id), new Text(fault.Title), new Text(string.Join(", ", fault.CaughtBy)));
        }

        Terminal.Out.Write(table);
        Terminal.Line($"{PlantedFaults.All.Count} planted faults; try: acphys verify --fault {PlantedFaults.All[0].Id}");
        return ExitCodes.Ok;
    }
}
