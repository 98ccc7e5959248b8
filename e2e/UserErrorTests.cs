using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>No internal error reaches a user (issue 19 item 3): each input below once printed "internal error" or a CLR type name.</summary>
public sealed class UserErrorTests
{
    private const string HugeStepWalk = """
        {"format":"acphys-case","version":1,"kind":"walk","title":"huge steps","invariant":"NO-BOUNDARY-FREEZE","foundBy":"props",
         "walk":{"start":{"cell":"0x36420039","x":100,"y":100,"z":0},"body":[{"x":0,"y":0,"z":0.5,"r":1}],"steps":[[1e30,1e30]]}}
        """;

    private const string SmallWalk = """
        {"format":"acphys-case","version":1,"kind":"walk","title":"small","invariant":"NO-BOUNDARY-FREEZE","foundBy":"props",
         "walk":{"start":{"cell":"0x36420039","x":100,"y":100,"z":0},"body":[{"x":0,"y":0,"z":0.5,"r":1}],"steps":[[1,1]]}}
        """;

    [Theory]
    [InlineData("0")]
    [InlineData("5")]
    public void MaxClassesOutOfRangeIsAUsageError(string n)
    {
        var run = Acphys.Run(["verify", "--max-classes", n, "--only", "ADJUST-RANGE", "--cases", "10"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains($"--max-classes must be between 1 and 4 (got {n})", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void Render_WalkWithHugeSteps_IsAClearUsageError()
    {
        var run = Acphys.Run(["render", Write(HugeStepWalk), "-o", Path.Combine(Temp(), "huge.svg")]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.DoesNotContain("internal error", run.Err, StringComparison.Ordinal);
        Assert.Contains("render draws walks up to 70000 m across", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void Render_EmptyOrDirectoryOutput_IsAnOutputErrorBeforeAnyWork()
    {
        string walk = Write(SmallWalk);
        var empty = Acphys.Run(["render", walk, "-o", string.Empty]);
        Assert.True(empty.Exit == 3, empty.ToString());
        Assert.Contains("-o: empty path", empty.Err, StringComparison.Ordinal);
        string dir = Temp();
        var folder = Acphys.Run(["render", walk, "-o", dir]);
        Assert.True(folder.Exit == 3, folder.ToString());
        Assert.Contains("it is a directory", folder.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("internal error", empty.Err + folder.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void Render_DashOutput_WritesTheSvgToStdout()
    {
        var run = Acphys.Run(["render", Write(SmallWalk), "-o", "-"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.StartsWith("<svg ", run.Out, StringComparison.Ordinal);
        Assert.Contains("render: wrote -", run.Err, StringComparison.Ordinal);
        Assert.False(File.Exists(Path.Combine(RepoPaths.Root, "-")), "a file named '-' was written");
    }

    [Fact]
    public void Verify_CasesOutOfRange_SaysTheRangeNotTheClrType()
    {
        var run = Acphys.Run(["verify", "--cases", "99999999999"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("--cases: '99999999999' is not a whole number from", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("System.", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void UnknownCommand_IsNamedFirstWithASuggestion()
    {
        var run = Acphys.Run(["verfy"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.StartsWith("unknown command 'verfy'; did you mean 'verify'?", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("Required command was not provided", run.Err, StringComparison.Ordinal);
        var other = Acphys.Run(["frobnicate"]);
        Assert.StartsWith("unknown command 'frobnicate'", other.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void Verify_UnwritableJunit_FailsAtOnceWithItsOwnExitCode()
    {
        // --cases 100000 of every invariant would take minutes: the check has to come before the run.
        var run = Acphys.Run(["verify", "--cases", "100000", "--junit", "/proc/acphys/out.xml"]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("cannot write '/proc/acphys/out.xml' (--junit)", run.Err, StringComparison.Ordinal);
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(20), run.ToString());
    }

    private static string Temp() => Directory.CreateTempSubdirectory("acphys-usererr-").FullName;

    private static string Write(string json)
    {
        string path = Path.Combine(Temp(), "walk.json");
        File.WriteAllText(path, json);
        return path;
    }
}
