using System.Diagnostics;
using System.Text;

namespace AcPhys.E2E.Support;

/// <summary>Runs the built acphys tool (copied next to the tests by the project reference) as a child process.</summary>
internal static class Acphys
{
    /// <summary>Gets the acphys.dll beside the tests.</summary>
    public static string Dll => Path.Combine(AppContext.BaseDirectory, "acphys.dll");

    /// <summary>Gets the command line that runs <c>acphys serve</c> (for --impl-cmd).</summary>
    public static string ServeCommand => $"dotnet {Dll} serve";

    /// <summary>Gets the command line of the Python example, absolute.</summary>
    public static string PythonExample => "python3 " + Path.Combine(RepoPaths.Root, "examples", "python", "acphys_impl.py");

    /// <summary>Returns the sh command line of a test implementation in e2e/Impls.</summary>
    /// <param name="name">The script name.</param>
    /// <returns>The command line.</returns>
    public static string Script(string name) => "sh " + Path.Combine(RepoPaths.Root, "e2e", "Impls", name);

    /// <summary>Runs acphys with arguments and waits for it (at most six minutes: a guard against a hung child, not a speed target; a loaded 2-core machine needs minutes for the out-of-process runs).</summary>
    /// <param name="args">The arguments.</param>
    /// <param name="environment">Extra environment variables.</param>
    /// <returns>Exit code, stdout, stderr and wall time.</returns>
    public static Run Run(IEnumerable<string> args, IReadOnlyDictionary<string, string>? environment = null)
    {
        var info = Info(args, environment);
        return RunToEnd(info, "acphys " + string.Join(' ', info.ArgumentList));
    }

    /// <summary>Starts a process whose output is redirected and waits for it, killing its tree after six minutes.</summary>
    /// <param name="info">The start info (stdout and stderr redirected).</param>
    /// <param name="label">How a timeout names the command.</param>
    /// <returns>Exit code, stdout, stderr and wall time.</returns>
    public static Run RunToEnd(ProcessStartInfo info, string label)
    {
        var stopwatch = Stopwatch.StartNew();
        using var process = Process.Start(info)!;
        var stdout = process.StandardOutput.ReadToEndAsync();
        var stderr = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(6)))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException(label + " ran for more than six minutes");
        }

        return new Run(process.ExitCode, stdout.Result, stderr.Result, stopwatch.Elapsed);
    }

    /// <summary>Describes a run of acphys (stdout and stderr redirected; stdin too when asked), for tests that drive the process themselves.</summary>
    /// <param name="args">The arguments.</param>
    /// <param name="environment">Extra environment variables.</param>
    /// <param name="stdin">True to redirect stdin.</param>
    /// <returns>The start info.</returns>
    public static ProcessStartInfo Info(IEnumerable<string> args, IReadOnlyDictionary<string, string>? environment = null, bool stdin = false)
    {
        var info = new ProcessStartInfo("dotnet")
        {
            RedirectStandardInput = stdin,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
            WorkingDirectory = RepoPaths.Root,
        };
        info.ArgumentList.Add(Dll);
        foreach (var a in args)
        {
            info.ArgumentList.Add(a);
        }

        info.Environment["ACPHYS_FAILURES"] = Path.Combine(Path.GetTempPath(), "acphys-e2e-failures");
        info.Environment["ACPHYS_COMMAND"] = "acphys";
        info.Environment.Remove("ACPHYS_PROFILE");
        foreach (var (k, v) in environment ?? new Dictionary<string, string>())
        {
            info.Environment[k] = v;
        }

        return info;
    }
}

/// <summary>The outcome of one acphys run.</summary>
/// <param name="Exit">The exit code.</param>
/// <param name="Out">Stdout.</param>
/// <param name="Err">Stderr.</param>
/// <param name="Elapsed">Wall time.</param>
internal sealed record Run(int Exit, string Out, string Err, TimeSpan Elapsed)
{
    /// <inheritdoc/>
    public override string ToString() => $"exit {Exit} after {Elapsed.TotalSeconds:0.0} s\n--- stdout ---\n{Out}\n--- stderr ---\n{Err}";
}
