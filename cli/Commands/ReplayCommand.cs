using System.CommandLine;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Replay;
using AcPhys.Contract;
using AcPhys.Formats.Dat;
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
        var pick = new Option<string>("--pick")
        {
            Description = "Check against the reference with this pick policy: retail or current-first (default: the case file's mode, else retail).",
            HelpName = "POLICY",
        };
        var fidelity = new Option<string>("--fidelity")
        {
            Description = "Check against the reference with these documented deviations declared, comma-separated (default: the case file's mode, else retail).",
            HelpName = "NAMES",
        };
        var implOptions = new ImplementationOptions();
        var command = new Command("replay", "Replay a stored case: every invariant on it, and whether it catches the faults it lists. A case written by verify in a declared mode, pick or fault is judged in that mode.") { file, fault, pick, fidelity };
        foreach (var option in implOptions.All)
        {
            command.Options.Add(option);
        }

        command.SetAction(parse => Guard.Run("replay", () => Run(parse.GetValue(file) ?? string.Empty, new CaseModeWords(parse.GetValue(fault), parse.GetValue(pick), parse.GetValue(fidelity)), implOptions.Read(parse))));
        return command;
    }

    private static int Run(string path, CaseModeWords given, ImplementationChoice choice)
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

        if (!records)
        {
            _ = ReplayInputs.For(path); // a kind replay does not know is a usage error before the file is read
        }

        if (choice.IsExternal && given.Any)
        {
            throw new UsageException("--fault, --pick and --fidelity configure the bundled reference; they do not apply to --impl / --impl-cmd (an implementation declares its mode in hello)");
        }

        var entry = CaseFiles.Read(path);
        if (!choice.IsExternal)
        {
            // Issue 41: the mode the case was found in (verify --pick / --fidelity / --fault) judges it again, unless given here.
            var mode = given.Any ? given : CaseModeWords.Of(entry.Mode);
            if (!given.Any && entry.Mode is { IsRetail: false } stored)
            {
                Console.Error.WriteLine($"replay: judged in the mode the case was found in: {string.Join(' ', stored.Words())}");
            }

            var (impl, fault) = mode.Reference();
            if (entry is { Walk: { } walk, Recorded: { } recorded } && fault is null)
            {
                // A minimised capture (capture check --minimise): the port's recorded answers are judged, not the reference's.
                Console.Error.WriteLine("replay: judging the port's recorded answers (field \"recorded\") against " + impl.Name + "; give --impl / --impl-cmd to ask the port again");
                return ReplayPrinter.Replay(entry, path, new ReplayTarget(new AcPhys.Spec.Capture.RecordedPhysics(walk, recorded, impl), null));
            }

            return ReplayPrinter.Replay(entry, path, new ReplayTarget(impl, fault));
        }

        if (entry.Mode is { IsRetail: false } ignored)
        {
            Console.Error.WriteLine($"replay: the case was found on the bundled reference in mode {string.Join(' ', ignored.Words())}; the implementation is judged in the mode it declares");
        }

        var (external, owned) = choice.Open(line => Console.Error.WriteLine("[impl] " + line));
        using (owned)
        {
            return ReplayPrinter.Replay(entry, path, new ReplayTarget(external, null));
        }
    }

    // The --fault, --pick and --fidelity words of a replay, given or read from the case file.
    private sealed record CaseModeWords(string? Fault, string? Pick, string? Fidelity)
    {
        public bool Any => Fault is not null || Pick is not null || Fidelity is not null;

        public static CaseModeWords Of(AcPhys.Formats.Corpus.CaseMode? mode) =>
            mode is null ? new(null, null, null) : new(mode.Fault, mode.Pick, mode.Fidelity.Count == 0 ? null : string.Join(',', mode.Fidelity));

        public (ICellPhysics Impl, PlantedFault? Fault) Reference()
        {
            if (!PickNames.TryParse(Pick, out var policy))
            {
                throw new UsageException($"unknown pick policy '{Pick}' (known: retail, current-first)");
            }

            var fidelity = ReferenceChoice.ParseFidelity(Fidelity);
            if (Fault is null)
            {
                return (ReferenceChoice.Create(policy, fidelity), null);
            }

            var planted = PlantedFaults.Find(Fault)
                ?? throw new UsageException($"unknown fault '{Fault}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            return (ReferenceChoice.Declared(PlantedFaults.Create(planted.Id), policy, fidelity), planted);
        }
    }
}
