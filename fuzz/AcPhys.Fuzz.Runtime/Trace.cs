using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace AcPhys.Fuzz.Runtime;

/// <summary>
/// The coverage probe that instrumented assemblies call at the start of every basic block: AFL's edge
/// coverage, <c>map[cur ^ prev]++; prev = cur &gt;&gt; 1</c>, over a 64 KiB map.
/// </summary>
/// <remarks>
/// <para>
/// <see cref="Map"/> starts as a private zeroed buffer, so instrumented code also runs (and counts into a
/// buffer nobody reads) outside afl-fuzz, e.g. in ordinary tests. <see cref="Fuzzer"/> points it at AFL's
/// System V shared memory when <c>__AFL_SHM_ID</c> is set.
/// </para>
/// <para>
/// Not thread-safe by design (as AFL's own <c>__afl_prev_loc</c> in single-threaded targets): a harness runs one
/// input at a time on one thread. Counters never wrap to zero (AFL++ "NeverZero"): 255 + 1 becomes 1.
/// </para>
/// </remarks>
public static unsafe class Trace
{
    /// <summary>Size of the coverage map in bytes (AFL++ 4.04c <c>MAP_SIZE</c>, 2^16).</summary>
    public const int MapSize = 1 << 16;

    /// <summary>Mask that keeps block ids inside the map.</summary>
    public const int IdMask = MapSize - 1;

    private static byte* map = AllocatePrivateMap();
    private static int previous;

    /// <summary>Gets the current coverage map (AFL's shared memory, or the private buffer).</summary>
    public static byte* Map => map;

    /// <summary>Records the edge from the previous block to block <paramref name="id"/>.</summary>
    /// <param name="id">The block's compile-time id, in [0, <see cref="MapSize"/>).</param>
    /// <remarks>Instrumented code calls this; the JIT inlines it into the caller.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hit(int id)
    {
        byte* cell = map + ((id ^ previous) & IdMask);
        int next = *cell + 1;
        *cell = (byte)(next + (next >> 8)); // NeverZero: 256 -> 1
        previous = id >> 1;
    }

    /// <summary>Forgets the previous block, so that the next input's first edge does not depend on the last input.</summary>
    public static void ResetPrevious() => previous = 0;

    /// <summary>Clears the whole current map.</summary>
    public static void ClearMap() => new Span<byte>(map, MapSize).Clear();

    /// <summary>Counts the non-zero cells of the current map (for diagnostics and tests).</summary>
    /// <returns>The number of distinct edges hit since the map was last cleared (modulo collisions).</returns>
    public static int CountEdges()
    {
        int count = 0;
        foreach (byte b in new ReadOnlySpan<byte>(map, MapSize))
        {
            if (b != 0)
            {
                count++;
            }
        }

        return count;
    }

    /// <summary>Points the probe at another map of <see cref="MapSize"/> bytes (AFL's shared memory).</summary>
    /// <param name="newMap">The map; must stay valid for the life of the process.</param>
    internal static void UseMap(byte* newMap)
    {
        map = newMap;
        previous = 0;
    }

    private static byte* AllocatePrivateMap() => (byte*)NativeMemory.AllocZeroed(MapSize);
}
