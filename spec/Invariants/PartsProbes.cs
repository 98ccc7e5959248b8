using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// The numerical-tie probes of a parts query (the parts twin of <see cref="Conformance.Probes"/>): in scenes the
/// conformance invariants accept a difference that the reference's answer to a query moved by
/// <see cref="Conformance.TieUlps"/> ulps explains (docs/conformance.md, "Scenes"), so a port computing in double what
/// retail computes in float32 (R = r + EPS at a portal's gate, facts §5.2, §5.3) is not failed at an exact bound.
/// </summary>
internal static class PartsProbes
{
    /// <summary>Returns the probes: every part's origin moved together by ±step along x, y, z and the four horizontal diagonals, and every radius by ±step.</summary>
    /// <param name="parts">The parts (the first is the anchor; cells and boxes are kept).</param>
    /// <returns>The probes.</returns>
    public static IEnumerable<Part[]> Of(IReadOnlyList<Part> parts)
    {
        float step = Conformance.TieStep(parts.SelectMany(p => new[] { p.Frame.Origin.X, p.Frame.Origin.Y, p.Frame.Origin.Z, p.Radius }));
        var moves = new Vector3[]
        {
            new(step, 0, 0), new(-step, 0, 0), new(0, step, 0), new(0, -step, 0), new(0, 0, step), new(0, 0, -step),
            new(step, step, 0), new(step, -step, 0), new(-step, step, 0), new(-step, -step, 0),
        };
        foreach (var m in moves)
        {
            yield return [.. parts.Select(p => p with { Frame = p.Frame with { Origin = p.Frame.Origin + m } })];
        }

        yield return [.. parts.Select(p => p with { Radius = p.Radius + step })];
        yield return [.. parts.Select(p => p with { Radius = MathF.Max(0, p.Radius - step) })];
    }
}
