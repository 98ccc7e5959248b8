using System.CommandLine;
using System.Text;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Protocol;

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
            Description = "Serve the reference with this planted fault switched on (see: acphys faults).",
            HelpName = "FAULT",
        };
        var pick = new Option<string>("--pick")
        {
            Description = "The pick policy to serve: retail (default) or current-first.",
            HelpName = "POLICY",
        };
        var command = new Command("serve", "Serve the reference core over protocol v1 on stdin/stdout (docs/protocol.md); ends at end of input.") { fault, pick };
        command.SetAction(parse => Guard.Run("serve", () => Run(parse.GetValue(fault), parse.GetValue(pick))));
        return command;
    }

    private static int Run(string? faultId, string? pickName)
    {
        if (!PickNames.TryParse(pickName, out var pick))
        {
            throw new UsageException($"unknown pick policy '{pickName}' (known: retail, current-first)");
        }

        ICellPhysics impl = pick == AcPhys.Core.PickPolicy.CurrentFirst ? ReferenceAdapter.CurrentFirst : ReferenceAdapter.Instance;
        if (faultId is not null)
        {
            if (PlantedFaults.Find(faultId) is not { } fault)
            {
                throw new UsageException($"unknown fault '{faultId}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            }

            impl = PlantedFaults.Create(fault.Id);
        }

        var utf8 = new UTF8Encoding(false);
        using var input = new StreamReader(Console.OpenStandardInput(), utf8);
        using var output = new StreamWriter(Console.OpenStandardOutput(), utf8) { NewLine = "\n" };
        new ProtocolServer(impl).Serve(input, output);
        return ExitCodes.Ok;
    }
}
