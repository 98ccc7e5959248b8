using AcPhys.Formats.Cases;
using AcPhys.Spec.Generators;
using FsCheck;

namespace AcPhys.Spec.Cases;

/// <summary>The LandDefs case domain.</summary>
public sealed class LandDomain : ICaseDomain<LandCase>
{
    /// <summary>Gets the instance.</summary>
    public static LandDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<LandCase> Arbitrary => LandGens.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(LandCase c) => BoundaryClasses.Of(c);

    /// <inheritdoc/>
    public string Primary(LandCase c) => BoundaryClasses.PrimaryCoordinate(c);
}

/// <summary>The outdoor-query case domain.</summary>
public sealed class OutdoorDomain : ICaseDomain<OutdoorCase>
{
    /// <summary>Gets the instance.</summary>
    public static OutdoorDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<OutdoorCase> Arbitrary => OutdoorGens.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(OutdoorCase c) => PlaceClasses.OfQuery(c);

    /// <inheritdoc/>
    public string Primary(OutdoorCase c) => PlaceClasses.OfQuery(c).FirstOrDefault() ?? "query:no-spheres";
}

/// <summary>The walk case domain.</summary>
public sealed class WalkDomain : ICaseDomain<Walk>
{
    /// <summary>Gets the instance.</summary>
    public static WalkDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<Walk> Arbitrary => WalkGens.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(Walk w) => PlaceClasses.OfWalk(w);

    /// <inheritdoc/>
    public string Primary(Walk w) => PlaceClasses.OfWalk(w).FirstOrDefault() ?? "walk:within-one-cell";
}

/// <summary>The parts-query case domain.</summary>
public sealed class PartsDomain : ICaseDomain<PartsCase>
{
    /// <summary>Gets the instance.</summary>
    public static PartsDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<PartsCase> Arbitrary => PartsGens.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(PartsCase c)
    {
        yield return c.Parts.Count > 1 ? "parts:multi" : "parts:one";
        if (c.Parts.Any(p => p.Always2D))
        {
            yield return "parts:always2d";
        }

        if (c.Parts.Any(p => p.Frame.Rotation != System.Numerics.Quaternion.Identity))
        {
            yield return "parts:rotated";
        }

        if (c.Parts.Any(p => p.Frame.Origin.X is < 0 or >= 192 || p.Frame.Origin.Y is < 0 or >= 192))
        {
            yield return "parts:outside-frame";
        }
    }

    /// <inheritdoc/>
    public string Primary(PartsCase c) => Classes(c).Last();
}
