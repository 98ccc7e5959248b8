using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// Where a walk happens in a dat world: a landblock and, optionally, a point (x, y in that block's frame, metres) and a
/// radius. Without a point the place is the whole block.
/// </summary>
/// <param name="Block">The landblock.</param>
/// <param name="X">The point's x in the block frame (0..192), or NaN for the whole block.</param>
/// <param name="Y">The point's y in the block frame (0..192), or NaN for the whole block.</param>
/// <param name="Radius">The radius (0..192 m).</param>
public readonly record struct ScenePlace(LandblockId Block, float X = float.NaN, float Y = float.NaN, float Radius = 0)
{
    /// <summary>Gets a value indicating whether the place is the whole block.</summary>
    public bool WholeBlock => float.IsNaN(X);

    /// <summary>Parses <c>0xAABB</c> (or <c>AABB</c>).</summary>
    /// <param name="text">The text.</param>
    /// <param name="block">The block.</param>
    /// <returns>True when valid and on the map.</returns>
    public static bool TryParseBlock(string text, out LandblockId block)
    {
        string hex = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) ? text[2..] : text;
        block = default;
        if (hex.Length is < 1 or > 4 || !ushort.TryParse(hex, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ushort v))
        {
            return false;
        }

        block = new LandblockId(v);
        return block.IsOnMap;
    }

    /// <summary>Parses <c>X,Y,R</c>: a point in the block frame and a radius.</summary>
    /// <param name="block">The block.</param>
    /// <param name="text">The text.</param>
    /// <param name="place">The place.</param>
    /// <returns>True when three finite numbers, x and y in 0..192, r in 0..192.</returns>
    public static bool TryParseAround(LandblockId block, string text, out ScenePlace place)
    {
        place = new ScenePlace(block);
        var parts = text.Split(',');
        if (parts.Length != 3)
        {
            return false;
        }

        var v = new float[3];
        for (int i = 0; i < 3; i++)
        {
            if (!float.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out v[i]) || !float.IsFinite(v[i]) || v[i] < 0 || v[i] > LandDefs.BlockLength)
            {
                return false;
            }
        }

        place = new ScenePlace(block, v[0], v[1], v[2]);
        return true;
    }

    /// <summary>Formats the place as the CLI takes it.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => WholeBlock ? Block.ToString() : string.Create(CultureInfo.InvariantCulture, $"{Block} around {X:R},{Y:R},{Radius:R}");
}
