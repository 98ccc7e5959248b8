using System.Diagnostics;
using System.IO.Compression;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>packaging/pack.sh: AcPhys.Core, AcPhys.Spec (depending on Core) and the acphys .NET tool; the tool installs from the local folder and runs.</summary>
public sealed class PackagingTests
{
    [Fact]
    public void ToolInstallsFromTheLocallyPackedPackageAndRuns()
    {
        string configuration = AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";
        string work = Directory.CreateTempSubdirectory("acphys-pack-").FullName;
        try
        {
            PackInstallRun(work, configuration);
        }
        finally
        {
            Directory.Delete(work, recursive: true);
        }
    }

    private static void PackInstallRun(string work, string configuration)
    {
        string packages = Path.Combine(work, "packages"), tools = Path.Combine(work, "tools");

        // A fresh version each run, so the install cannot be served a stale copy from the NuGet cache.
        string version = "1.0.0-e2e." + DateTime.UtcNow.ToString("yyyyMMddHHmmssfff", System.Globalization.CultureInfo.InvariantCulture);
        var pack = Exec("bash", [Path.Combine(RepoPaths.Root, "packaging", "pack.sh"), "--no-build", "-c", configuration, "-o", packages, "--version", version]);
        Assert.True(pack.Exit == 0, pack.Output);
        foreach (string id in new[] { "AcPhys.Core", "AcPhys.Spec", "AcPhys.Cli" })
        {
            Assert.True(Directory.GetFiles(packages, id + ".*.nupkg").Length == 1, $"{id} not packed:\n{pack.Output}");
        }

        using (var spec = ZipFile.OpenRead(Directory.GetFiles(packages, "AcPhys.Spec.*.nupkg")[0]))
        {
            using var nuspec = new StreamReader(spec.GetEntry("AcPhys.Spec.nuspec")!.Open());
            Assert.Contains("<dependency id=\"AcPhys.Core\"", nuspec.ReadToEnd(), StringComparison.Ordinal);
            Assert.NotNull(spec.GetEntry("lib/net10.0/AcPhys.Spec.dll"));
        }

        var install = Exec("dotnet", ["tool", "install", "--tool-path", tools, "--add-source", packages, "AcPhys.Cli", "--version", version]);
        Assert.True(install.Exit == 0, install.Output);

        var run = Exec(Path.Combine(tools, "acphys"), ["verify", "--only", "LCOORD-ROUNDTRIP,COVERAGE", "--cases", "100", "--quiet"]);
        Assert.True(run.Exit == 0, run.Output);
        Assert.Contains("verify: 2 invariants, 2 passed, 0 failed", run.Output, StringComparison.Ordinal);

        var bad = Exec(Path.Combine(tools, "acphys"), ["verify", "--fault", "trunc-floor", "--only", "ADJUST-RANGE", "--cases", "500", "--quiet"]);
        Assert.True(bad.Exit == 1, bad.Output); // the installed tool bites too
    }

    private static (int Exit, string Output) Exec(string file, IEnumerable<string> args)
    {
        var info = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false, WorkingDirectory = Path.GetTempPath() };
        foreach (var a in args)
        {
            info.ArgumentList.Add(a);
        }

        info.Environment["DOTNET_NOLOGO"] = "1";
        info.Environment["ACPHYS_FAILURES"] = Path.Combine(Path.GetTempPath(), "acphys-e2e-failures");
        using var p = Process.Start(info)!;
        var stdout = p.StandardOutput.ReadToEndAsync();
        var stderr = p.StandardError.ReadToEndAsync();
        if (!p.WaitForExit(TimeSpan.FromMinutes(4)))
        {
            p.Kill(entireProcessTree: true);
            return (-1, $"{file} timed out");
        }

        return (p.ExitCode, $"{file} {string.Join(' ', info.ArgumentList)} -> {p.ExitCode}\n{stdout.Result}\n{stderr.Result}");
    }
}
