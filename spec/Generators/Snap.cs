namespace AcPhys.Spec.Generators;

/// <summary>Simpler versions of a number, for shrinking: nearest line or corner, whole metres, eighths, zero.</summary>
internal static class Snap
{
    /// <summary>Returns candidates simpler than v, each bit-wise different from v and from each other.</summary>
    /// <param name="v">The value.</param>
    /// <returns>Candidates, simplest first.</returns>
    public static IEnumerable<float> Simpler(float v)
    {
        var seen = new HashSet<int> { BitConverter.SingleToInt32Bits(v) };
        foreach (var c in Raw(v))
        {
            if (float.IsFinite(c) && seen.Add(BitConverter.SingleToInt32Bits(c)))
            {
                yield return c;
            }
        }
    }

    private static IEnumerable<float> Raw(float v)
    {
        yield return 0f;
        yield return MathF.Round(v / 192f) * 192f;
        yield return MathF.Round(v / 24f) * 24f;
        yield return MathF.Round(v);
        yield return MathF.Round(v * 8f) / 8f;
    }
}
