using System.Diagnostics;
using System.Globalization;

namespace AcPhys.E2E.Support;

/// <summary>Watches a process's peak resident memory (VmHWM in /proc/PID/status) while it runs (the size-limit tests).</summary>
internal sealed class PeakMemory
{
    private readonly Task<long> watch;

    private PeakMemory(Process process) => watch = Task.Run(() =>
    {
        long peak = 0;
        while (!process.HasExited)
        {
            peak = Math.Max(peak, Read(process.Id));
            Thread.Sleep(20);
        }

        return peak;
    });

    /// <summary>Starts watching.</summary>
    /// <param name="process">The running process.</param>
    /// <returns>The watcher.</returns>
    public static PeakMemory Watch(Process process) => new(process);

    /// <summary>Returns the largest peak seen, in MiB, once the process has exited.</summary>
    /// <returns>MiB.</returns>
    public long MiB() => watch.Result / 1024;

    /// <summary>Returns the process's peak so far, in MiB (0 when it is gone).</summary>
    /// <param name="process">The process.</param>
    /// <returns>MiB.</returns>
    public static long Now(Process process) => Read(process.Id) / 1024;

    private static long Read(int pid)
    {
        try
        {
            foreach (string line in File.ReadLines($"/proc/{pid}/status"))
            {
                if (line.StartsWith("VmHWM:", StringComparison.Ordinal))
                {
                    return long.Parse(line["VmHWM:".Length..].Trim().Split(' ')[0], CultureInfo.InvariantCulture);
                }
            }
        }
        catch (IOException)
        {
            // Gone between the check and the read.
        }

        return 0;
    }
}
