namespace AcPhys.Fuzz.Runtime;

/// <summary>
/// A persistent-mode forkserver that never forks: one .NET process runs every input afl-fuzz sends, and answers
/// the protocol of <see cref="Protocol"/> as if each input ran in a fresh child.
/// </summary>
internal static unsafe class ForkServer
{
    /// <summary>FS_OPT_ERROR with FS_ERROR_SHMAT: afl-fuzz prints "the shmat() call failed".</summary>
    private const uint ShmAtFailed = 0xF800008F | (8 << 8);

    /// <summary>Serves afl-fuzz until it closes the control pipe.</summary>
    /// <param name="shmId">The value of <c>__AFL_SHM_ID</c>.</param>
    /// <param name="test">The test; an exception escaping it is a crash.</param>
    /// <param name="input">Where the current input is read from.</param>
    /// <returns>The process exit code: 0 when afl-fuzz went away, 1 on a setup failure.</returns>
    public static int Serve(int shmId, Action<ReadOnlySpan<byte>> test, InputSource input)
    {
        nint address = LibC.ShmAt(shmId, 0, 0);
        if (address == -1)
        {
            Pipe.TryWriteWord(Protocol.StatusFd, ShmAtFailed);
            Console.Error.WriteLine($"AcPhys.Fuzz.Runtime: shmat({shmId}) failed");
            return 1;
        }

        Trace.UseMap((byte*)address);

        // The decoy process must not inherit the pipes, or afl-fuzz would not see them close when we exit.
        LibC.Fcntl(Protocol.ControlFd, LibC.F_SETFD, LibC.FD_CLOEXEC);
        LibC.Fcntl(Protocol.StatusFd, LibC.F_SETFD, LibC.FD_CLOEXEC);

        if (!Pipe.TryWriteWord(Protocol.StatusFd, Protocol.Hello))
        {
            Console.Error.WriteLine("AcPhys.Fuzz.Runtime: no forkserver pipe on fd 199 (is this afl-fuzz?)");
            return 1;
        }

        using var decoy = new PidDecoy();
        bool verbose = Environment.GetEnvironmentVariable("ACPHYS_FUZZ_VERBOSE") == "1";
        bool first = true;
        while (Pipe.TryReadWord(Protocol.ControlFd, out uint timedOut))
        {
            if (!Pipe.TryWriteWord(Protocol.StatusFd, (uint)decoy.NextPid(timedOut != 0)))
            {
                break;
            }

            ReadOnlySpan<byte> data = input.Read();
            if (first)
            {
                // Static constructors and first-call paths run only once; a discarded first run keeps them out of
                // the map, so calibration does not see the first input's coverage vary ("unstable" edges).
                Execute(test, data, verbose: false);
                Trace.ClearMap();
                first = false;
            }

            Trace.ResetPrevious();
            uint status = Execute(test, data, verbose);
            if (!Pipe.TryWriteWord(Protocol.StatusFd, status))
            {
                break;
            }
        }

        return 0;
    }

    private static uint Execute(Action<ReadOnlySpan<byte>> test, ReadOnlySpan<byte> data, bool verbose)
    {
        try
        {
            test(data);
            return Protocol.StatusOk;
        }
#pragma warning disable CA1031 // Any exception escaping the test is by definition a finding.
        catch (Exception e)
#pragma warning restore CA1031
        {
            if (verbose)
            {
                Console.Error.WriteLine(e);
            }

            return Protocol.StatusCrash;
        }
    }
}
