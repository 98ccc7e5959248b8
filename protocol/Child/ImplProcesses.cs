using System.Runtime.InteropServices;

namespace AcPhys.Protocol.Child;

/// <summary>
/// The processes of one <c>--impl-cmd</c> run on Linux, found by a tag in their environment: every process the
/// implementation starts inherits it, a <c>setsid</c> grandchild too, which leaves the process group the run kills
/// (issue 28). Used to end them all and to tell "closed its stdout but stays alive" from "did not answer".
/// </summary>
internal static class ImplProcesses
{
    /// <summary>The environment variable that carries the tag.</summary>
    public const string Variable = "ACPHYS_IMPL_RUN";

    private const int SigKill = 9;

    /// <summary>Returns a new tag for one run.</summary>
    /// <returns>The tag.</returns>
    public static string NewTag() => $"{Environment.ProcessId}-{Guid.NewGuid():N}";

    /// <summary>Kills every process that carries <paramref name="tag"/> (a no-op off Linux).</summary>
    /// <param name="tag">The run's tag.</param>
    public static void KillTagged(string tag)
    {
        foreach (int pid in Tagged(tag))
        {
            _ = NativeKill(pid, SigKill);
        }
    }

    /// <summary>
    /// Returns whether the implementation gave up its stdout while still running: processes of the run are alive, but
    /// none other than the wrapping shell (<c>/bin/sh -c COMMAND</c>, which only waits for its child) holds the pipe's
    /// write end. False when it cannot be told (not Linux, no pipe found).
    /// </summary>
    /// <param name="tag">The run's tag.</param>
    /// <param name="pipe">The pipe, as <c>/proc</c> names it (<c>pipe:[N]</c>).</param>
    /// <param name="commandLine">The implementation's command line (to recognise the wrapping shell).</param>
    /// <returns>Whether stdout was closed by a live implementation.</returns>
    public static bool ClosedStdout(string tag, string pipe, string commandLine)
    {
        var alive = Tagged(tag).ToList();
        if (alive.Count == 0)
        {
            return false;
        }

        foreach (int pid in alive)
        {
            if (HoldsForWrite(pid, pipe) && !IsWrapper(pid, commandLine))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Returns the <c>/proc</c> name of an open file descriptor of this process (<c>pipe:[N]</c> for a pipe), or null.</summary>
    /// <param name="fd">The descriptor.</param>
    /// <returns>The link text, or null.</returns>
    public static string? NameOf(int fd)
    {
        try
        {
            return OperatingSystem.IsLinux() ? new FileInfo($"/proc/self/fd/{fd}").LinkTarget : null;
        }
        catch (IOException)
        {
            return null;
        }
    }

    private static IEnumerable<int> Tagged(string tag)
    {
        if (!OperatingSystem.IsLinux())
        {
            yield break;
        }

        byte[] wanted = System.Text.Encoding.UTF8.GetBytes($"{Variable}={tag}\0");
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (!int.TryParse(Path.GetFileName(dir), out int pid) || pid == Environment.ProcessId)
            {
                continue;
            }

            byte[] environ;
            try
            {
                environ = File.ReadAllBytes(Path.Combine(dir, "environ"));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                continue; // gone, or not ours to read
            }

            if (environ.AsSpan().IndexOf(wanted) >= 0)
            {
                yield return pid;
            }
        }
    }

    private static bool HoldsForWrite(int pid, string pipe)
    {
        try
        {
            foreach (string fd in Directory.EnumerateFileSystemEntries($"/proc/{pid}/fd"))
            {
                if (new FileInfo(fd).LinkTarget != pipe)
                {
                    continue;
                }

                // flags in fdinfo are octal; O_ACCMODE 3: 1 = write only, 2 = read and write.
                string info = File.ReadAllText($"/proc/{pid}/fdinfo/{Path.GetFileName(fd)}");
                string? flags = info.Split('\n').FirstOrDefault(l => l.StartsWith("flags:", StringComparison.Ordinal));
                if (flags is null || (Convert.ToInt32(flags["flags:".Length..].Trim(), 8) & 3) != 0)
                {
                    return true;
                }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or FormatException)
        {
            return true; // cannot tell: assume it holds it (then the message stays "did not answer")
        }

        return false;
    }

    private static bool IsWrapper(int pid, string commandLine)
    {
        try
        {
            string[] args = File.ReadAllText($"/proc/{pid}/cmdline").Split('\0');
            return args.Length >= 3 && args[0] == "/bin/sh" && args[1] == "-c" && args[2] == commandLine;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativeKill(int pid, int signal);
}
