using System.CommandLine;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Replay;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Dat;
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
            Description = "The input file: " + string.Join("; ", ReplayInputs.All.Select(i => $"kind \"{i.Kind}\": {i.Description}")) + "; or a record folder (acphys scene export) holding a scene walk.",
        };
        var fault = new Option<string>("--fault")
        {
            Description = "Check against the reference with this planted fault switched on (see: acphys faults).",
            HelpName = "FAULT",
        };
        var implOptions = new ImplementationOptions();
        var command = new Command("replay", "Replay a stored case: every invariant on it, and whether it catches the faults it lists.") { file, fault };
        foreach (var option in implOptions.All)
        {
            command.Options.Add(option);
        }

        command.SetAction(parse => Guard.Run("replay", () => Run(parse.GetValue(file) ?? string.Empty, parse.GetValue(fault), implOptions.Read(parse))));
        return command;
    }

    private static int Run(string path, string? faultId, ImplementationChoice choice)
    {
        bool records = DatFolder.IsRecordFolder(path);
        if (Directory.Exists(path) && !records)
        {
            throw new UsageException($"{path}: is a directory without {DatFolder.ManifestName}; give one file or a record folder");
        }

        if (!records && !File.Exists(path))
        {
            throw new UsageException($"{(path.Length == 0 ? "''" : path)}: no such file");
        }

        PlantedFault? fault = null;
        if (faultId is not null)
        {
            fault = PlantedFaults.Find(faultId)
                ?? throw new UsageException($"unknown fault '{faultId}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
        }

        if (!choice.IsExternal)
        {
            ICellPhysics impl = fault is null ? ReferenceAdapter.Instance : PlantedFaults.Create(fault.Id);
            return records ? ReplayPrinter.Replay(CaseFiles.Read(path), path, new ReplayTarget(impl, fault)) : ReplayInputs.For(path).Replay(path, new ReplayTarget(impl, fault));
        }

        if (fault is not null)
        {
            throw new UsageException("--fault configures the bundled reference; it does not apply to --impl / --impl-cmd");
        }

        var entry = records ? CaseFiles.Read(path) : null;
        var input = records ? null : ReplayInputs.For(path);
        var (external, owned) = choice.Open(line => Console.Error.WriteLine("[impl] " + line));
        using (owned)
        {
            return entry is not null ? ReplayPrinter.Replay(entry, path, new ReplayTarget(external, null)) : input!.Replay(path, new ReplayTarget(external, null));
        }
    }
}
