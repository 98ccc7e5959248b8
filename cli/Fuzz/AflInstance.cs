using System.Diagnostics;
using AcPhys.Fuzz.Targets;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// One afl-fuzz process (-M main or -S secN) on the campaign's sync folder. It is started through
/// <c>setpriv --pdeathsig TERM</c>, so that if acphys itself dies (even by SIGKILL) afl-fuzz gets SIGTERM, stops
/// cleanly and leaves its queue and crashes for the next run to resume.
/// </summary>
internal sealed class AflInstance : IDisposable
{
    private readonly Process process;

    private AflInstance(string name, string dir, Process process)
    {
        Name = name;
        Dir = dir;
        this.process = process;
    }

    /// <summary>Gets the instance name.</summary>
    public string Name { get; }

    /// <summary>Gets the instance's folder in the sync folder.</summary>
    public string Dir { get; }

    /// <summary>Gets a value indicating whether afl-fuzz has exited.</summary>
    public bool HasExited => process.HasExited;

    /// <summary>Gets the exit code (after exit).</summary>
    public int ExitCode => process.ExitCode;

    /// <summary>Starts one instance. Must be called on a thread that lives as long as the campaign (the parent-death signal follows the thread).</summary>
    /// <param name="s">The settings.</param>
    /// <param name="index">0 for the main instance.</param>
    /// <param name="seeds">The -i folder.</param>
    /// <param name="dictionary">The -x file, or null.</param>
    /// <returns>The instance.</returns>
    public static AflInstance Start(FuzzSettings s, int index, string seeds, string? dictionary)
    {
        string name = FuzzSettings.InstanceName(index);
        var info = new ProcessStartInfo("/bin/sh") { UseShellExecute = false };
        info.ArgumentList.Add("-c");
        info.ArgumentList.Add("exec setpriv --pdeathsig TERM -- \"$@\" >\"$ACPHYS_AFL_LOG\" 2>&1");
        info.ArgumentList.Add("sh");
        string[] args =
        [
            "afl-fuzz", "-i", seeds, "-o", s.SyncDir, index == 0 ? "-M" : "-S", name, "-V", s.Seconds.ToString(System.Globalization.CultureInfo.InvariantCulture),
            "-t", s.TimeoutMs.ToString(System.Globalization.CultureInfo.InvariantCulture), "-m", "none",
            .. dictionary is null ? Array.Empty<string>() : ["-x", dictionary],
            "--", s.Harness, s.Target.Name,
        ];
        foreach (string a in args)
        {
            info.ArgumentList.Add(a);
        }

        var env = info.Environment;
        env["ACPHYS_AFL_LOG"] = Path.Combine(s.LogDir, $"afl-{name}.log");
        env["ACPHYS_FAULT"] = s.Fault ?? string.Empty;
        env[PortSubject.ImplVariable] = s.Port.AssemblyPath is null ? string.Empty : s.PortAssembly; // the instrumented copy
        env[PortSubject.CommandVariable] = s.Port.Command ?? string.Empty;
        env[PortSubject.TimeoutVariable] = s.Port.Timeout.TotalSeconds.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture);
        env["AFL_SKIP_BIN_CHECK"] = "1"; // the dotnet apphost carries no AFL marker strings
        env["AFL_NO_UI"] = "1";
        env["AFL_SKIP_CPUFREQ"] = "1";
        env["AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES"] = "1";
        env["AFL_TRY_AFFINITY"] = "1";
        env["AFL_SKIP_CRASHES"] = "1";
        env["AFL_AUTORESUME"] = "1"; // an existing sync folder is resumed (as -i -), never wiped
        env["AFL_FORKSRV_INIT_TMOUT"] = Environment.GetEnvironmentVariable("AFL_FORKSRV_INIT_TMOUT") ?? "60000";
        if (s.UntilCrash)
        {
            env["AFL_BENCH_UNTIL_CRASH"] = "1";
        }

        return new AflInstance(name, Path.Combine(s.SyncDir, name), Process.Start(info)!);
    }

    /// <summary>Asks afl-fuzz to stop (SIGINT: it finishes the current input and writes its stats).</summary>
    public void Interrupt()
    {
        if (!process.HasExited)
        {
            AflTools.Run("kill", "-INT", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
    }

    /// <summary>Waits for the exit; kills it after <paramref name="grace"/>.</summary>
    /// <param name="grace">How long to wait.</param>
    /// <returns>True when it exited on its own.</returns>
    public bool WaitOrKill(TimeSpan grace)
    {
        if (process.WaitForExit(grace))
        {
            return true;
        }

        process.Kill();
        process.WaitForExit();
        return false;
    }

    /// <summary>Reads the instance's stats.</summary>
    /// <returns>The stats.</returns>
    public InstanceStats Stats() => InstanceStats.Read(Dir);

    /// <inheritdoc/>
    public void Dispose() => process.Dispose();
}
