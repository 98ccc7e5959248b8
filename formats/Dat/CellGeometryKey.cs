using System.Runtime.InteropServices;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// A key equal for cells whose CellStructs would be equal (<see cref="CellStructBuilder.Build"/> reads nothing else):
/// the piece count, each piece's plane count and planes, the portal count and each portal's unit plane, by bits.
/// </summary>
public readonly struct CellGeometryKey : IEquatable<CellGeometryKey>
{
    private readonly uint[] words;
    private readonly int hash;

    private CellGeometryKey(uint[] words)
    {
        this.words = words;
        var h = default(HashCode);
        h.AddBytes(MemoryMarshal.AsBytes(words.AsSpan()));
        hash = h.ToHashCode();
    }

    /// <summary>Returns the key of a cell's geometry.</summary>
    /// <param name="cell">The cell.</param>
    /// <returns>The key.</returns>
    public static CellGeometryKey Of(SceneCell cell)
    {
        // Counts before their items, so no two geometries share a key. One array, sized first (issue 26: a list and a
        // string per cell were a tenth of writing a scene).
        int count = 2 + (4 * cell.Portals.Count);
        for (int i = 0; i < cell.Pieces.Count; i++)
        {
            count += 1 + (4 * cell.Pieces[i].ToConvex().Planes.Count);
        }

        var words = new uint[count];
        int at = 0;
        words[at++] = (uint)cell.Pieces.Count;
        for (int i = 0; i < cell.Pieces.Count; i++)
        {
            var planes = cell.Pieces[i].ToConvex().Planes;
            words[at++] = (uint)planes.Count;
            for (int k = 0; k < planes.Count; k++)
            {
                at = Bits(words, at, planes[k]);
            }
        }

        words[at++] = (uint)cell.Portals.Count;
        for (int i = 0; i < cell.Portals.Count; i++)
        {
            at = Bits(words, at, PolygonPlane.Unit(cell.Portals[i].Plane));
        }

        return new CellGeometryKey(words);
    }

    /// <inheritdoc/>
    public bool Equals(CellGeometryKey other) => hash == other.hash && words.AsSpan().SequenceEqual(other.words);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is CellGeometryKey k && Equals(k);

    /// <inheritdoc/>
    public override int GetHashCode() => hash;

    private static int Bits(uint[] words, int at, CellPlane p)
    {
        words[at] = BitConverter.SingleToUInt32Bits(p.Normal.X);
        words[at + 1] = BitConverter.SingleToUInt32Bits(p.Normal.Y);
        words[at + 2] = BitConverter.SingleToUInt32Bits(p.Normal.Z);
        words[at + 3] = BitConverter.SingleToUInt32Bits(p.D);
        return at + 4;
    }
}
