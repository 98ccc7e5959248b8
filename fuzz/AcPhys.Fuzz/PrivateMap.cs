using System.Runtime.InteropServices;
using SharpTrace = SharpFuzz.Common.Trace;

namespace AcPhys.Fuzz;

/// <summary>
/// A process-private coverage map for SharpFuzz's probes outside afl-fuzz. SharpFuzz.Common leaves
/// <c>Trace.SharedMem</c> null until <c>Fuzzer.Run</c> attaches afl-fuzz's shared memory, so instrumented code that
/// runs before or without it (seeds, replay, cmin, bench, target discovery) would write through a null pointer.
/// </summary>
internal static unsafe class PrivateMap
{
    /// <summary>Size of SharpFuzz's coverage map (AFL's MAP_SIZE).</summary>
    public const int Size = 1 << 16;

    private static readonly byte* Map = (byte*)NativeMemory.AllocZeroed(Size);

    /// <summary>Gets the current map as a span.</summary>
    public static ReadOnlySpan<byte> Current => new(Map, Size);

    /// <summary>Points the probes at the private map; must run before any instrumented code.</summary>
    public static void Attach() => SharpTrace.SharedMem = Map;

    /// <summary>Attaches and clears the private map and forgets the previous block (one input's coverage).</summary>
    public static void Reset()
    {
        Attach();
        new Span<byte>(Map, Size).Clear();
        SharpTrace.PrevLocation = 0;
    }
}
