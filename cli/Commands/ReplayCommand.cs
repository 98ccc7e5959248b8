using System.CommandLine;
using AcPhys.Cli.Replay;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Faults;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>replay</c> verb: checks one stored input file (a corpus case today) against the reference or a planted fault.</summary>
internal static class ReplayCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var file = new Argument<string>("file")
        {
            Description = "The input file: " + string.Join("; ", ReplayInputs.All.Select(i => $"kind \"{i.Kind}\": {i.Description}")) + ".",
        };
        var fault = new Option<string>("--fault")
        {
            Description = "Check against the reference with this planted fault switched on (see: acphys faults).",
            HelpName = "FAULT",
        };
        var command = new Command("replay", "Replay a stored case: every invariant on it, and whether it catches the faults it lists.") { file, fault };
        command.SetAction(parse => Guard.Run("replay", () => Run(parse.GetValue(file) ?? string.Empty, parse.GetValue(fault))));
        return command;
    }

    private static int Run(string path, string? faultId)
    {
        if (Directory.Exists(path))
        {
            throw new UsageException($"{path}: is a directory; give one file");
        }

        if (!File.Exists(path))
        {
            throw new UsageException($"{(path.Length == 0 ? "''" : path)}: no such file");
        }

        PlantedFault? fault = null;
        if (faultId is not null)
        {
            fault = PlantedFaults.Find(faultId)
                ?? throw new UsageException($"unknown fault '{faultId}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
        }

        ICellPhysics impl = fault is null ? ReferenceAdapter.Instance : PlantedFaults.Create(fault.Id);
        return ReplayInputs.For(path).Replay(path, new ReplayTarget(impl, fault));
    }
}
