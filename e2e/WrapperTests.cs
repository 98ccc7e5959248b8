using System.Diagnostics;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The <c>./acphys</c> wrapper says what it is doing when it has to build (issue 19 item 1): one stderr line within a
/// second, then a done line. A stand-in <c>dotnet</c> on PATH makes the "build" take 3 s, so the test needs no real build.
/// </summary>
public sealed class WrapperTests
{
    [Fact]
    public void Wrapper_Building_SaysSoWithinOneSecond()
    {
        if (OperatingSystem.IsWindows())
        {
            return;
        }

        string root = Directory.CreateTempSubdirectory("acphys-wrapper-").FullName;
        File.Copy(Path.Combine(RepoPaths.Root, "acphys"), Path.Combine(root, "acphys"));
        Directory.CreateDirectory(Path.Combine(root, "cli"));
        File.WriteAllText(Path.Combine(root, "cli", "AcPhys.Cli.csproj"), "<Project/>");
        string bin = Directory.CreateDirectory(Path.Combine(root, "fakebin")).FullName;
        string fake = Path.Combine(bin, "dotnet");
        File.WriteAllText(fake, """
            #!/bin/sh
            if [ "$1" = build ]; then sleep 3; mkdir -p "$(dirname "$2")/bin/Release/net10.0"; : > "$(dirname "$2")/bin/Release/net10.0/acphys.dll"; exit 0; fi
            echo "ran $*"
            """.Replace("\r", string.Empty, StringComparison.Ordinal));
        File.SetUnixFileMode(fake, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);

        var info = new ProcessStartInfo("bash") { RedirectStandardError = true, RedirectStandardOutput = true, UseShellExecute = false };
        info.ArgumentList.Add(Path.Combine(root, "acphys"));
        info.ArgumentList.Add("--version");
        info.Environment["PATH"] = bin + ":" + Environment.GetEnvironmentVariable("PATH");
        var clock = Stopwatch.StartNew();
        using var process = Process.Start(info)!;
        string? first = process.StandardError.ReadLine();
        var firstAt = clock.Elapsed;
        string rest = process.StandardError.ReadToEnd();
        string stdout = process.StandardOutput.ReadToEnd(); // one short line: no pipe fills up meanwhile
        Assert.True(process.WaitForExit(TimeSpan.FromSeconds(30)));

        Assert.NotNull(first);
        Assert.StartsWith("acphys: building cli (first run, ~", first, StringComparison.Ordinal);
        Assert.True(firstAt < TimeSpan.FromSeconds(1), $"first line after {firstAt.TotalSeconds:0.00} s");
        Assert.Contains("acphys: build done in", rest, StringComparison.Ordinal);
        Assert.Contains("ran ", stdout, StringComparison.Ordinal);
        Assert.Equal(0, process.ExitCode);
    }
}
