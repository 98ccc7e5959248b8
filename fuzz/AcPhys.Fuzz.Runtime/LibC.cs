using System.Runtime.InteropServices;

namespace AcPhys.Fuzz.Runtime;

/// <summary>The few libc calls the forkserver needs (Linux only).</summary>
internal static unsafe partial class LibC
{
    /// <summary>errno for an interrupted system call.</summary>
    internal const int EINTR = 4;

    /// <summary><c>fcntl</c> command: set the descriptor flags.</summary>
    internal const int F_SETFD = 2;

    /// <summary>Descriptor flag: close on exec.</summary>
    internal const int FD_CLOEXEC = 1;

    /// <summary><c>lseek</c> whence: relative to the current position.</summary>
    internal const int SEEK_CUR = 1;

    private const string Library = "libc";

    [LibraryImport(Library, EntryPoint = "shmat", SetLastError = true)]
    internal static partial nint ShmAt(int shmid, nint address, int flags);

    [LibraryImport(Library, EntryPoint = "read", SetLastError = true)]
    internal static partial nint Read(int fd, byte* buffer, nint count);

    [LibraryImport(Library, EntryPoint = "write", SetLastError = true)]
    internal static partial nint Write(int fd, byte* buffer, nint count);

    [LibraryImport(Library, EntryPoint = "lseek", SetLastError = true)]
    internal static partial long LSeek(int fd, long offset, int whence);

    [LibraryImport(Library, EntryPoint = "fcntl", SetLastError = true)]
    internal static partial int Fcntl(int fd, int command, int argument);
}
