namespace AcPhys.Cli.Fuzz;

/// <summary>Publishes the harness and the SharpFuzz instrumenter (Release) and instruments the physics assemblies in place, all in one instrumenter process (docs/fuzzing.md).</summary>
internal static class HarnessBuild
{
    /// <summary>The assemblies that get AFL edge probes: the physics, the invariants and faults, the toy.</summary>
    public static readonly string[] Instrumented = ["AcPhys.Core.dll", "AcPhys.Spec.dll", "AcPhys.Fuzz.Toy.dll"];

    /// <summary>Builds into <see cref="FuzzSettings.BuildDir"/> unless <see cref="FuzzSettings.NoBuild"/> and a build is there.</summary>
    /// <param name="s">The settings.</param>
    /// <param name="say">Progress sink.</param>
    /// <exception cref="UsageException">A publish or the instrumentation failed (the log is named).</exception>
    public static void Ensure(FuzzSettings s, Action<string> say)
    {
        if (s.NoBuild && File.Exists(s.Harness))
        {
            say($"build: reusing {s.BuildDir}");
            return;
        }

        Directory.CreateDirectory(s.LogDir);
        say($"build: publishing the harness and the instrumenter (Release) into {s.BuildDir}");
        Publish(s, "fuzz/AcPhys.Fuzz/AcPhys.Fuzz.csproj", "harness");
        Publish(s, "fuzz/AcPhys.Fuzz.Instrumenter/AcPhys.Fuzz.Instrumenter.csproj", "instrument");
        var dlls = Instrumented.Select(d => Path.Combine(s.BuildDir, "harness", d)).Where(File.Exists).ToArray();
        var (code, output) = AflTools.Run(Path.Combine(s.BuildDir, "instrument", "AcPhys.Fuzz.Instrumenter"), dlls);
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

    private static void Publish(FuzzSettings s, string project, string folder)
    {
        string log = Path.Combine(s.LogDir, $"publish-{folder}.log");
        var (code, output) = AflTools.Run(
            "dotnet",
            ["publish", Path.Combine(s.Root, project), "-c", "Release", "-o", Path.Combine(s.BuildDir, folder), "--nologo"],
            new Dictionary<string, string> { ["DOTNET_NOLOGO"] = "1", ["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1" });
        File.WriteAllText(log, output);
        if (code != 0)
        {
            throw new UsageException($"dotnet publish {project} failed ({code}); see {log}");
        }
    }
}
