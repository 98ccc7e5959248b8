using System.Buffers.Binary;

namespace AcPhys.Formats.Dat;

/// <summary>
/// A Landblock record 0xAABBFFFF (dat-records.md, Landblock): hasObjects, 81 terrain words, 81 height bytes (bytes,
/// not the WORDs ACE's comment claims), ALIGN 251 → 252. Scenes are written flat: terrain 0 and height index 0.
/// hasObjects is 1 exactly when the block's LandblockInfo is written: ACE reads a LandblockInfo only when the flag is 1
/// (dat-records.md), so a faithful reader would otherwise see none of the block's buildings (issue #29).
/// </summary>
public static class LandblockRecord
{
    /// <summary>The record size: 4 + 4 + 162 + 81 + 1 pad.</summary>
    public const int Length = 252;

    /// <summary>Writes a flat landblock (terrain 0, heights 0).</summary>
    /// <param name="id">The record id (0xAABBFFFF).</param>
    /// <param name="hasObjects">Whether the block's LandblockInfo follows (buildings, env cells).</param>
    /// <returns>The bytes.</returns>
    public static byte[] WriteFlat(uint id, bool hasObjects)
    {
        // Everything after the two words is zero: 81 terrain words, 81 height bytes and the pad.
        var bytes = new byte[Length];
        BinaryPrimitives.WriteUInt32LittleEndian(bytes, id);
        BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(4), hasObjects ? 1u : 0u);
        return bytes;
    }

    /// <summary>Reads a landblock and checks it is flat (scenes carry no terrain).</summary>
    /// <param name="data">The bytes.</param>
    /// <param name="expectedId">The id.</param>
    /// <returns>hasObjects: whether a reader reads the block's LandblockInfo.</returns>
    /// <exception cref="InputFormatException">Not a landblock of this id, hasObjects other than 0 or 1, not flat, or trailing bytes.</exception>
    public static bool ReadFlat(byte[] data, uint expectedId) => ByteReader.Strictly(named => ReadFlat(data, expectedId, named));

    internal static bool ReadFlat(byte[] data, uint expectedId, bool named)
    {
        var r = new ByteReader(data, "Landblock", expectedId, named);
        uint id = r.U32("id");
        r.Require(id == expectedId, "id", 0, $"record id {RecordIds.Text(id)} is not its name {RecordIds.Text(expectedId)}");
        uint hasObjects = r.U32("hasObjects");
        r.Require(hasObjects <= 1, "hasObjects", 4, $"{hasObjects}: expected 0 or 1 (ACE treats anything but 1 as 0)");
        if (!named && r.NextAreZero((81 * 2) + 81))
        {
            // A flat block (every scene's): one scan of the terrain and height words instead of 162 checked reads; any
            // other block is read field by field, which refuses it with the same message (issue 26).
            r.Skip((81 * 2) + 81);
        }
        else
        {
            for (int i = 0; i < 81; i++)
            {
                int at = r.Position;
                ushort t = r.U16(r.Path($"terrain[{i}]"));
                r.Require(t == 0, r.Path($"terrain[{i}]"), at, $"0x{t:X4}: scenes are flat (expected 0)");
            }

            for (int i = 0; i < 81; i++)
            {
                int at = r.Position;
                byte h = r.U8(r.Path($"height[{i}]"));
                r.Require(h == 0, r.Path($"height[{i}]"), at, $"{h}: scenes are flat (expected 0)");
            }
        }

        r.Align("height");
        r.End();
        return hasObjects == 1;
    }
}
