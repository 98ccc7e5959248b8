namespace AcPhys.Props.Support;

/// <summary>A fact that is reported as skipped, with the reason, when ../shared/data/retail-positions.tsv is absent.</summary>
public sealed class RequiresSharedDataFactAttribute : FactAttribute
{
    /// <summary>Gets the data file's path.</summary>
    public static string DataFile => Path.Combine(RepoPaths.Shared, "data", "retail-positions.tsv");

    /// <summary>Initializes a new instance; sets <see cref="FactAttribute.Skip"/> when the data is missing.</summary>
    public RequiresSharedDataFactAttribute()
    {
        if (!File.Exists(DataFile))
        {
            Skip = $"SKIPPED: {DataFile} is not present (real retail positions live in ../shared beside the repository)";
        }
    }
}
