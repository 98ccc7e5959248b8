namespace AcPhys.Fuzz.Tests;

/// <summary>Where the repository is, for tests that read its corpus files.</summary>
internal static class RepoPaths
{
    /// <summary>Gets the folder holding AcPhysVerify.sln, above the test binaries.</summary>
    public static string Root
    {
        get
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            {
                if (File.Exists(Path.Combine(dir.FullName, "AcPhysVerify.sln")))
                {
                    return dir.FullName;
                }
            }

            throw new InvalidOperationException("AcPhysVerify.sln not found above " + AppContext.BaseDirectory);
        }
    }
}
