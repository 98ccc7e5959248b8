using System.Text;

namespace AcPhys.Fuzz.Instrument;

/// <summary>
/// Compile-time block ids: pseudo-random in [0, 2^16), as AFL's <c>R(MAP_SIZE)</c>, but derived from
/// (seed, assembly, method token, IL offset) instead of a live RNG, so that instrumenting the same build twice gives
/// the same map layout (comparable coverage across runs and machines).
/// </summary>
internal sealed class BlockIds
{
    private readonly ulong assemblyKey;

    /// <summary>Initializes a new instance of the <see cref="BlockIds"/> class.</summary>
    /// <param name="assemblyName">The simple name of the assembly being instrumented.</param>
    /// <param name="seed">A user seed; change it to get another layout.</param>
    public BlockIds(string assemblyName, ulong seed) => assemblyKey = Mix(Fnv1a(assemblyName) ^ seed);

    /// <summary>Returns the id of the block starting at <paramref name="ilOffset"/> of the method.</summary>
    /// <param name="methodToken">The method's metadata token.</param>
    /// <param name="ilOffset">The block's original IL offset.</param>
    /// <returns>An id in [0, 65536).</returns>
    public int Get(uint methodToken, int ilOffset) =>
        (int)(Mix(assemblyKey ^ ((ulong)methodToken << 32) ^ (uint)ilOffset) & 0xFFFF);

    // SplitMix64 finalizer: a cheap full-avalanche mix.
    private static ulong Mix(ulong z)
    {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }

    private static ulong Fnv1a(string text)
    {
        ulong hash = 0xCBF29CE484222325UL;
        foreach (byte b in Encoding.UTF8.GetBytes(text))
        {
            hash = (hash ^ b) * 0x100000001B3UL;
        }

        return hash;
    }
}
