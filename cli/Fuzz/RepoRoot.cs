namespace AcPhys.Cli.Fuzz;

/// <summary>Finds the checkout <c>acphys fuzz</c> works in: the nearest folder above the working directory (or the tool) holding AcPhysVerify.sln.</summary>
internal static class RepoRoot
{
    /// <summary>Returns the checkout's root folder.</summary>
    /// <returns>The folder.</returns>
    /// <exception cref="UsageException">Neither the working directory nor the tool lies inside a checkout.</exception>
    public static string Find()
    {
        foreach (string start in new[] { Environment.CurrentDirectory, AppContext.BaseDirectory })
        {
            for (var dir = new DirectoryInfo(start); dir is not null; dir = dir.Parent)
            {
                if (File.Exists(Path.Combine(dir.FullName, "AcPhysVerify.sln")) && Directory.Exists(Path.Combine(dir.FullName, "fuzz")))
                {
                    return dir.FullName;
                }
            }
        }

        throw new UsageException("fuzz builds the harness from source: run it inside an AcPhysVerify checkout");
    }
}
