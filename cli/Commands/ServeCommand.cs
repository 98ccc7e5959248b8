using System.CommandLine;
using System.Text;
using AcPhys.Contract;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Faults;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>serve</c> verb: the reference core (or a planted fault) over protocol v1 on stdin/stdout, so the
/// out-of-process path can be tested end to end (<c>acphys verify --impl-cmd "acphys serve"</c>) and other
/// implementations can be compared with it.
/// </summary>
internal static class ServeCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var fault = new Option<string>("--fault")
        {
            Description = "Serve the reference with this planted fault switched on (see: acphys faults); several outdoor faults comma-separated make a port with several bugs.",
            HelpName = "FAULT[,FAULT...]",
        };
        var pick = new Option<string>("--pick")
        {
            Description = "The pick policy to serve: retail (default) or current-first.",
            HelpName = "POLICY",
        };
        var fidelity = new Option<string>("--fidelity")
        {
            Description = "Serve the reference with these documented deviations, declared in hello (comma-separated: ace, double, ace-early-return, ...; docs/protocol.md).",
            HelpName = "NAMES",
        };
        var noLoad = new Option<bool>("--no-load-scene") { Description = "Do not announce load_scene: every find_cell carries its whole scene (as a server without it)." };
        var noDat = new Option<bool>("--no-dat-records") { Description = "Announce load_scene without dat_records: scenes arrive as the project's JSON, not as retail dat records." };
        var noWalks = new Option<bool>("--no-walks") { Description = "Do not announce find_cell_walk or find_cell_parts_walk: walks travel one query per round trip (as a server without them)." };
        var noPipeline = new Option<bool>("--no-pipeline") { Description = "Do not announce pipeline: the tool waits for each answer before the next request (as a server without it)." };
        var announceRetail = new Option<bool>("--announce-retail")
        {
            Description = "Serve the --pick / --fidelity behaviour but announce retail in hello: a port deviating without declaring it (the suite must fail it; docs/facts-coverage.md). With --fidelity ace it is the planted fault ace-announced-retail.",
        };
        var ops = new Option<string>("--ops")
        {
            Description = "Offer only these operations (comma-separated protocol names, e.g. every op but find_cell_scene: a port whose only scene query is the transition; docs/ports.md).",
            HelpName = "OPS",
        };
        var worldFrame = new Option<bool>("--world-frame") { Description = "Declare \"frame\": \"world\" and take every point in world coordinates, as a port that keeps one world frame (docs/protocol.md, \"World frame\")." };
        var worldFrameFault = new Option<string>("--world-frame-fault")
        {
            Description = "With --world-frame, convert with a planted shim bug: swapped-block-axes (the suite must fail it; an alias of --fault world-frame-swapped-axes).",
            HelpName = "FAULT",
        };
        var command = new Command("serve", "Serve the reference core over protocol v1 on stdin/stdout (docs/protocol.md); ends at end of input.") { fault, pick, fidelity, noLoad, noDat, noWalks, noPipeline, announceRetail, ops, worldFrame, worldFrameFault };
        command.SetAction(parse => Guard.Run("serve", () => Run(
            parse.GetValue(fault),
            parse.GetValue(pick),
            parse.GetValue(fidelity),
            (parse.GetValue(noLoad), parse.GetValue(noDat), parse.GetValue(noWalks), parse.GetValue(noPipeline), parse.GetValue(announceRetail)),
            parse.GetValue(ops),
            (parse.GetValue(worldFrame), parse.GetValue(worldFrameFault)))));
        return command;
    }

    // --ops: the operations kept; the capabilities (load_scene, dat_records, find_cell_walk, pipeline) are the server's own.
    private static Op ParseOps(string names)
    {
        var ops = OpNames.Parse(names.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries), out var unknown);
        if (unknown.Count > 0 || ops == Op.None)
        {
            throw new UsageException($"--ops: unknown or no operation '{(unknown.Count > 0 ? unknown[0] : names)}' (known: {string.Join(", ", OpNames.Names(Op.All))})");
        }

        return ops;
    }

    private static int Run(string? faultId, string? pickName, string? fidelityNames, (bool NoLoadScene, bool NoDatRecords, bool NoWalks, bool NoPipeline, bool AnnounceRetail) flags, string? opNames, (bool On, string? Fault) world)
    {
        var (noLoadScene, noDatRecords, noWalks, noPipeline, announceRetail) = flags;
        bool swappedShim = world.Fault switch
        {
            null => false,
            "swapped-block-axes" when world.On => true,
            "swapped-block-axes" => throw new UsageException("--world-frame-fault needs --world-frame"),
            _ => throw new UsageException($"unknown --world-frame-fault '{world.Fault}' (known: swapped-block-axes)"),
        };
        if (!PickNames.TryParse(pickName, out var pick))
        {
            throw new UsageException($"unknown pick policy '{pickName}' (known: retail, current-first)");
        }

        var fidelity = Impl.ReferenceChoice.ParseFidelity(fidelityNames);
        ICellPhysics impl = Impl.ReferenceChoice.Create(pick, fidelity);
        if (faultId is not null)
        {
            string[] ids = faultId.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
            foreach (string id in ids.Length == 0 ? [faultId] : ids)
            {
                if (PlantedFaults.Find(id) is null)
                {
                    throw new UsageException($"unknown fault '{id}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
                }
            }

            try
            {
                impl = Impl.ReferenceChoice.Declared(ids.Length == 1 ? PlantedFaults.Create(ids[0]) : PlantedFaults.Combine(ids), pick, fidelity); // declared: the fault's answers, that mode declared
            }
            catch (ArgumentException e)
            {
                throw new UsageException("--fault with several faults takes outdoor faults only: " + e.Message);
            }
        }

        if (swappedShim)
        {
            // The server converts the world frame back exactly; the planted shim then takes the wrong origin: the
            // numbers the old shim bug gave, now the planted fault world-frame-swapped-axes.
            impl = PortShimFaults.BehindSwappedShim(impl);
        }

        if (announceRetail)
        {
            impl = PortShimFaults.AnnouncingRetail(impl);
        }

        if (opNames is not null)
        {
            impl = new OpsOffered(impl, ParseOps(opNames));
        }

        int maxLine = Impl.LineLimitSetting.Read(AcPhys.Spec.Running.ToolEnvironment.Process);
        using var input = Console.OpenStandardInput();
        using var output = new StreamWriter(Console.OpenStandardOutput(), new UTF8Encoding(false)) { NewLine = "\n" };
        new ProtocolServer(impl) { LoadScenes = !noLoadScene, DatRecords = !noDatRecords, Walks = !noWalks, Pipeline = !noPipeline, InWorldFrame = world.On }.Serve(input, output, maxLine);
        return ExitCodes.Ok;
    }
}
