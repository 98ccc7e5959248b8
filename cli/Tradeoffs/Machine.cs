using System.Globalization;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>Describes the machine a measurement ran on: cores and load average (the machine is shared; timings need both).</summary>
internal static class Machine
{
    /// <summary>Returns e.g. <c>2 cores, load 3.10 2.05 1.40</c>.</summary>
    /// <returns>The text.</returns>
    public static string Describe() => $"{Environment.ProcessorCount} cores, load {Load()}";

    /// <summary>Returns the 1-minute load average, or NaN where /proc/loadavg does not exist.</summary>
    /// <returns>The load.</returns>
    public static double Load1() =>
        double.TryParse(Load().Split(' ')[0], NumberStyles.Float, CultureInfo.InvariantCulture, out double v) ? v : double.NaN;

    private static string Load()
    {
        try
        {
            var parts = File.ReadAllText("/proc/loadavg").Split(' ');
            return string.Join(' ', parts.Take(3));
        }
        catch (IOException)
        {
            return "n/a";
        }
        catch (UnauthorizedAccessException)
        {
            return "n/a";
        }
    }
}
