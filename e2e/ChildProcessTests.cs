using System.Diagnostics;
using System.Globalization;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// Children die with their parent (issue 19 item 4): a signal to <c>acphys verify --impl-cmd</c> during the handshake
/// leaves neither the shell nor the implementation running. SIGKILL is the hard one: no handler runs, so the watcher in
/// the implementation's process group has to notice.
/// </summary>
public sealed class ChildProcessTests
{
    [Theory]
    [InlineData("TERM", 3)] // handled: acphys kills the group on its way out
    [InlineData("INT", 3)] // handled the same way
    [InlineData("KILL", 6)] // not handled: the group's watcher polls acphys once a second, TERMs then KILLs the group
    public void ImplementationDiesWithAcphys(string signal, int seconds)
    {
        if (OperatingSystem.IsWindows())
        {
            return;
        }

        // A duration no other test uses, so the processes found are this test's own.
        string sleep = "sleep " + (1003000 + Random.Shared.Next(1, 99999)).ToString(CultureInfo.InvariantCulture);
        var info = new ProcessStartInfo("dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            WorkingDirectory = RepoPaths.Root,
        };
        foreach (string a in new[] { Acphys.Dll, "verify", "--impl-cmd", sleep, "--timeout", "300" })
        {
            info.ArgumentList.Add(a);
        }

        using var acphys = Process.Start(info)!;
        _ = acphys.StandardOutput.ReadToEndAsync();
        _ = acphys.StandardError.ReadToEndAsync();
        try
        {
            Assert.True(Poll.Until(TimeSpan.FromSeconds(60), () => Matching(sleep).Any(c => c.StartsWith(sleep, StringComparison.Ordinal))), "the implementation never started");
            // A job started in the background without job control inherits SIGINT ignored (POSIX), and acphys keeps a
            // signal ignored on entry ignored, as a background job should: then INT must leave it running, and TERM ends it.
            bool ignoredOnEntry = signal == "INT" && IgnoredHere(2);
            Signals.Send(signal, acphys.Id);
            if (ignoredOnEntry)
            {
                Assert.False(acphys.WaitForExit(TimeSpan.FromSeconds(2)), "SIGINT was ignored on entry, yet acphys exited on it");
                Signals.Send("TERM", acphys.Id);
            }

            Assert.True(acphys.WaitForExit(TimeSpan.FromSeconds(30)), "acphys did not exit");
            bool gone = Poll.Until(TimeSpan.FromSeconds(seconds), () => Matching(sleep).Count == 0);
            Assert.True(gone, $"after SIGKILL/TERM/INT ({signal}) these survived {seconds} s: " + string.Join(" | ", Matching(sleep)));
        }
        finally
        {
            if (!acphys.HasExited)
            {
                acphys.Kill(entireProcessTree: true);
            }
        }
    }


    /// <summary>Whether this test process ignores a signal (inherited by the processes it starts): /proc/self/status SigIgn.</summary>
    private static bool IgnoredHere(int signalNumber)
    {
        string? line = File.ReadLines("/proc/self/status").FirstOrDefault(l => l.StartsWith("SigIgn:", StringComparison.Ordinal));
        return line is not null && (ulong.Parse(line["SigIgn:".Length..].Trim(), NumberStyles.HexNumber, CultureInfo.InvariantCulture) & (1UL << (signalNumber - 1))) != 0;
    }

    /// <summary>Returns the command lines of running processes that mention <paramref name="text"/>.</summary>
    private static List<string> Matching(string text)
    {
        var found = new List<string>();
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (!int.TryParse(Path.GetFileName(dir), out _))
            {
                continue;
            }

            try
            {
                string cmdline = File.ReadAllText(Path.Combine(dir, "cmdline")).Replace('\0', ' ').Trim();
                if (cmdline.Contains(text, StringComparison.Ordinal) && !cmdline.Contains("acphys.dll", StringComparison.Ordinal))
                {
                    found.Add(cmdline);
                }
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // The process ended while being read.
            }
        }

        return found;
    }
}
