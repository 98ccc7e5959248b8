using System.Globalization;
using System.Runtime.InteropServices;
using AcPhys.Contract;

namespace AcPhys.Protocol.Child;

/// <summary>The child's end: its process group killed whole (and every group at the tool's exit, the exit hook), its death worded with its stderr tail.</summary>
internal sealed partial class LineProcess : IDisposable
{
    /// <summary>Ends every implementation process group still running (acphys is exiting, a signal stopped the run).</summary>
    internal static void KillAllGroups()
    {
        foreach (int pgid in LiveGroups.Keys)
        {
            if (LiveGroups.TryRemove(pgid, out _))
            {
                _ = NativeKill(-pgid, SigKill);
            }
        }

        foreach (string tag in LiveTags.Keys)
        {
            if (LiveTags.TryRemove(tag, out _))
            {
                ImplProcesses.KillTagged(tag);
            }
        }
    }

    private static void EnsureExitHook()
    {
        if (Interlocked.Exchange(ref exitHooked, 1) == 0)
        {
            AppDomain.CurrentDomain.ProcessExit += (_, _) => KillAllGroups();
        }
    }

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativeKill(int pid, int signal);

    private void KillGroup()
    {
        if (group != 0 && LiveGroups.TryRemove(group, out _))
        {
            _ = NativeKill(-group, SigKill); // the implementation, anything it started, and the watcher
        }

        if (LiveTags.TryRemove(tag, out _))
        {
            ImplProcesses.KillTagged(tag); // what left the group (setsid) but still carries the run's tag
        }
    }

    private AdapterFailureException Died(string what, Exception? inner)
    {
        dead = true;
        string status = process.WaitForExit(2000)
            ? string.Create(CultureInfo.InvariantCulture, $"exited with code {process.ExitCode}")
            : "is still running";
        string message = $"'{commandLine}' {what}; the process {status}{TailText()}";
        return inner is null ? new AdapterFailureException(message) : new AdapterFailureException(message, inner);
    }

    private string TailText()
    {
        // stderr arrives asynchronously: give the last lines a moment to land before quoting them.
        Thread.Sleep(50);
        var lines = tail.ToArray();
        return lines.Length == 0 ? " (nothing on its stderr)" : $". Last stderr lines:{Environment.NewLine}  " + string.Join(Environment.NewLine + "  ", lines.TakeLast(8));
    }

    private void Kill()
    {
        KillGroup();
        try
        {
            process.Kill(entireProcessTree: true);
            process.WaitForExit(2000);
        }
        catch (Exception e) when (e is InvalidOperationException or System.ComponentModel.Win32Exception or NotSupportedException)
        {
            // Already gone.
        }
    }

    private void OnStderr(string? line)
    {
        if (line is null)
        {
            return;
        }

        line = AcPhys.Formats.Values.InputQuote.Line(line, MaxStderrChars); // the child's text: no raw control characters, no endless line (issue 28)
        tail.Enqueue(line);
        while (tail.Count > TailLines && tail.TryDequeue(out _))
        {
        }

        stderrSink?.Invoke(line);
    }
}
