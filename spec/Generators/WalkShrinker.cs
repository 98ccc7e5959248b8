using System.Numerics;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Shrinks walks toward one a person reads at a glance: drop steps, merge neighbouring steps, drop extra spheres,
/// round radii, snap the start to the nearest line or corner, round moves. Each pass yields strictly different walks.
/// </summary>
public static class WalkShrinker
{
    /// <summary>Returns simpler candidates, most aggressive first; every candidate starts inside its block, as generated walks do.</summary>
    /// <param name="w">The failing walk.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<Walk> Shrink(Walk w) => Candidates(w).Where(c => c.StartsInBlock).Select(c => c.Normalised()).Where(c => c != w);

    private static IEnumerable<Walk> Candidates(Walk w)
    {
        for (int i = 0; i < w.Steps.Count; i++)
        {
            yield return w with { Steps = [.. w.Steps.Take(i), .. w.Steps.Skip(i + 1)] };
        }

        for (int i = 0; i + 1 < w.Steps.Count; i++)
        {
            yield return w with { Steps = [.. w.Steps.Take(i), w.Steps[i] + w.Steps[i + 1], .. w.Steps.Skip(i + 2)] };
        }

        for (int i = w.Body.Count - 1; i >= 1; i--)
        {
            yield return w with { Body = [.. w.Body.Take(i), .. w.Body.Skip(i + 1)] };
        }

        for (int i = 0; i < w.Body.Count; i++)
        {
            foreach (var r in Snap.Simpler(w.Body[i].Radius).Where(r => r >= 0))
            {
                var body = w.Body.ToArray();
                body[i] = body[i] with { Radius = r };
                yield return w with { Body = body };
            }

            if (i > 0 && w.Body[i].Offset != Vector3.Zero)
            {
                var body = w.Body.ToArray();
                body[i] = body[i] with { Offset = Vector3.Zero };
                yield return w with { Body = body };
            }
        }

        foreach (var x in Snap.Simpler(w.Start.X))
        {
            yield return w with { Start = new Vector3(x, w.Start.Y, w.Start.Z) };
        }

        foreach (var y in Snap.Simpler(w.Start.Y))
        {
            yield return w with { Start = new Vector3(w.Start.X, y, w.Start.Z) };
        }

        for (int i = 0; i < w.Steps.Count; i++)
        {
            var s = w.Steps[i];
            foreach (var x in Snap.Simpler(s.X))
            {
                yield return WithStep(w, i, new Vector2(x, s.Y));
            }

            foreach (var y in Snap.Simpler(s.Y))
            {
                yield return WithStep(w, i, new Vector2(s.X, y));
            }
        }
    }

    private static Walk WithStep(Walk w, int i, Vector2 step)
    {
        var steps = w.Steps.ToArray();
        steps[i] = step;
        return w with { Steps = steps };
    }
}
