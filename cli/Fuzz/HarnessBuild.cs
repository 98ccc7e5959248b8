namespace AcPhys.Cli.Fuzz;

/// <summary>Publishes the harness and the SharpFuzz instrumenter (Release) and instruments the physics assemblies in place, all in one instrumenter process (docs/fuzzing.md).</summary>
internal static class HarnessBuild
{
    /// <summary>The assemblies that get AFL edge probes: the physics, the formats and protocol v1 (the serve-request target), the invariants and faults, the toy.</summary>
    public static readonly string[] Instrumented = ["AcPhys.Core.dll", "AcPhys.Contract.dll", "AcPhys.Formats.dll", "AcPhys.Protocol.dll", "AcPhys.Spec.dll", "AcPhys.Fuzz.Toy.dll"];

    /// <summary>Builds into <see cref="FuzzSettings.BuildDir"/> unless <see cref="FuzzSettings.NoBuild"/> and a build is there.</summary>
    /// <param name="s">The settings.</param>
    /// <param name="say">Progress sink.</param>
    /// <param name="stop">Cancelled by Ctrl-C / SIGTERM: the build step in progress is killed with everything it started.</param>
    /// <exception cref="UsageException">A publish or the instrumentation failed (the log is named), or <paramref name="stop"/> fired.</exception>
    /// <remarks><para>
    /// Every step runs through <see cref="GuardedChild"/>, and <c>dotnet publish</c> with <c>--disable-build-servers</c>
    /// (no MSBuild node reuse, no compiler server), so a killed acphys leaves no <c>dotnet publish</c> writing the
    /// build folder (issue #17 part 2, issue #19 "Orphans").
    /// </para></remarks>
    public static void Ensure(FuzzSettings s, Action<string> say, CancellationToken stop)
    {
        if (s.NoBuild && File.Exists(s.Harness))
        {
            say($"build: reusing {s.BuildDir}");
            return;
        }

        Directory.CreateDirectory(s.LogDir);
        say($"build: publishing the harness and the instrumenter (Release) into {s.BuildDir}");
        Publish(s, "fuzz/AcPhys.Fuzz/AcPhys.Fuzz.csproj", "harness", stop);
        Publish(s, "fuzz/AcPhys.Fuzz.Instrumenter/AcPhys.Fuzz.Instrumenter.csproj", "instrument", stop);
        if (!s.InstrumentsOurs)
        {
            say("build: the suite's own assemblies stay uninstrumented (an --impl campaign is guided by the port's branches)");
            return;
        }

        var dlls = Instrumented.Select(d => Path.Combine(s.BuildDir, "harness", d)).Where(File.Exists).ToArray();
        var (code, output) = GuardedChild.Run(Path.Combine(s.BuildDir, "instrument", "AcPhys.Fuzz.Instrumenter"), dlls, null, stop);
        File.WriteAllText(Path.Combine(s.LogDir, "instrument.log"), output);
        if (code != 0)
        {
            throw new UsageException($"instrumenting failed ({code}); see {Path.Combine(s.LogDir, "instrument.log")}");
        }

        foreach (string line in output.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            say("  " + line);
        }
    }

    /// <summary>Runs the instrumenter (already built) on assemblies, in one process; returns its output.</summary>
    /// <param name="s">The settings.</param>
    /// <param name="dlls">The assemblies, instrumented in place.</param>
    /// <param name="log">The log file.</param>
    /// <param name="stop">Cancelled by Ctrl-C / SIGTERM.</param>
    /// <returns>The instrumenter's lines.</returns>
    /// <exception cref="UsageException">Instrumenting failed.</exception>
    public static string Instrument(FuzzSettings s, IReadOnlyList<string> dlls, string log, CancellationToken stop)
    {
        var (code, output) = GuardedChild.Run(Path.Combine(s.BuildDir, "instrument", "AcPhys.Fuzz.Instrumenter"), dlls, null, stop);
        File.WriteAllText(log, output);
        return code == 0 ? output : throw new UsageException($"instrumenting failed ({code}); see {log}");
    }

    private static void Publish(FuzzSettings s, string project, string folder, CancellationToken stop)
    {
        string log = Path.Combine(s.LogDir, $"publish-{folder}.log");
        var (code, output) = GuardedChild.Run(
            "dotnet",
            ["publish", Path.Combine(s.Root, project), "-c", "Release", "-o", Path.Combine(s.BuildDir, folder), "--nologo", "--disable-build-servers"],
            new Dictionary<string, string> { ["DOTNET_NOLOGO"] = "1", ["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1" },
            stop);
        File.WriteAllText(log, output);
        if (code != 0)
        {
            throw new UsageException($"dotnet publish {project} failed ({code}); see {log}");
        }
    }
}
