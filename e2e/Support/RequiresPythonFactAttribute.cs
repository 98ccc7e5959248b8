using System.Diagnostics;

namespace AcPhys.E2E.Support;

/// <summary>A fact that needs <c>python3</c> on PATH (the Python example implementation); reported as skipped without it.</summary>
public sealed class RequiresPythonFactAttribute : FactAttribute
{
    private static readonly Lazy<bool> Present = new(() =>
    {
        try
        {
            using var p = Process.Start(new ProcessStartInfo("python3", "--version") { RedirectStandardOutput = true, RedirectStandardError = true });
            return p is not null && p.WaitForExit(10_000) && p.ExitCode == 0;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return false;
        }
    });

    /// <summary>Initializes a new instance.</summary>
    public RequiresPythonFactAttribute()
    {
        if (!Present.Value)
        {
            Skip = "SKIPPED: python3 is not on PATH (needed for examples/python/acphys_impl.py)";
        }
    }
}
