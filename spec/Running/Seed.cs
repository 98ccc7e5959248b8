using System.Globalization;

namespace AcPhys.Spec.Running;

/// <summary>An FsCheck random state (seed, gamma) plus the size it ran at: everything needed to replay a run bit for bit.</summary>
/// <param name="Value">The seed.</param>
/// <param name="Gamma">The gamma (odd).</param>
/// <param name="Size">The FsCheck size, when replaying one failing case.</param>
public readonly record struct Seed(ulong Value, ulong Gamma, int? Size = null)
{
    /// <summary>Derives the fixed seed of one invariant from a base seed: stable across runs, machines and releases.</summary>
    /// <param name="baseSeed">The profile's base seed.</param>
    /// <param name="invariantId">The invariant ID.</param>
    /// <returns>The seed.</returns>
    public static Seed Derive(ulong baseSeed, string invariantId)
    {
        ulong h = 14695981039346656037UL;
        foreach (char ch in invariantId)
        {
            h = (h ^ ch) * 1099511628211UL;
        }

        return new Seed(baseSeed ^ h, (h * 0x9E3779B97F4A7C15UL) | 1UL);
    }

    /// <summary>Returns a fresh seed from the system's random source.</summary>
    /// <returns>The seed.</returns>
    public static Seed Fresh() => new((ulong)Random.Shared.NextInt64(), ((ulong)Random.Shared.NextInt64()) | 1UL);

    /// <summary>Parses <c>seed,gamma[,size]</c> (decimal or 0x-hex).</summary>
    /// <param name="text">The text.</param>
    /// <param name="seed">The parsed seed.</param>
    /// <returns>True on success.</returns>
    public static bool TryParse(string? text, out Seed seed)
    {
        seed = default;
        var parts = (text ?? string.Empty).Split(',', StringSplitOptions.TrimEntries);
        if (parts.Length is < 2 or > 3 || !TryParseU64(parts[0], out var v) || !TryParseU64(parts[1], out var g) || (g & 1) == 0)
        {
            return false;
        }

        int? size = null;
        if (parts.Length == 3)
        {
            if (!int.TryParse(parts[2], NumberStyles.None, CultureInfo.InvariantCulture, out var s))
            {
                return false;
            }

            size = s;
        }

        seed = new Seed(v, g, size);
        return true;
    }

    /// <summary>Formats as <c>seed,gamma[,size]</c> in decimal.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => Size is int s
        ? string.Create(CultureInfo.InvariantCulture, $"{Value},{Gamma},{s}")
        : string.Create(CultureInfo.InvariantCulture, $"{Value},{Gamma}");

    private static bool TryParseU64(string s, out ulong v) =>
        s.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
            ? ulong.TryParse(s.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out v)
            : ulong.TryParse(s, NumberStyles.None, CultureInfo.InvariantCulture, out v);
}
