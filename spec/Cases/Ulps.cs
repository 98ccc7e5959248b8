namespace AcPhys.Spec.Cases;

/// <summary>Steps a float32 by whole units in the last place: the neighbours of a line that boundary classes and generators need.</summary>
public static class Ulps
{
    /// <summary>Returns <paramref name="v"/> moved by <paramref name="count"/> ULPs (up when positive, down when negative).</summary>
    /// <param name="v">The value.</param>
    /// <param name="count">Signed number of steps.</param>
    /// <returns>The neighbour.</returns>
    public static float Step(float v, int count)
    {
        for (; count > 0; count--)
        {
            v = MathF.BitIncrement(v);
        }

        for (; count < 0; count++)
        {
            v = MathF.BitDecrement(v);
        }

        return v;
    }
}
