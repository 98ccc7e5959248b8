using System.Diagnostics;

namespace AcPhys.E2E.Support;

/// <summary>Captures written by the independent writer, examples/python/acphys_capture.py.</summary>
internal static class PythonCapture
{
    /// <summary>Runs the writer and saves what it printed.</summary>
    /// <param name="dir">The folder.</param>
    /// <param name="name">The file name.</param>
    /// <param name="args">The writer's arguments.</param>
    /// <returns>The file's path.</returns>
    public static string Write(string dir, string name, IEnumerable<string> args)
    {
        string path = Path.Combine(dir, name);
        var info = new ProcessStartInfo("python3") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        info.ArgumentList.Add(Path.Combine(RepoPaths.Root, "examples", "python", "acphys_capture.py"));
        foreach (string w in args)
        {
            info.ArgumentList.Add(w);
        }

        var run = Acphys.RunToEnd(info, "acphys_capture.py");
        Assert.True(run.Exit == 0, run.ToString());
        File.WriteAllText(path, run.Out);
        return path;
    }
}
