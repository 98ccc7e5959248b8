using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Studies.Numerics;

/// <summary>
/// Outdoor queries with full 24-bit float32 mantissas (the suite's generators use a 2⁻¹⁰ m grid, where float32 is
/// exact): uniform points, points at a log-uniform distance (0.5 m down to 1e-9 m) from a 24 m line in the block
/// frame or a neighbour's, and disc edges at such a distance from a line. Deterministic for a seed.
/// </summary>
public static class FineFloats
{
    /// <summary>Returns n queries.</summary>
    /// <param name="seed">The seed.</param>
    /// <param name="n">How many.</param>
    /// <returns>The queries.</returns>
    public static OutdoorCase[] Cases(int seed, int n)
    {
        var random = new Random(seed);
        var cases = new OutdoorCase[n];
        for (int i = 0; i < n; i++)
        {
            int bx = random.Next(10) == 0 ? random.Next(2) * 0xFE : random.Next(0xFF);
            int by = random.Next(10) == 0 ? random.Next(2) * 0xFE : random.Next(0xFF);
            var cell = new CellId((byte)bx, (byte)by, (ushort)(1 + random.Next(64)));
            var spheres = new Sphere[random.Next(4) == 0 ? 2 : 1];
            for (int s = 0; s < spheres.Length; s++)
            {
                float r = Radius(random);
                spheres[s] = new Sphere(new Vector3(Coordinate(random, r), Coordinate(random, r), 0.5f), r);
            }

            cases[i] = new OutdoorCase(cell, spheres);
        }

        return cases;
    }

    private static float Radius(Random random) => random.Next(5) switch
    {
        0 => (float)(30 * random.NextDouble()),
        1 => (float)Math.Pow(10, -6 + (7.5 * random.NextDouble())),
        2 => ExtremePoints.Radii[random.Next(ExtremePoints.Radii.Count)],
        _ => (float)(0.25 + (2 * random.NextDouble())),
    };

    private static float Coordinate(Random random, float r)
    {
        double line = 24.0 * random.Next(-8, 17);
        double offset = (random.Next(2) == 0 ? -1 : 1) * Math.Pow(10, -9 + (8.7 * random.NextDouble()));
        return random.Next(10) switch
        {
            < 3 => (float)((216 * random.NextDouble()) - 24),
            < 7 => (float)(line + offset),
            _ => (float)(line + ((random.Next(2) == 0 ? -1 : 1) * r) + offset),
        };
    }
}
