using System.Diagnostics;

namespace AcPhys.Cli.Fuzz;

/// <summary>Finds afl-fuzz, installing Debian's <c>afl++</c> package with apt-get when it is missing (root or passwordless sudo).</summary>
internal static class AflTools
{
    /// <summary>Makes sure afl-fuzz is on the PATH.</summary>
    /// <param name="say">Progress sink.</param>
    /// <exception cref="UsageException">afl-fuzz is missing and cannot be installed.</exception>
    public static void Ensure(Action<string> say)
    {
        if (Which("afl-fuzz") is not null)
        {
            return;
        }

        say("afl-fuzz not found: installing the Debian package afl++ (apt-get)");
        string[] sudo = Environment.UserName == "root" || Run("id", "-u").Output.Trim() == "0" ? [] : ["sudo", "-n"];
        if (sudo.Length > 0 && Run("sudo", "-n", "true").Code != 0)
        {
            throw new UsageException("afl-fuzz is missing and there is no root or passwordless sudo to install afl++ (apt-get install afl++)");
        }

        foreach (var args in new[] { new[] { "apt-get", "update", "-qq" }, ["apt-get", "install", "-y", "-qq", "afl++"] })
        {
            string[] full = [.. sudo, .. args];
            var (code, output) = Run(full[0], full[1..]);
            if (code != 0)
            {
                throw new UsageException($"{string.Join(' ', args)} failed ({code}): {output.Trim()}");
            }
        }

        if (Which("afl-fuzz") is null)
        {
            throw new UsageException("apt-get install afl++ did not provide afl-fuzz");
        }
    }

    /// <summary>Finds a program on the PATH.</summary>
    /// <param name="name">The program.</param>
    /// <returns>Its path, or null.</returns>
    public static string? Which(string name) =>
        (Environment.GetEnvironmentVariable("PATH") ?? string.Empty).Split(':', StringSplitOptions.RemoveEmptyEntries)
            .Select(d => Path.Combine(d, name))
            .FirstOrDefault(File.Exists);

    /// <summary>Runs a program to completion with environment variables, capturing stdout and stderr together.</summary>
    /// <param name="file">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <returns>The exit code and the output.</returns>
    public static (int Code, string Output) Run(string file, params string[] args) => Run(file, args, null);

    /// <summary>Runs a program to completion, capturing stdout and stderr together.</summary>
    /// <param name="file">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <param name="environment">Extra environment variables, or null.</param>
    /// <returns>The exit code and the output.</returns>
    public static (int Code, string Output) Run(string file, IEnumerable<string> args, IReadOnlyDictionary<string, string>? environment)
    {
        var info = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in args)
        {
            info.ArgumentList.Add(a);
        }

        foreach (var (k, v) in environment ?? new Dictionary<string, string>())
        {
            info.Environment[k] = v;
        }

        try
        {
            using var p = Process.Start(info)!;
            var stderr = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            return (p.ExitCode, stdout + stderr.Result);
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            return (127, $"{file}: {e.Message}");
        }
    }
}
