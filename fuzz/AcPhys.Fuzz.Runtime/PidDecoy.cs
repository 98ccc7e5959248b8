using System.Diagnostics;

namespace AcPhys.Fuzz.Runtime;

/// <summary>
/// Supplies the "child pid" the forkserver protocol demands for every input, although nothing is forked.
/// </summary>
/// <remarks>
/// afl-fuzz sends SIGKILL to that pid when an input times out. SharpFuzz reports the harness's own pid, so one slow
/// input kills the harness and afl-fuzz aborts with "Unable to communicate with fork server". This class instead
/// reports a sacrificial <c>tail -f /dev/null --pid=HARNESS</c> process: a timeout kills only the decoy (respawned
/// for the next input), afl-fuzz then waits for the slow input's status and files it under hangs/. The decoy exits
/// by itself within a second of the harness. When it cannot be started (or ACPHYS_FUZZ_DECOY=0) the own pid is used.
/// </remarks>
internal sealed class PidDecoy : IDisposable
{
    private readonly bool enabled = Environment.GetEnvironmentVariable("ACPHYS_FUZZ_DECOY") != "0";
    private Process? decoy;

    /// <summary>Returns the pid to report for the next input.</summary>
    /// <param name="previousTimedOut">The control word was non-zero: afl-fuzz killed the last pid.</param>
    /// <returns>A live process id, never 0.</returns>
    public int NextPid(bool previousTimedOut)
    {
        if (!enabled)
        {
            return Environment.ProcessId;
        }

        if (decoy is null || previousTimedOut)
        {
            Respawn();
        }

        return decoy?.Id ?? Environment.ProcessId;
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Kill();
        decoy?.Dispose();
        decoy = null;
    }

    private void Respawn()
    {
        Kill();
        decoy?.Dispose();
        decoy = null;
        try
        {
            var start = new ProcessStartInfo("tail") { UseShellExecute = false };
            start.ArgumentList.Add("-f");
            start.ArgumentList.Add("/dev/null");
            start.ArgumentList.Add($"--pid={Environment.ProcessId}");
            decoy = Process.Start(start);
        }
        catch (System.ComponentModel.Win32Exception)
        {
            decoy = null;
        }
    }

    private void Kill()
    {
        try
        {
            if (decoy is { HasExited: false })
            {
                decoy.Kill();
            }
        }
        catch (InvalidOperationException)
        {
            // Already gone.
        }
    }
}
