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
        if (s.InstrumentsOurs && Directory.Exists(Path.Combine(s.BuildDir, "harness")))
        {
            // Publish skips a file whose copy is newer: an unchanged assembly kept the probes of an earlier build while
            // a changed one was instrumented alone, by a process whose block ids start again (ids shared by two
            // assemblies), and a change of what is instrumented never reached the copies. Fresh copies, all
            // instrumented in one process, every build.
            foreach (string dll in Instrumented)
            {
                File.Delete(Path.Combine(s.BuildDir, "harness", dll));
            }
        }

        Publish(s, "fuzz/AcPhys.Fuzz/AcPhys.Fuzz.csproj", "harness", stop);
        Publish(s, "fuzz/AcPhys.Fuzz.Instrumenter/AcPhys.Fuzz.Instrumenter.csproj", "instrument", stop);
        if (!s.InstrumentsOurs)
        {
            say("build: the suite's own assemblies stay uninstrumented (an --impl campaign is guided by the port's branches)");
            return;
        }

        var dlls = For(s).Select(d => Path.Combine(s.BuildDir, "harness", d)).Where(File.Exists).ToArray();
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

    /// <summary>
    /// Returns the assemblies a campaign's build instruments: <see cref="Instrumented"/>, but for an <c>--impl-cmd</c>
    /// campaign (its own build folder, <c>.fuzz/build-cmd</c>) not the protocol's (issue 40). Its pipeline reads the
    /// child's answers on a second thread, and SharpFuzz's previous-block register is one static for all threads, so the
    /// wire code's probes mixed their edges into the main thread's at random: served campaigns were 64–96 % stable
    /// against 99.6 % in process, and afl-fuzz calibrates an unstable path 40 times instead of 8. The wire code is the
    /// tool's, not the port's; the serve-request target keeps it instrumented in the default build.
    /// </summary>
    /// <param name="s">The settings.</param>
    /// <returns>The assembly file names.</returns>
    public static IReadOnlyList<string> For(FuzzSettings s) =>
        s.Port.Command is null ? Instrumented : [.. Instrumented.Where(d => d != "AcPhys.Protocol.dll")];

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
