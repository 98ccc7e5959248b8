using AcPhys.Fuzz.Runtime;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>Plays afl-fuzz 4.04c against <see cref="ForkServer"/> in-process: fds 198/199, a System V map, @@ input.</summary>
[Collection(TraceCollection.Name)]
public sealed unsafe class ForkServerTests
{
    private const int ProbeId = 0x1234;

    [Fact]
    public void Speaks_the_afl_4_04c_forkserver_protocol()
    {
        if (!OperatingSystem.IsLinux())
        {
            return; // System V shm and fds 198/199: Linux only.
        }

        Assert.True(Posix.Fcntl(Protocol.ControlFd, Posix.FGetFd, 0) == -1 && Posix.Fcntl(Protocol.StatusFd, Posix.FGetFd, 0) == -1,
            "fds 198/199 are already open in the test host");

        int shmId = Posix.ShmGet(Posix.IpcPrivate, Trace.MapSize, Posix.IpcCreat | 0x180);
        Assert.True(shmId >= 0, "shmget failed");
        byte* map = (byte*)Posix.ShmAt(shmId, 0, 0);
        byte* privateMap = Trace.Map;
        int* control = stackalloc int[2];
        int* status = stackalloc int[2];
        Assert.Equal(0, Posix.Pipe(control));
        Assert.Equal(0, Posix.Pipe(status));
        Posix.Dup2(control[0], Protocol.ControlFd);
        Posix.Dup2(status[1], Protocol.StatusFd);
        Posix.Close(control[0]);
        Posix.Close(status[1]);
        int toServer = control[1], fromServer = status[0];

        // afl-fuzz's own pipe ends are not in the target; here they are, so keep them out of the decoy process.
        Posix.Fcntl(toServer, Posix.FSetFd, Posix.FdCloexec);
        Posix.Fcntl(fromServer, Posix.FSetFd, Posix.FdCloexec);
        string input = Path.GetTempFileName();

        // If the server misbehaves, closing the only write end of the status pipe turns a blocked read into EOF.
        using var watchdog = new Timer(_ => Posix.Close(Protocol.StatusFd), null, TimeSpan.FromSeconds(60), Timeout.InfiniteTimeSpan);
        try
        {
            int exitCode = -1;
            var server = new Thread(() => exitCode = ForkServer.Serve(shmId, Test, new InputSource(input))) { IsBackground = true };
            server.Start();

            uint hello = Posix.ReadWord(fromServer);
            Assert.Equal(Protocol.OptEnabled, hello & Protocol.OptEnabled);
            Assert.Equal(Protocol.OptMapSize, hello & Protocol.OptMapSize);
            Assert.Equal(65536, Protocol.DecodeMapSize(hello));
            Assert.Equal(0xC001FFFFu, hello);

            var (pid1, ok) = RunOne(toServer, fromServer, map, input, "hello"u8, timedOut: false);
            Assert.Equal(Protocol.StatusOk, ok);
            Assert.True(pid1 > 0);
            Assert.Equal(1, map[ProbeId]); // counted once: the warm-up run of the first input was cleared

            var (_, crash) = RunOne(toServer, fromServer, map, input, "AC!P"u8, timedOut: false);
            Assert.Equal(Protocol.StatusCrash, crash);
            Assert.True((crash & 0x7F) != 0 && (crash & 0x7F) != 0x7F, "WIFSIGNALED must hold for a crash");

            // afl-fuzz killed the previous "child" on a timeout: the server must survive and hand out a live pid.
            if (pid1 != Environment.ProcessId)
            {
                System.Diagnostics.Process.GetProcessById(pid1).Kill();
            }

            var (pid3, after) = RunOne(toServer, fromServer, map, input, "ok"u8, timedOut: true);
            Assert.Equal(Protocol.StatusOk, after);
            Assert.NotEqual(Environment.ProcessId == pid1 ? 0 : pid1, pid3);

            Posix.Close(toServer); // afl-fuzz goes away
            toServer = -1;
            Assert.True(server.Join(TimeSpan.FromSeconds(30)), "server did not stop at end of file");
            Assert.Equal(0, exitCode);
        }
        finally
        {
            Trace.UseMap(privateMap);
            if (toServer >= 0)
            {
                Posix.Close(toServer);
            }

            Posix.Close(fromServer);
            Posix.Close(Protocol.ControlFd);
            Posix.Close(Protocol.StatusFd);
            Posix.ShmDt((nint)map);
            Posix.ShmCtl(shmId, Posix.IpcRmid, 0);
            File.Delete(input);
        }
    }

    private static void Test(ReadOnlySpan<byte> data)
    {
        Trace.Hit(ProbeId);
        if (data.StartsWith("AC!P"u8))
        {
            throw new InvalidOperationException("planted");
        }
    }

    // One afl-fuzz iteration: write the input, clear the map, send the control word, read pid and status.
    private static (int Pid, uint Status) RunOne(int toServer, int fromServer, byte* map, string input, ReadOnlySpan<byte> data, bool timedOut)
    {
        File.WriteAllBytes(input, data.ToArray());
        new Span<byte>(map, Trace.MapSize).Clear();
        Posix.WriteWord(toServer, timedOut ? 1u : 0u);
        int pid = (int)Posix.ReadWord(fromServer);
        uint status = Posix.ReadWord(fromServer);
        return (pid, status);
    }
}
