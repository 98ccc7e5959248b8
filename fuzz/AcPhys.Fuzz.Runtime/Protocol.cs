namespace AcPhys.Fuzz.Runtime;

/// <summary>
/// The AFL++ 4.04c forkserver protocol, as the fuzzer side (<c>src/afl-forkserver.c</c>, <c>include/types.h</c>)
/// expects it from a target. See docs/fuzzing.md for the sources and for how later AFL++ versions differ.
/// </summary>
/// <remarks>
/// <list type="number">
/// <item>Handshake: the target writes one 4-byte word on <see cref="StatusFd"/>. Plain 0 is accepted; a word with all
/// bits of <see cref="OptEnabled"/> set carries option bits, here <see cref="OptMapSize"/> and the map size.</item>
/// <item>Per input: afl-fuzz clears the map, writes a 4-byte word on <see cref="ControlFd"/> (1 when the previous run
/// timed out, else 0), reads a 4-byte child pid (must be &gt; 0; afl-fuzz sends it SIGKILL on a timeout), then reads a
/// 4-byte <c>waitpid</c> status: <c>WIFSIGNALED</c> (low 7 bits neither 0 nor 0x7f) is a crash, anything else not.</item>
/// </list>
/// AFL++ 4.20c and later first look for the "new" handshake (the word 0x41464C01, "AFL\x01"), and still accept this
/// old one with a warning; 4.04c knows only the old one.
/// </remarks>
public static class Protocol
{
    /// <summary>Descriptor afl-fuzz writes control words to (FORKSRV_FD).</summary>
    public const int ControlFd = 198;

    /// <summary>Descriptor afl-fuzz reads the hello, pids and statuses from (FORKSRV_FD + 1).</summary>
    public const int StatusFd = 199;

    /// <summary>Environment variable holding the System V shared memory id of the coverage map (SHM_ENV_VAR).</summary>
    public const string ShmEnvVar = "__AFL_SHM_ID";

    /// <summary>FS_OPT_ENABLED: both bits set mark the hello word as carrying options.</summary>
    public const uint OptEnabled = 0x80000001;

    /// <summary>FS_OPT_MAPSIZE: the hello word carries the map size (FS_OPT_SET_MAPSIZE).</summary>
    public const uint OptMapSize = 0x40000000;

    /// <summary>Status reported for an input whose test threw: "killed by SIGABRT" in <c>waitpid</c> encoding.</summary>
    public const uint StatusCrash = 6;

    /// <summary>Status reported for an input whose test returned: "exited with code 0".</summary>
    public const uint StatusOk = 0;

    /// <summary>Gets the hello word: options enabled, map size <see cref="Trace.MapSize"/>.</summary>
    public static uint Hello => OptEnabled | OptMapSize | EncodeMapSize(Trace.MapSize);

    /// <summary>FS_OPT_SET_MAPSIZE: (size − 1) &lt;&lt; 1, for 2 ≤ size ≤ 2^23.</summary>
    /// <param name="size">The map size in bytes.</param>
    /// <returns>The bits to OR into the hello word.</returns>
    public static uint EncodeMapSize(int size)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(size, 2);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(size, 1 << 23);
        return (uint)(size - 1) << 1;
    }

    /// <summary>FS_OPT_GET_MAPSIZE, the fuzzer's decoding (for tests).</summary>
    /// <param name="hello">A hello word.</param>
    /// <returns>The map size it announces.</returns>
    public static int DecodeMapSize(uint hello) => (int)(((hello & 0x00FFFFFE) >> 1) + 1);
}
