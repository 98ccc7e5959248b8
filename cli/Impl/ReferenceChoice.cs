using AcPhys.Core;
using AcPhys.Spec.Adapters;

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
            : throw new UsageException($"unknown fidelity '{AcPhys.Spec.Protocol.Wire.Brief(bad!, 60)}' (known: {string.Join(", ", FidelityNames.Known)})");
    }

    /// <summary>Returns the reference adapter for a pick and a fidelity.</summary>
    /// <param name="pick">The pick policy.</param>
    /// <param name="fidelity">The declared deviations.</param>
    /// <returns>The adapter (the shared instances for the plain modes).</returns>
    public static ReferenceAdapter Create(PickPolicy pick, (IndoorFidelity Indoor, OutdoorFidelity Outdoor) fidelity) =>
        fidelity == default
            ? pick == PickPolicy.CurrentFirst ? ReferenceAdapter.CurrentFirst : ReferenceAdapter.Instance
            : new ReferenceAdapter(pick, outdoor: fidelity.Outdoor) { Indoor = fidelity.Indoor };
}
