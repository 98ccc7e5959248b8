using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Generators;

/// <summary>Shrinks outdoor queries: fewer spheres, simpler radii, centres snapped to lines, corners and whole metres.</summary>
internal static class OutdoorShrinker
{
    /// <summary>Returns simpler candidates.</summary>
    /// <param name="c">The failing query.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<OutdoorCase> Shrink(OutdoorCase c)
    {
        for (int i = c.Spheres.Count - 1; i >= 0 && c.Spheres.Count > 1; i--)
        {
            yield return c with { Spheres = [.. c.Spheres.Take(i), .. c.Spheres.Skip(i + 1)] };
        }

        if (c.Spheres.Count == 0)
        {
            foreach (var x in Snap.Simpler(c.Origin.X))
            {
                yield return c with { Origin = c.Origin with { X = x } };
            }

            foreach (var y in Snap.Simpler(c.Origin.Y))
            {
                yield return c with { Origin = c.Origin with { Y = y } };
            }
        }

        for (int i = 0; i < c.Spheres.Count; i++)
        {
            var s = c.Spheres[i];
            foreach (var r in Snap.Simpler(s.Radius).Where(r => r >= 0))
            {
                yield return With(c, i, s with { Radius = r });
            }

            foreach (var x in Snap.Simpler(s.Center.X))
            {
                yield return With(c, i, s with { Center = new Vector3(x, s.Center.Y, s.Center.Z) });
            }

            foreach (var y in Snap.Simpler(s.Center.Y))
            {
                yield return With(c, i, s with { Center = new Vector3(s.Center.X, y, s.Center.Z) });
            }
        }
    }

    private static OutdoorCase With(OutdoorCase c, int i, Sphere s)
    {
        var spheres = c.Spheres.ToArray();
        spheres[i] = s;
        return c with { Spheres = spheres };
    }
}
