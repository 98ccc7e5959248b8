using System.Globalization;

namespace AcPhys.Formats.Dat;

/// <summary>The record types a scene is written as.</summary>
public enum RecordType
{
    /// <summary>EnvCell 0xAABBcccc, cccc in 0x0100..0xFFFD (cell dat).</summary>
    EnvCell,

    /// <summary>Environment 0x0D?????? (portal dat).</summary>
    Environment,

    /// <summary>LandblockInfo 0xAABBFFFE (cell dat).</summary>
    LandblockInfo,

    /// <summary>Landblock 0xAABBFFFF (cell dat).</summary>
    Landblock,
}

/// <summary>How a record id names its type and dat (dat-records.md, "How an id names its record type").</summary>
public static class RecordIds
{
    /// <summary>The one Environment record a scene is written with (its low word is every EnvCell's environment id).</summary>
    public const uint EnvironmentId = 0x0D000001;

    /// <summary>Returns the type of a record id in a dat.</summary>
    /// <param name="id">The id.</param>
    /// <param name="portalDat">True for the portal dat, false for the cell dat.</param>
    /// <returns>The type, or null when no type of that dat has such ids.</returns>
    public static RecordType? TypeOf(uint id, bool portalDat)
    {
        if (portalDat)
        {
            return id >> 24 == 0x0D ? RecordType.Environment : null;
        }

        uint low = id & 0xFFFF;
        return low switch
        {
            0xFFFF => RecordType.Landblock,
            0xFFFE => RecordType.LandblockInfo,
            >= 0x0100 => RecordType.EnvCell,
            _ => null,
        };
    }

    /// <summary>Gets the file name of a record: 8 upper-case hex digits and <c>.bin</c>.</summary>
    /// <param name="id">The id.</param>
    /// <returns>The name.</returns>
    public static string FileName(uint id) => id.ToString("X8", CultureInfo.InvariantCulture) + ".bin";

    /// <summary>Formats an id as <c>0x</c> and 8 hex digits.</summary>
    /// <param name="id">The id.</param>
    /// <returns>The text.</returns>
    public static string Text(uint id) => "0x" + id.ToString("X8", CultureInfo.InvariantCulture);
}
