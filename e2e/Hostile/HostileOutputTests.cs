using AcPhys.E2E.Support;

namespace AcPhys.E2E.Hostile;

/// <summary>
/// Issue 28, the paths on the command line: a device, FIFO or symlink is never renamed over, an output never
/// overwrites an input or another output, and every path problem is exit 3 before the run.
/// </summary>
public sealed class HostileOutputTests
{
    private static readonly string[] Small = ["verify", "--only", "ADJUST-RANGE", "--cases", "5", "--quiet"];

    /// <summary>OUTPUT-DEVICE: a character device that refuses writes (like /dev/full) stays a device; the write fails with exit 3.</summary>
    [Fact]
    public void Junit_ToAFullDevice_IsExit3AndTheDeviceStays()
    {
        string full = Path.Combine(HostileFiles.Temp(), "full");
        HostileFiles.Tool("mknod", full, "c", "1", "7");
        var run = Acphys.Run([.. Small, "--junit", full]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("No space left on device", run.Err, StringComparison.Ordinal);
        Assert.Equal("character special file", HostileFiles.TypeOf(full));
    }

    /// <summary>OUTPUT-DEVICE: a character device that takes writes (like /dev/null) is written in place and stays a device.</summary>
    [Fact]
    public void Markdown_ToANullDevice_IsWrittenInPlace()
    {
        string nul = Path.Combine(HostileFiles.Temp(), "null");
        HostileFiles.Tool("mknod", nul, "c", "1", "3");
        var run = Acphys.Run([.. Small, "--markdown", nul]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Equal("character special file", HostileFiles.TypeOf(nul));
    }

    /// <summary>OUTPUT-FIFO: a FIFO is refused before the run (exit 3) and stays a FIFO; nothing waits on a reader.</summary>
    [Fact]
    public void Junit_ToAFifo_IsRefusedBeforeTheRun()
    {
        string fifo = Path.Combine(HostileFiles.Temp(), "fifo");
        HostileFiles.Tool("mkfifo", fifo);
        var run = Acphys.Run([.. Small, "--junit", fifo]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("(--junit): it is a FIFO", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("verify:", run.Out, StringComparison.Ordinal);
        Assert.Equal("fifo", HostileFiles.TypeOf(fifo));
    }

    /// <summary>OUTPUT-SYMLINK: a symlink is written through: the link stays, its target holds the report.</summary>
    [Fact]
    public void Junit_ToASymlink_IsWrittenThrough()
    {
        string dir = HostileFiles.Temp();
        string target = Path.Combine(dir, "real.xml"), link = Path.Combine(dir, "link.xml");
        File.WriteAllText(target, "old");
        File.CreateSymbolicLink(link, "real.xml");
        var run = Acphys.Run([.. Small, "--junit", link]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Equal("symbolic link", HostileFiles.TypeOf(link));
        Assert.StartsWith("<?xml", File.ReadAllText(target), StringComparison.Ordinal);
    }

    /// <summary>OUTPUT-SYMLINK (own input 4): a dangling symlink is written through: its target is created.</summary>
    [Fact]
    public void Markdown_ToADanglingSymlink_CreatesItsTarget()
    {
        string dir = HostileFiles.Temp();
        string link = Path.Combine(dir, "link.md");
        File.CreateSymbolicLink(link, "made.md");
        var run = Acphys.Run([.. Small, "--markdown", link]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Equal("symbolic link", HostileFiles.TypeOf(link));
        Assert.StartsWith("## acphys verify", File.ReadAllText(Path.Combine(dir, "made.md")), StringComparison.Ordinal);
    }

    /// <summary>OUTPUT-SYMLINK (own input 5): a symlink to a folder is no output file: exit 3 before the run.</summary>
    [Fact]
    public void Junit_ToASymlinkedFolder_IsExit3()
    {
        string dir = HostileFiles.Temp();
        string link = Path.Combine(dir, "folder.xml");
        File.CreateSymbolicLink(link, HostileFiles.Temp());
        var run = Acphys.Run([.. Small, "--junit", link]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("it is a directory", run.Err, StringComparison.Ordinal);
    }

    /// <summary>OUTPUT-NOT-INPUT: render -o its own input is a usage error (exit 3) and the input is unchanged.</summary>
    [Fact]
    public void Render_OntoItsOwnInput_IsExit3()
    {
        string input = HostileFiles.Seed("cottage-a9b3-a9b4-through.json");
        string before = File.ReadAllText(input);
        var run = Acphys.Run(["render", input, "-o", input]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("would overwrite the input", run.Err, StringComparison.Ordinal);
        Assert.Equal(before, File.ReadAllText(input));
    }

    /// <summary>OUTPUT-NOT-INPUT: render of a record folder onto its manifest, and scene import onto one of its records, are exit 3; the folder is unchanged.</summary>
    [Fact]
    public void RecordFolder_OutputsInsideIt_AreExit3()
    {
        string rec = Path.Combine(HostileFiles.Temp(), "rec");
        var export = Acphys.Run(["scene", "export", HostileFiles.Seed("cottage-a9b3-a9b4-through.json"), "--dat", rec]);
        Assert.True(export.Exit == 0, export.ToString());
        string manifest = Path.Combine(rec, "manifest.json");
        string before = File.ReadAllText(manifest);
        var render = Acphys.Run(["render", rec, "-o", manifest]);
        Assert.True(render.Exit == 3, render.ToString());
        Assert.Contains("would overwrite the input", render.Err, StringComparison.Ordinal);
        string record = Directory.EnumerateFiles(rec, "*.bin").First();
        byte[] bytes = File.ReadAllBytes(record);
        var import = Acphys.Run(["scene", "import", rec, "-o", record]);
        Assert.True(import.Exit == 3, import.ToString());
        Assert.Equal(before, File.ReadAllText(manifest));
        Assert.Equal(bytes, File.ReadAllBytes(record));
    }

    /// <summary>OUTPUTS-DISTINCT: verify --junit X --markdown X and bite --json X --markdown X are exit 3 before any work.</summary>
    [Fact]
    public void TwoOutputsOnOnePath_AreExit3()
    {
        string x = Path.Combine(HostileFiles.Temp(), "x");
        var verify = Acphys.Run([.. Small, "--junit", x, "--markdown", x]);
        Assert.True(verify.Exit == 3, verify.ToString());
        Assert.Contains("--junit and --markdown name the same file", verify.Err, StringComparison.Ordinal);
        var bite = Acphys.Run(["bite", "--seeds", "1", "--json", x, "--markdown", x]);
        Assert.True(bite.Exit == 3, bite.ToString());
        Assert.Contains("--markdown and --json name the same file", bite.Err, StringComparison.Ordinal);
        Assert.False(File.Exists(x));
    }

    /// <summary>OUTPUT-NOT-INPUT (own input 6): --junit onto the --impl assembly is exit 3 and the assembly is unchanged.</summary>
    [Fact]
    public void Junit_OntoTheImplAssembly_IsExit3()
    {
        string dll = Path.Combine(HostileFiles.Temp(), "Adapter.dll");
        File.WriteAllText(dll, "not really an assembly");
        var run = Acphys.Run(["verify", "--impl", dll, "--junit", dll]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("would overwrite the input", run.Err, StringComparison.Ordinal);
        Assert.Equal("not really an assembly", File.ReadAllText(dll));
    }

    /// <summary>PATHS-EXIT-3: empty, file-as-folder and /proc outputs of scene export / import and diff are exit 3 before the work; diff -o "" writes nothing into the working folder.</summary>
    [Fact]
    public void BadOutputFolders_AreExit3BeforeTheWork()
    {
        string seed = HostileFiles.Seed("cottage-a9b3-a9b4-through.json");
        string file = HostileFiles.Write("existing.txt", "x");
        var cases = new (string[] Args, string Message)[]
        {
            (["scene", "export", seed, "--dat", string.Empty], "--dat: empty path"),
            (["scene", "export", seed, "--dat", file], "it is a file, not a folder"),
            (["scene", "import", Path.GetDirectoryName(seed)!, "-o", string.Empty], "-o: empty path"),
            (["scene", "import", Path.GetDirectoryName(seed)!, "-o", HostileFiles.Temp()], "it is a directory"),
            (["diff", "--impl-cmd", Acphys.ServeCommand, "--cases", "5", "-o", file], "it is a file, not a folder"),
            (["diff", "--impl-cmd", Acphys.ServeCommand, "--cases", "5", "-o", "/proc/acphys-x"], "cannot write into '/proc/acphys-x'"),
            (["diff", "--impl-cmd", Acphys.ServeCommand, "--cases", "5", "-o", string.Empty], "-o: empty path"),
        };
        foreach (var (args, message) in cases)
        {
            var run = Acphys.Run(args);
            Assert.True(run.Exit == 3, string.Join(' ', args) + "\n" + run);
            Assert.Contains(message, run.Err, StringComparison.Ordinal);
            Assert.DoesNotContain("internal error", run.Err, StringComparison.Ordinal);
            Assert.DoesNotContain("diff:", run.Out, StringComparison.Ordinal);
        }

        Assert.False(File.Exists(Path.Combine(RepoPaths.Root, "summary.md")), "diff -o '' wrote summary.md into the working folder");
    }

    /// <summary>PATHS-EXIT-3: ACPHYS_FAILURES naming a file or a /proc path is exit 3 before the run.</summary>
    [Theory]
    [InlineData("file")]
    [InlineData("/proc/acphys-x")]
    public void FailuresFolder_Unwritable_IsExit3BeforeTheRun(string kind)
    {
        string path = kind == "file" ? HostileFiles.Write("failures", "x") : kind;
        var run = Acphys.Run(Small, new Dictionary<string, string> { ["ACPHYS_FAILURES"] = path });
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("(ACPHYS_FAILURES)", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("verify:", run.Out, StringComparison.Ordinal);
    }

    /// <summary>VERDICT-KEPT: a failing verify whose default failures folder cannot be created (working folder in /proc) keeps exit 1 and writes its JUnit.</summary>
    [Fact]
    public void FailingVerify_FromAnUnwritableFolder_KeepsExit1AndTheJunit()
    {
        string junit = Path.Combine(HostileFiles.Temp(), "j.xml");
        var info = Acphys.Info(["verify", "--fault", "checked-cast", "--only", "ADJUST-RANGE", "--cases", "500", "--max-classes", "1", "--quiet", "--junit", junit]);
        info.Environment.Remove("ACPHYS_FAILURES");
        info.WorkingDirectory = "/proc";
        using var process = System.Diagnostics.Process.Start(info)!;
        string output = process.StandardOutput.ReadToEnd();
        string err = process.StandardError.ReadToEnd();
        Assert.True(process.WaitForExit(TimeSpan.FromMinutes(3)));
        Assert.True(process.ExitCode == 1, $"exit {process.ExitCode}\n{output}\n{err}");
        Assert.Contains("not written:", output, StringComparison.Ordinal);
        Assert.True(File.Exists(junit), "no JUnit");
    }

    /// <summary>PATHS-EXIT-3 (own input 7): diff -o naming a FIFO is exit 3 before the implementation starts.</summary>
    [Fact]
    public void Diff_OutputFolderIsAFifo_IsExit3()
    {
        string fifo = Path.Combine(HostileFiles.Temp(), "fifo");
        HostileFiles.Tool("mkfifo", fifo);
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.ServeCommand, "--cases", "5", "-o", fifo]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("it is a file, not a folder", run.Err, StringComparison.Ordinal);
        Assert.Equal("fifo", HostileFiles.TypeOf(fifo));
    }
}
