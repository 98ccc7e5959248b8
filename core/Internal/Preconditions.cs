namespace AcPhys.Core.Internal;

/// <summary>The only place in core that throws argument exceptions.</summary>
internal static class Preconditions
{
    /// <summary>Throws <see cref="ArgumentOutOfRangeException"/> unless min ≤ value ≤ max.</summary>
    /// <param name="value">The value to check.</param>
    /// <param name="min">Inclusive lower bound.</param>
    /// <param name="max">Inclusive upper bound.</param>
    /// <param name="name">The parameter name.</param>
    internal static void CheckRange(int value, int min, int max, string name)
    {
        if (value < min || value > max)
        {
            throw new ArgumentOutOfRangeException(name, value, $"must be in [{min}, {max}]");
        }
    }
}
