using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Protocol.Messages;

namespace AcPhys.Cli.Impl;

/// <summary>The bundled reference in a declared mode: a pick policy and the documented deviations of <c>--fidelity</c> (FidelityNames).</summary>
internal static class ReferenceChoice
{
    /// <summary>Parses <c>--fidelity</c>: comma-separated deviation names, or null / empty for retail.</summary>
    /// <param name="text">The option's value.</param>
    /// <returns>The indoor and outdoor fidelity.</returns>
    /// <exception cref="UsageException">An unknown name.</exception>
    public static (IndoorFidelity Indoor, OutdoorFidelity Outdoor) ParseFidelity(string? text)
    {
        var names = (text ?? string.Empty).Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        return FidelityNames.TryParse(names, out var indoor, out var outdoor, out var bad)
            ? (indoor, outdoor)
            : throw new UsageException($"unknown fidelity '{Wire.Brief(bad!, 60)}' (known: {string.Join(", ", FidelityNames.Known)})");
    }

    /// <summary>Returns the <c>--fidelity</c> names that choose a fidelity again: <c>ace</c> for every ACE difference, else one name per switch.</summary>
    /// <param name="fidelity">The declared deviations.</param>
    /// <returns>The names, empty for retail.</returns>
    public static IReadOnlyList<string> FidelityWords((IndoorFidelity Indoor, OutdoorFidelity Outdoor) fidelity)
    {
        if ((fidelity.Indoor with { ReframeTransit = false }) != IndoorFidelity.Ace)
        {
            return FidelityNames.Names(fidelity.Indoor, fidelity.Outdoor);
        }

        var words = new List<string> { FidelityNames.Ace };
        words.AddRange(FidelityNames.Names(IndoorFidelity.Retail with { ReframeTransit = fidelity.Indoor.ReframeTransit }, fidelity.Outdoor));
        return words;
    }

    /// <summary>Returns a planted fault (or any implementation) declaring <c>--pick</c> and <c>--fidelity</c>: retail and no deviation keep its own declaration.</summary>
    /// <param name="impl">The faulty implementation.</param>
    /// <param name="pick">The pick given.</param>
    /// <param name="fidelity">The deviations given.</param>
    /// <returns>The implementation under that declaration.</returns>
    public static ICellPhysics Declared(ICellPhysics impl, PickPolicy pick, (IndoorFidelity Indoor, OutdoorFidelity Outdoor) fidelity) =>
        AcPhys.Spec.Faults.DeclaredFault.Declaring(
            impl,
            pick == PickPolicy.CurrentFirst ? pick : null,
            fidelity == default ? null : fidelity.Indoor,
            fidelity == default ? null : fidelity.Outdoor);

    /// <summary>Returns the reference adapter for a pick and a fidelity.</summary>
    /// <param name="pick">The pick policy.</param>
    /// <param name="fidelity">The declared deviations.</param>
    /// <returns>The adapter (the shared instances for the plain modes).</returns>
    public static ReferenceAdapter Create(PickPolicy pick, (IndoorFidelity Indoor, OutdoorFidelity Outdoor) fidelity) =>
        fidelity == default
            ? pick == PickPolicy.CurrentFirst ? ReferenceAdapter.CurrentFirst : ReferenceAdapter.Instance
            : new ReferenceAdapter(pick, outdoor: fidelity.Outdoor) { Indoor = fidelity.Indoor };
}
