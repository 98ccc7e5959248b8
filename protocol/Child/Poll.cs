using System.Runtime.InteropServices;

namespace AcPhys.Protocol.Child;

/// <summary>poll(2) on one descriptor (Linux and macOS): how the tool waits for a child's answer with a timeout on the
/// thread that then reads it (<see cref="LineProcess"/>).</summary>
internal static class Poll
{
    private const short In = 0x001;
    private const int Interrupted = 4; // EINTR

    /// <summary>Waits until <paramref name="fd"/> can be read without blocking: input, its end, or an error.</summary>
    /// <param name="fd">The descriptor.</param>
    /// <param name="milliseconds">The most to wait; -1 waits for ever, 0 only looks.</param>
    /// <returns>False when the time ran out first, or a signal interrupted the wait (the caller waits again for what is left).</returns>
    /// <exception cref="IOException">poll itself failed.</exception>
    public static bool Readable(int fd, int milliseconds)
    {
        var one = new PollFd { Fd = fd, Events = In };
        int ready = NativePoll(ref one, 1, milliseconds);
        if (ready >= 0)
        {
            return ready > 0; // POLLIN, POLLHUP or POLLERR: the read that follows returns at once
        }

        int errno = Marshal.GetLastPInvokeError();
        return errno == Interrupted ? false : throw new IOException($"poll failed (errno {errno})");
    }

    /// <summary>Asks Linux for a pipe of <paramref name="bytes"/> (F_SETPIPE_SZ); a refusal or another system keeps the pipe as it is.</summary>
    /// <param name="fd">Either end of the pipe.</param>
    /// <param name="bytes">The size wanted (at most /proc/sys/fs/pipe-max-size for an unprivileged process).</param>
    /// <returns>True when the pipe holds that much now.</returns>
    public static bool GrowPipe(int fd, int bytes) => OperatingSystem.IsLinux() && NativeFcntl(fd, SetPipeSize, bytes) >= bytes;

    private const int SetPipeSize = 1031; // F_SETPIPE_SZ (Linux)

    [DllImport("libc", EntryPoint = "fcntl", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativeFcntl(int fd, int command, int argument);

    [DllImport("libc", EntryPoint = "poll", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativePoll(ref PollFd fds, nuint count, int timeout);

    [StructLayout(LayoutKind.Sequential)]
    private struct PollFd
    {
        public int Fd;
        public short Events;
        public short Revents;
    }
}
