using System.Diagnostics;
using System.Globalization;

namespace AcPhys.E2E.Support;

/// <summary>Sends POSIX signals and lists children (signal tests).</summary>
internal static class Signals
{
    /// <summary>Sends a signal with kill(1).</summary>
    /// <param name="signal">The name, e.g. <c>TERM</c>.</param>
    /// <param name="pid">The process.</param>
    public static void Send(string signal, int pid)
    {
        using var kill = Process.Start("kill", ["-s", signal, pid.ToString(CultureInfo.InvariantCulture)]);
        kill.WaitForExit();
    }

    /// <summary>Returns the ids of the processes whose parent is <paramref name="pid"/> (from /proc/*/stat).</summary>
    /// <param name="pid">The parent.</param>
    /// <returns>The children's ids.</returns>
    public static List<int> Children(int pid)
    {
        var children = new List<int>();
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (!int.TryParse(Path.GetFileName(dir), out int child))
            {
                continue;
            }

            try
            {
                // "pid (comm) state ppid ...": the command may hold spaces, so read after its closing parenthesis.
                string stat = File.ReadAllText(Path.Combine(dir, "stat"));
                string[] rest = stat[(stat.LastIndexOf(')') + 2)..].Split(' ');
                if (int.Parse(rest[1], CultureInfo.InvariantCulture) == pid)
                {
                    children.Add(child);
                }
            }
            catch (IOException)
            {
                // Gone meanwhile.
            }
        }

        return children;
    }
}
