using System.Diagnostics;
using System.IO.Compression;
using AcPhys.E2E.Support;
using AcPhys.Spec.Invariants;

namespace AcPhys.E2E;

/// <summary>
/// packaging/pack.sh: AcPhys.Core, AcPhys.Contract (depending on Core only), AcPhys.Formats, AcPhys.Spec, AcPhys.Xunit and the acphys
/// .NET tool, packed once for the class; the tool installs from the local folder and runs, and an adapter builds
/// against the contract package alone.
/// </summary>
public sealed class PackagingTests(PackagingTests.PackedFolder packed) : IClassFixture<PackagingTests.PackedFolder>
{
    [Fact]
    public void ToolInstallsFromTheLocallyPackedPackageAndRuns()
    {
        string packages = packed.Packages, version = packed.Version, tools = Path.Combine(packed.Work, "tools");
        foreach (string id in new[] { "AcPhys.Core", "AcPhys.Contract", "AcPhys.Formats", "AcPhys.Spec", "AcPhys.Xunit", "AcPhys.Cli" })
        {
            Assert.True(Directory.GetFiles(packages, id + ".*.nupkg").Length == 1, $"{id} not packed:\n{packed.Output}");
        }

        // The one-way arrows as package dependencies: contract ← formats ← spec, and FsCheck only from spec up.
        Assert.Equal(["AcPhys.Core"], packed.Dependencies("AcPhys.Contract"));
        Assert.Equal(["AcPhys.Contract"], packed.Dependencies("AcPhys.Formats"));
        Assert.Contains("AcPhys.Formats", packed.Dependencies("AcPhys.Spec"));
        Assert.Contains("FsCheck", packed.Dependencies("AcPhys.Spec"));
        Assert.Equal(["AcPhys.Spec", "xunit.assert", "xunit.extensibility.core", "xunit.extensibility.execution", "Xunit.SkippableFact"], packed.Dependencies("AcPhys.Xunit").Order(StringComparer.OrdinalIgnoreCase));
        using (var spec = ZipFile.OpenRead(Directory.GetFiles(packages, "AcPhys.Spec.*.nupkg")[0]))
        {
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

    [Fact]
    public void AdapterBuildsAgainstTheContractPackageAloneWithoutFsCheck()
    {
        // A port's own project, outside the repository (no Directory.*.props): the example adapter's source and one
        // package reference, restored from the packed folder only.
        string project = Directory.CreateDirectory(Path.Combine(packed.Work, "my-port")).FullName;
        File.Copy(Path.Combine(RepoPaths.Root, "examples", "dotnet-adapter", "MyLandDefsAdapter.cs"), Path.Combine(project, "MyLandDefsAdapter.cs"));
        File.WriteAllText(Path.Combine(project, "MyPort.csproj"), $$"""
            <Project Sdk="Microsoft.NET.Sdk">
              <PropertyGroup>
                <TargetFramework>net10.0</TargetFramework>
                <Nullable>enable</Nullable>
                <ImplicitUsings>enable</ImplicitUsings>
              </PropertyGroup>
              <ItemGroup>
                <PackageReference Include="AcPhys.Contract" Version="{{packed.Version}}" />
              </ItemGroup>
            </Project>
            """);
        WritePackedSource(project);
        var build = Exec("dotnet", ["build", Path.Combine(project, "MyPort.csproj"), "-c", "Release", "-nologo", "-v:quiet"]);
        Assert.True(build.Exit == 0, build.Output);

        string assets = File.ReadAllText(Path.Combine(project, "obj", "project.assets.json"));
        string deps = File.ReadAllText(Directory.GetFiles(Path.Combine(project, "bin"), "MyPort.deps.json", SearchOption.AllDirectories).Single());
        Assert.Contains($"\"AcPhys.Contract/{packed.Version}\"", assets, StringComparison.Ordinal);
        Assert.Contains($"\"AcPhys.Core/{packed.Version}\"", assets, StringComparison.Ordinal);
        foreach (string heavy in new[] { "FsCheck", "FSharp.Core", "AcPhys.Spec", "AcPhys.Formats" })
        {
            Assert.DoesNotContain(heavy, assets, StringComparison.Ordinal);
            Assert.DoesNotContain(heavy, deps, StringComparison.Ordinal);
        }
    }

    [Fact(DisplayName = "PORT-PACKAGE: a port's own xunit project runs the gate from the packed AcPhys.Xunit alone (24 passed, the rest skipped NOT TESTED on the example port)")]
    public void GateTestsRunFromTheXunitPackageInAPortsOwnProject()
    {
        // A port's repository, outside this one: the example port's source and its one-line gate class in an ordinary
        // xunit project whose only AcPhysVerify reference is the AcPhys.Xunit package.
        string project = Directory.CreateDirectory(Path.Combine(packed.Work, "my-port-gate")).FullName;
        string example = Path.Combine(RepoPaths.Root, "examples", "dotnet-port");
        foreach (string source in Directory.GetFiles(example, "*.cs").Append(Path.Combine(example, "GateTests", "ExamplePortGate.cs")))
        {
            File.Copy(source, Path.Combine(project, Path.GetFileName(source)));
        }

        File.WriteAllText(Path.Combine(project, "MyPortGate.csproj"), $$"""
            <Project Sdk="Microsoft.NET.Sdk">
              <PropertyGroup>
                <TargetFramework>net10.0</TargetFramework>
                <Nullable>enable</Nullable>
                <ImplicitUsings>enable</ImplicitUsings>
                <IsPackable>false</IsPackable>
              </PropertyGroup>
              <ItemGroup>
                <PackageReference Include="AcPhys.Xunit" Version="{{packed.Version}}" />
                <PackageReference Include="Microsoft.NET.Test.Sdk" Version="18.0.1" />
                <PackageReference Include="xunit" Version="2.9.3" />
                <PackageReference Include="xunit.runner.visualstudio" Version="3.1.5" />
              </ItemGroup>
            </Project>
            """);
        WritePackedSource(project); // xunit, FsCheck and the rest resolve from the global packages folder this repository's restore filled
        var test = Exec("dotnet", ["test", Path.Combine(project, "MyPortGate.csproj"), "-c", "Release", "-nologo"]);
        Assert.True(test.Exit == 0, test.Output);
        // 23 invariants tested + the minimum-tested floor row pass; every other invariant is a skipped NOT TESTED row.
        Assert.Matches($@"Failed:\s+0, Passed:\s+24, Skipped:\s+{InvariantCatalogue.All.Count - 23}, Total:\s+{InvariantCatalogue.All.Count + 1}", test.Output);
    }

    // A nuget.config whose only source is the folder the packages were packed into.
    private void WritePackedSource(string project) =>
        File.WriteAllText(Path.Combine(project, "nuget.config"), $$"""
            <configuration>
              <packageSources>
                <clear />
                <add key="packed" value="{{packed.Packages}}" />
              </packageSources>
            </configuration>
            """);

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

    /// <summary>The packages of this checkout, packed once (with --no-build: what the test run built) at a fresh version, deleted afterwards.</summary>
    public sealed class PackedFolder : IDisposable
    {
        public PackedFolder()
        {
            string configuration = AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";
            Work = Directory.CreateTempSubdirectory("acphys-pack-").FullName;
            Packages = Path.Combine(Work, "packages");

            // A fresh version each run, so an install or restore cannot be served a stale copy from the NuGet cache.
            Version = "1.0.0-e2e." + DateTime.UtcNow.ToString("yyyyMMddHHmmssfff", System.Globalization.CultureInfo.InvariantCulture);
            var pack = Exec("bash", [Path.Combine(RepoPaths.Root, "packaging", "pack.sh"), "--no-build", "-c", configuration, "-o", Packages, "--version", Version]);
            Output = pack.Output;
            Assert.True(pack.Exit == 0, pack.Output);
        }

        public string Work { get; }

        public string Packages { get; }

        public string Version { get; }

        public string Output { get; }

        /// <summary>Returns the package ids a packed package depends on, from its nuspec.</summary>
        public string[] Dependencies(string id)
        {
            using var package = ZipFile.OpenRead(Path.Combine(Packages, $"{id}.{Version}.nupkg"));
            using var nuspec = new StreamReader(package.GetEntry(id + ".nuspec")!.Open());
            var doc = System.Xml.Linq.XDocument.Parse(nuspec.ReadToEnd());
            return [.. doc.Descendants().Where(e => e.Name.LocalName == "dependency").Select(e => (string)e.Attribute("id")!).Distinct()];
        }

        public void Dispose() => Directory.Delete(Work, recursive: true);
    }
}
