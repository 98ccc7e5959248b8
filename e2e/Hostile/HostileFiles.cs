using System.Diagnostics;

namespace AcPhys.E2E.Hostile;

/// <summary>Temp folders, scripts and special files for the hostile-input tests (issue 28); nothing under /dev is touched.</summary>
internal static class HostileFiles
{
    /// <summary>Returns a new temp folder.</summary>
    /// <returns>The folder.</returns>
    public static string Temp() => Directory.CreateTempSubdirectory("acphys-hostile-").FullName;

    /// <summary>Writes a shell script that plays a protocol v1 implementation and returns the command line that runs it.</summary>
    /// <param name="body">The script.</param>
    /// <returns>The <c>--impl-cmd</c> value.</returns>
    public static string Script(string body)
    {
        string path = Path.Combine(Temp(), "impl.sh");
        File.WriteAllText(path, body);
        return "sh " + path;
    }

    /// <summary>Writes a file into a new temp folder.</summary>
    /// <param name="name">The file name.</param>
    /// <param name="text">The content.</param>
    /// <returns>The path.</returns>
    public static string Write(string name, string text)
    {
        string path = Path.Combine(Temp(), name);
        File.WriteAllText(path, text);
        return path;
    }

    /// <summary>Runs a system tool (mknod, mkfifo) and fails the test when it fails.</summary>
    /// <param name="tool">The tool.</param>
    /// <param name="args">Its arguments.</param>
    public static void Tool(string tool, params string[] args)
    {
        var info = new ProcessStartInfo(tool) { RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in args)
        {
            info.ArgumentList.Add(a);
        }

        using var p = Process.Start(info)!;
        string err = p.StandardError.ReadToEnd();
        p.WaitForExit();
        Assert.True(p.ExitCode == 0, $"{tool} {string.Join(' ', args)} failed: {err}");
    }

    /// <summary>Returns the file type as stat prints it ("character special file", "fifo", "symbolic link", "regular file").</summary>
    /// <param name="path">The path (not followed).</param>
    /// <returns>The type.</returns>
    public static string TypeOf(string path)
    {
        var info = new ProcessStartInfo("stat") { RedirectStandardOutput = true, UseShellExecute = false, ArgumentList = { "-c", "%F", path } };
        using var p = Process.Start(info)!;
        string type = p.StandardOutput.ReadToEnd().Trim();
        p.WaitForExit();
        return type;
    }

    /// <summary>Gets a copy of a corpus seed in a new temp folder.</summary>
    /// <param name="name">The seed's file name.</param>
    /// <returns>The copy.</returns>
    public static string Seed(string name)
    {
        string path = Path.Combine(Temp(), name);
        File.Copy(Path.Combine(Support.RepoPaths.Corpus, "seeds", name), path);
        return path;
    }
}
