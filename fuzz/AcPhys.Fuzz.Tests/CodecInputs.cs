namespace AcPhys.Fuzz.Tests;

/// <summary>The inputs a codec must survive: empty, all zeros, all ones, a megabyte, and random lengths up to twice what it reads.</summary>
internal static class CodecInputs
{
    /// <summary>Builds the inputs (fixed seed).</summary>
    /// <param name="length">Bytes the codec reads.</param>
    /// <param name="randomCount">How many random inputs.</param>
    /// <param name="seed">The random seed.</param>
    /// <returns>The inputs.</returns>
    public static List<byte[]> Edges(int length, int randomCount, int seed)
    {
        var random = new Random(seed);
        var inputs = new List<byte[]> { Array.Empty<byte>(), new byte[length], Enumerable.Repeat((byte)0xFF, length).ToArray() };
        var huge = new byte[1 << 20];
        random.NextBytes(huge);
        inputs.Add(huge);
        for (int i = 0; i < randomCount; i++)
        {
            var input = new byte[random.Next(0, 2 * length)];
            random.NextBytes(input);
            inputs.Add(input);
        }

        return inputs;
    }
}
