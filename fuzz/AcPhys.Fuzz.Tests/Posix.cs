using System.Runtime.InteropServices;

namespace AcPhys.Fuzz.Tests;

/// <summary>libc calls the protocol test needs to play afl-fuzz's side.</summary>
internal static unsafe partial class Posix
{
    public const int IpcPrivate = 0;
    public const int IpcCreat = 0x200;
    public const int IpcRmid = 0;
    public const int FGetFd = 1;
    public const int FSetFd = 2;
    public const int FdCloexec = 1;

    [LibraryImport("libc", EntryPoint = "pipe", SetLastError = true)]
    public static partial int Pipe(int* fds);

    [LibraryImport("libc", EntryPoint = "dup2", SetLastError = true)]
    public static partial int Dup2(int from, int to);

    [LibraryImport("libc", EntryPoint = "close", SetLastError = true)]
    public static partial int Close(int fd);

    [LibraryImport("libc", EntryPoint = "fcntl", SetLastError = true)]
    public static partial int Fcntl(int fd, int command, int argument);

    [LibraryImport("libc", EntryPoint = "read", SetLastError = true)]
    public static partial nint Read(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "write", SetLastError = true)]
    public static partial nint Write(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "shmget", SetLastError = true)]
    public static partial int ShmGet(int key, nint size, int flags);

    [LibraryImport("libc", EntryPoint = "shmat", SetLastError = true)]
    public static partial nint ShmAt(int id, nint address, int flags);

    [LibraryImport("libc", EntryPoint = "shmdt", SetLastError = true)]
    public static partial int ShmDt(nint address);

    [LibraryImport("libc", EntryPoint = "shmctl", SetLastError = true)]
    public static partial int ShmCtl(int id, int command, nint buffer);

    public static uint ReadWord(int fd)
    {
        uint value;
        if (Read(fd, (byte*)&value, 4) != 4)
        {
            throw new IOException("short read from the status pipe");
        }

        return value;
    }

    public static void WriteWord(int fd, uint value)
    {
        if (Write(fd, (byte*)&value, 4) != 4)
        {
            throw new IOException("short write to the control pipe");
        }
    }
}
