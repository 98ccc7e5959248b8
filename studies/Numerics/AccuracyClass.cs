using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Studies.Numerics;

/// <summary>
/// The boundary class of an outdoor query for the accuracy tables: where the nearest boundary is that a sphere's
/// centre or disc edge sits on (within <see cref="Band"/>). Indoor classes, "portal-straddle" among them:
/// <see cref="IndoorAccuracyClass"/>.
/// </summary>
public static class AccuracyClass
{
    /// <summary>Distance from a line within which a centre or disc edge counts as on it, metres (the 1 mm tie band of the invariants).</summary>
    public const double Band = 1e-3;

    /// <summary>Gets the classes, most specific first.</summary>
    public static IReadOnlyList<string> All { get; } = ["map-edge", "corner", "block-line", "cell-line", "interior"];

    /// <summary>Returns the class of a query (spheres up to the first whose centre is off the map).</summary>
    /// <param name="c">The query.</param>
    /// <returns>One of <see cref="All"/>.</returns>
    public static string Of(OutdoorCase c)
    {
        bool mapEdge = false, block = false, onX = false, onY = false;
        foreach (var s in c.Spheres)
        {
            if (!OutdoorInvariants.OnMap(c.Cell, s.Center) || !float.IsFinite(s.Radius))
            {
                break;
            }

            var (wx, wy) = OutdoorInvariants.World(c.Cell, s.Center);
            double r = s.Radius, edge = 24.0 * Oracle.MapCells;
            mapEdge |= wx - r <= Band || wx + r >= edge - Band || wy - r <= Band || wy + r >= edge - Band;
            onX |= Near(wx, r, ref block);
            onY |= Near(wy, r, ref block);
        }

        return mapEdge ? "map-edge" : onX && onY ? "corner" : block ? "block-line" : onX || onY ? "cell-line" : "interior";
    }

    // Whether the centre or a disc edge lies within Band of a 24 m line; notes whether that line is a 192 m one.
    private static bool Near(double w, double r, ref bool block)
    {
        bool near = false;
        foreach (double p in (ReadOnlySpan<double>)[w, w - r, w + r])
        {
            double line = Math.Round(p / 24.0) * 24.0;
            if (Math.Abs(p - line) <= Band)
            {
                near = true;
                block |= Math.IEEERemainder(line, 192.0) == 0;
            }
        }

        return near;
    }
}
