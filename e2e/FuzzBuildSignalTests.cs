using System.Diagnostics;
using System.Globalization;
using System.Text;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// A signal to <c>acphys fuzz</c> during its build step ends the build with it (issue #17 part 2, issue #19
/// "Orphans": a SIGKILL used to leave <c>dotnet publish</c> running and writing <c>.fuzz/build</c>). Each test runs the
/// real build into a folder of its own, waits until <c>dotnet publish</c> runs, signals acphys, and then requires that
/// every process acphys had started is gone and that the build folder stops changing.
/// </summary>
public sealed class FuzzBuildSignalTests : IDisposable
{
    private readonly string work = Path.Combine(Path.GetTempPath(), "acphys-fuzz-signal-" + Guid.NewGuid().ToString("N"));

    private string BuildDir => Path.Combine(work, "build");

    [Fact(DisplayName = "acphys fuzz SIGKILLed while dotnet publish runs: no process it started survives, the build folder stops changing")]
    public void SigkillDuringBuildLeavesNothingRunning() => KillDuringBuild("KILL");

    [Fact(DisplayName = "acphys fuzz SIGTERMed while dotnet publish runs: it stops the build at once, says so, and leaves nothing running")]
    public void SigtermDuringBuildStopsTheBuild() => KillDuringBuild("TERM");

    public void Dispose()
    {
        if (Directory.Exists(work))
        {
            Directory.Delete(work, recursive: true);
        }
    }

    private void KillDuringBuild(string signal)
    {
        var info = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false, WorkingDirectory = RepoPaths.Root };
        foreach (string a in (string[])[Acphys.Dll, "fuzz", "--target", "toy", "--minutes", "0.1", "--quiet", "--fresh", "--build-dir", BuildDir,
            "--campaign", Path.Combine(work, "campaign"), "--regressions", Path.Combine(work, "regressions")])
        {
            info.ArgumentList.Add(a);
        }

        using var acphys = Process.Start(info)!;
        var stdout = acphys.StandardOutput.ReadToEndAsync();
        var stderr = acphys.StandardError.ReadToEndAsync();
        try
        {
            Assert.True(Poll.Until(TimeSpan.FromSeconds(120), () => Publishes(BuildDir).Count > 0), "dotnet publish never started");
            Thread.Sleep(500); // let MSBuild start its worker nodes; an up-to-date publish still runs for seconds after this
            var started = Descendants(acphys.Id);
            Assert.NotEmpty(started);
            Assert.Equal(0, Kill(signal, acphys.Id));

            if (signal == "TERM")
            {
                Assert.True(acphys.WaitForExit(TimeSpan.FromSeconds(10)), "acphys went on for 10 s after SIGTERM");
                Assert.Equal(2, acphys.ExitCode);
                Assert.Contains("stopped during the build step", stderr.Result, StringComparison.Ordinal);
            }

            // The guard kills the whole group the moment it hears of it: 2 s is slack, not a wait for the build to end.
            bool gone = Poll.Until(TimeSpan.FromSeconds(2), () => started.All(p => !Alive(p.Pid, p.Start)));
            Assert.True(gone, "still running 2 s after SIGKILL/SIGTERM of acphys: " + string.Join("; ", started.Where(p => Alive(p.Pid, p.Start)).Select(p => $"{p.Pid} {p.CommandLine}")));
            string before = Snapshot(BuildDir);
            Thread.Sleep(2000);
            Assert.Equal(before, Snapshot(BuildDir));
        }
        finally
        {
            if (!acphys.HasExited)
            {
                acphys.Kill(entireProcessTree: true);
            }

            foreach (var p in Publishes(BuildDir))
            {
                Kill("KILL", p); // a failing run must not leave its publish behind for the next test
            }
        }
    }

    private static int Kill(string signal, int pid)
    {
        using var kill = Process.Start(new ProcessStartInfo("kill", ["-" + signal, pid.ToString(CultureInfo.InvariantCulture)]) { UseShellExecute = false })!;
        kill.WaitForExit();
        return kill.ExitCode;
    }


    // Every process whose command line runs `dotnet publish ... -o BUILD/...`.
    private static List<int> Publishes(string buildDir) =>
        Processes().Where(p => p.CommandLine.Contains(" publish ", StringComparison.Ordinal) && p.CommandLine.Contains(buildDir, StringComparison.Ordinal)).Select(p => p.Pid).ToList();

    private static List<(int Pid, string Start, string CommandLine)> Descendants(int root)
    {
        var all = Processes().ToList();
        var found = new List<(int, string, string)>();
        var frontier = new Queue<int>([root]);
        while (frontier.TryDequeue(out int parent))
        {
            foreach (var p in all.Where(p => p.Parent == parent))
            {
                found.Add((p.Pid, p.Start, p.CommandLine));
                frontier.Enqueue(p.Pid);
            }
        }

        return found;
    }

    // Alive: the same process (pid and start time) is there and not a zombie.
    private static bool Alive(int pid, string start) => Stat(pid) is { } s && s.Start == start && s.State != "Z";

    private static IEnumerable<(int Pid, int Parent, string Start, string CommandLine)> Processes()
    {
        foreach (string d in Directory.EnumerateDirectories("/proc"))
        {
            if (int.TryParse(Path.GetFileName(d), NumberStyles.None, CultureInfo.InvariantCulture, out int pid) && Stat(pid) is { } s)
            {
                string cmd;
                try
                {
                    cmd = Encoding.UTF8.GetString(File.ReadAllBytes(Path.Combine(d, "cmdline"))).Replace('\0', ' ');
                }
                catch (IOException)
                {
                    continue;
                }
                catch (UnauthorizedAccessException)
                {
                    continue;
                }

                yield return (pid, s.Parent, s.Start, cmd);
            }
        }
    }

    // /proc/PID/stat: "pid (comm) state ppid ..." with the start time as field 22; comm may hold spaces and parentheses.
    private static (string State, int Parent, string Start)? Stat(int pid)
    {
        string text;
        try
        {
            text = File.ReadAllText($"/proc/{pid}/stat");
        }
        catch (IOException)
        {
            return null;
        }
        catch (UnauthorizedAccessException)
        {
            return null;
        }

        var fields = text[(text.LastIndexOf(')') + 2)..].Split(' ');
        return (fields[0], int.Parse(fields[1], CultureInfo.InvariantCulture), fields[19]);
    }

    private static string Snapshot(string dir) => !Directory.Exists(dir)
        ? string.Empty
        : string.Join('\n', Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories).Order(StringComparer.Ordinal)
            .Select(f => new FileInfo(f)).Select(f => $"{f.FullName} {f.Length} {f.LastWriteTimeUtc.Ticks}"));
}
