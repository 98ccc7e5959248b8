using System.Runtime.InteropServices;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// What kind of file a path names when it is neither a regular file nor a folder (a FIFO, a device, a socket): such a
/// path is never renamed over (issue 28: <c>--junit /dev/full</c> once replaced the device with a plain file).
/// </summary>
public static class SpecialFile
{
    private const int TypeMask = 0xF000;
    private const int Fifo = 0x1000;
    private const int CharDevice = 0x2000;
    private const int BlockDevice = 0x6000;
    private const int Socket = 0xC000;

    /// <summary>Returns the kind of a special file (following symlinks), or null for a regular file, a folder, a missing path or an unknown platform.</summary>
    /// <param name="path">The path.</param>
    /// <returns>"a FIFO", "a character device", "a block device", "a socket", or null.</returns>
    public static string? KindOf(string path)
    {
        if (!OperatingSystem.IsLinux() || RuntimeInformation.ProcessArchitecture is not (Architecture.X64 or Architecture.Arm64))
        {
            return null;
        }

        var buffer = new byte[256]; // struct stat is 144 (x86-64) or 128 (arm64) bytes
        try
        {
            if (NativeStat(path, buffer) != 0)
            {
                return null; // missing, or not reachable: the caller's own checks say why
            }
        }
        catch (Exception e) when (e is EntryPointNotFoundException or DllNotFoundException)
        {
            return null;
        }

        // st_mode follows st_dev, st_ino and (x86-64 only) the 8-byte st_nlink.
        int mode = BitConverter.ToInt32(buffer, RuntimeInformation.ProcessArchitecture == Architecture.X64 ? 24 : 16);
        return (mode & TypeMask) switch
        {
            Fifo => "a FIFO",
            CharDevice => "a character device",
            BlockDevice => "a block device",
            Socket => "a socket",
            _ => null,
        };
    }

    [DllImport("libc", EntryPoint = "stat", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativeStat([MarshalAs(UnmanagedType.LPUTF8Str)] string path, byte[] buffer);
}
