using System.Globalization;
using FsCheck.Xunit;

namespace AcPhys.Props.Mutation;

/// <summary>
/// An FsCheck.Xunit <see cref="PropertyAttribute"/> for a mutation-killing property: its own fixed seed and
/// <see cref="FixedSeed.Cases"/> cases in every profile, so the mutants it kills are the same on every run.
/// </summary>
/// <remarks>
/// A failure prints FsCheck's own <c>Falsifiable, after N tests (K shrinks) (seed,gamma)</c> with the original and
/// shrunk case; the pair is this attribute's <see cref="PropertyAttribute.Replay"/>, so the failure reproduces as it is.
/// </remarks>
[AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
public sealed class FixedSeedPropertyAttribute : PropertyAttribute
{
    /// <summary>Initializes a new instance of the <see cref="FixedSeedPropertyAttribute"/> class.</summary>
    /// <param name="seed">The property's own seed (<see cref="FixedSeed.Gamma"/> is the gamma).</param>
    public FixedSeedPropertyAttribute(ulong seed)
    {
        Seed = seed;
        MaxTest = FixedSeed.Cases;
        Replay = string.Create(CultureInfo.InvariantCulture, $"({seed},{FixedSeed.Gamma})");
    }

    /// <summary>Gets the property's own seed.</summary>
    public ulong Seed { get; }
}
