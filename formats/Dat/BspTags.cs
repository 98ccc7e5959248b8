namespace AcPhys.Formats.Dat;

/// <summary>
/// BSP node tags (dat-records.md, BSP node; facts §5.7): 4 ASCII letters, stored reversed, so the u32 read
/// little-endian is the letters read big-endian. Unknown tags are refused (ACE would parse them as childless nodes).
/// </summary>
public static class BspTags
{
    /// <summary>LEAF.</summary>
    public static readonly uint Leaf = Of("LEAF");

    /// <summary>PORT: always a positive then a negative child.</summary>
    public static readonly uint Port = Of("PORT");

    private static readonly uint[] PositiveOnly = [Of("BPnn"), Of("BPIn")];
    private static readonly uint[] NegativeOnly = [Of("BpIN"), Of("BpnN")];
    private static readonly uint[] Both = [Of("BPIN"), Of("BPnN")];

    /// <summary>Returns the u32 of a 4-letter tag.</summary>
    /// <param name="letters">The letters.</param>
    /// <returns>The tag.</returns>
    public static uint Of(string letters) => ((uint)letters[0] << 24) | ((uint)letters[1] << 16) | ((uint)letters[2] << 8) | letters[3];

    /// <summary>Returns the letters of a tag, with non-printable bytes as <c>?</c>.</summary>
    /// <param name="tag">The tag.</param>
    /// <returns>The text.</returns>
    public static string Name(uint tag) => new([.. new[] { tag >> 24, (tag >> 16) & 0xFF, (tag >> 8) & 0xFF, tag & 0xFF }.Select(b => b is >= 0x20 and < 0x7F ? (char)b : '?')]);

    /// <summary>Returns the writer's tag for a node's children: BPnn, BpnN or BPnN.</summary>
    /// <param name="positive">Has a positive child.</param>
    /// <param name="negative">Has a negative child.</param>
    /// <returns>The tag.</returns>
    public static uint For(bool positive, bool negative) => positive && negative ? Both[1] : positive ? PositiveOnly[0] : NegativeOnly[1];

    /// <summary>Returns which children a tag carries, or null for an unknown tag.</summary>
    /// <param name="tag">The tag.</param>
    /// <returns>(positive, negative), or null.</returns>
    public static (bool Positive, bool Negative)? Children(uint tag) =>
        tag == Leaf ? (false, false)
        : tag == Port || Both.Contains(tag) ? (true, true)
        : PositiveOnly.Contains(tag) ? (true, false)
        : NegativeOnly.Contains(tag) ? (false, true)
        : null;
}
