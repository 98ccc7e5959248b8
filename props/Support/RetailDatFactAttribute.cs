namespace AcPhys.Props.Support;

/// <summary>A fact that needs the user's retail dat files (ACPHYS_CELL_DAT, ACPHYS_PORTAL_DAT) and the shared positions file; skipped when any is absent.</summary>
public sealed class RetailDatFactAttribute : FactAttribute
{
    /// <summary>Initializes a new instance; sets <see cref="FactAttribute.Skip"/> when a file is missing.</summary>
    public RetailDatFactAttribute()
    {
        if (Cell is null || Portal is null || !File.Exists(Cell) || !File.Exists(Portal))
        {
            Skip = "SKIPPED: set ACPHYS_CELL_DAT and ACPHYS_PORTAL_DAT to the game's client_cell_1.dat and client_portal.dat (docs/ports.md \"Your own world\")";
        }
        else if (!File.Exists(RequiresSharedDataFactAttribute.DataFile))
        {
            Skip = $"SKIPPED: {RequiresSharedDataFactAttribute.DataFile} is not present";
        }
    }

    /// <summary>Gets the cell database's path, or null.</summary>
    public static string? Cell => Environment.GetEnvironmentVariable("ACPHYS_CELL_DAT") is { Length: > 0 } p ? p : null;

    /// <summary>Gets the portal database's path, or null.</summary>
    public static string? Portal => Environment.GetEnvironmentVariable("ACPHYS_PORTAL_DAT") is { Length: > 0 } p ? p : null;
}
