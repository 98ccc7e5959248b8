namespace AcPhys.E2E.Support;

/// <summary>Finds the repository root (the folder holding AcPhysVerify.sln) and the shared folder beside it.</summary>
internal static class RepoPaths
{
    private static readonly Lazy<string> RootLazy = new(() =>
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "AcPhysVerify.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("AcPhysVerify.sln not found above " + AppContext.BaseDirectory);
    });

    /// <summary>Gets the repository root.</summary>
    public static string Root => RootLazy.Value;

    /// <summary>Gets ../shared beside the repository (may not exist).</summary>
    public static string Shared => Path.GetFullPath(Path.Combine(Root, "..", "shared"));

    /// <summary>Gets the corpus folder.</summary>
    public static string Corpus => Path.Combine(Root, "corpus");
}
