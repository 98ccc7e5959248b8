using System.Diagnostics;
using System.Globalization;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Runs a build step (<c>dotnet publish</c>, the instrumenter) so that nothing it started outlives acphys: the step
/// runs in a process group of its own, led by a small <c>/bin/sh</c> guard started through
/// <c>setpriv --pdeathsig TERM</c> and <c>setsid</c>. When acphys dies, even by SIGKILL, the kernel sends the guard
/// SIGTERM and the guard kills its whole group (the step, MSBuild's worker nodes, the compiler); when acphys is asked
/// to stop (SIGTERM, Ctrl-C), it signals the guard the same way. Build servers are the caller's to turn off
/// (<c>--disable-build-servers</c>): they would leave the group by design.
/// </summary>
internal static class GuardedChild
{
    // $$ is the guard: setsid made it the leader of a new group, so "kill 0" reaches every process of the step.
    private const string Guard = "trap 'trap - TERM; kill -KILL 0' TERM INT HUP; \"$@\" & wait $!";

    /// <summary>Runs <paramref name="file"/> to completion in its own guarded process group, capturing stdout and stderr together.</summary>
    /// <param name="file">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <param name="environment">Extra environment variables, or null.</param>
    /// <param name="stop">Cancelled when acphys is asked to stop: the group is killed and <see cref="UsageException"/> thrown.</param>
    /// <returns>The exit code and the output.</returns>
    /// <exception cref="UsageException">Stopped by <paramref name="stop"/>, or setpriv/setsid missing.</exception>
    public static (int Code, string Output) Run(string file, IEnumerable<string> args, IReadOnlyDictionary<string, string>? environment, CancellationToken stop)
    {
        if (AflTools.Which("setpriv") is null || AflTools.Which("setsid") is null)
        {
            throw new UsageException("setpriv and setsid (util-linux) are needed to stop the build when acphys dies; install util-linux");
        }

        var info = new ProcessStartInfo("setpriv") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in (string[])["--pdeathsig", "TERM", "--", "setsid", "/bin/sh", "-c", Guard, "sh", file, .. args])
        {
            info.ArgumentList.Add(a);
        }

        foreach (var (k, v) in environment ?? new Dictionary<string, string>())
        {
            info.Environment[k] = v;
        }

        // The parent-death signal follows the thread that forked: start from this (the campaign's) thread.
        using var p = Process.Start(info)!;
        using var registration = stop.Register(() => Signal(p));
        var stderr = p.StandardError.ReadToEndAsync(CancellationToken.None);
        string stdout = p.StandardOutput.ReadToEnd();
        p.WaitForExit();
        if (stop.IsCancellationRequested)
        {
            throw new UsageException($"stopped during the build step ({Path.GetFileName(file)}); nothing it started is left running");
        }

        return (p.ExitCode, stdout + stderr.Result);
    }

    private static void Signal(Process guard)
    {
        if (!guard.HasExited)
        {
            AflTools.Run("kill", "-TERM", guard.Id.ToString(CultureInfo.InvariantCulture));
        }
    }
}
