using System.Runtime.InteropServices;

namespace AcPhys.Fuzz;

/// <summary>
/// Keeps afl-fuzz's fork-server pipes (file descriptors 198 and 199, inherited without close-on-exec) out of every
/// process the harness starts. An <c>--impl-cmd</c> child (and its process-group watcher) would otherwise hold the
/// status pipe's write end: when afl-fuzz kills the harness (a timeout, the end of a campaign) it would wait on that
/// pipe for ever instead of reading end-of-file (seen: afl-fuzz blocked in a pipe read, the harness a zombie).
/// </summary>
internal static partial class ForkServerPipes
{
    private const int ControlFd = 198; // afl's FORKSRV_FD; the status pipe is FORKSRV_FD + 1
    private const int GetFlags = 1; // F_GETFD
    private const int SetFlags = 2; // F_SETFD
    private const int CloseOnExec = 1; // FD_CLOEXEC

    /// <summary>Marks both pipes close-on-exec (a no-op when they are not open, e.g. outside afl-fuzz, or off Linux).</summary>
    public static void KeepFromChildren()
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }

        foreach (int fd in (int[])[ControlFd, ControlFd + 1])
        {
            int flags = Fcntl(fd, GetFlags, 0);
            if (flags >= 0)
            {
                _ = Fcntl(fd, SetFlags, flags | CloseOnExec);
            }
        }
    }

    [LibraryImport("libc", EntryPoint = "fcntl", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static partial int Fcntl(int fd, int command, int argument);
}
