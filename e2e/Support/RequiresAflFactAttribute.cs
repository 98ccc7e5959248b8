namespace AcPhys.E2E.Support;

/// <summary>A fact that runs afl-fuzz campaigns: reported as skipped, with the reason, only when afl-fuzz is not on PATH (CI here has it).</summary>
public sealed class RequiresAflFactAttribute : FactAttribute
{
    private static readonly bool Present = (Environment.GetEnvironmentVariable("PATH") ?? string.Empty)
        .Split(':', StringSplitOptions.RemoveEmptyEntries).Any(d => File.Exists(Path.Combine(d, "afl-fuzz")));

    /// <summary>Initializes a new instance.</summary>
    public RequiresAflFactAttribute()
    {
        if (!Present)
        {
            Skip = "SKIPPED: afl-fuzz is not on PATH (Debian: apt-get install afl++); the nightly workflow's campaigns need it";
        }
    }
}
