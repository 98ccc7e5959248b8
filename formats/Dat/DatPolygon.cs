using System.Numerics;

namespace AcPhys.Formats.Dat;

/// <summary>A CellStruct vertex: id, origin, normal and UVs (dat-records.md, CellStruct).</summary>
/// <param name="Id">The key.</param>
/// <param name="Origin">The position (cell-local).</param>
/// <param name="Normal">The lighting normal (unused by physics).</param>
/// <param name="Uvs">Texture coordinates.</param>
public sealed record DatVertex(ushort Id, Vector3 Origin, Vector3 Normal, IReadOnlyList<Vector2> Uvs);

/// <summary>A CellStruct polygon (dat-records.md, Polygon).</summary>
/// <param name="Id">The key.</param>
/// <param name="Stippling">4 NoPos, 8 NoNeg.</param>
/// <param name="SidesType">0, 1 None, 2 Clockwise, 3 CounterClockwise.</param>
/// <param name="PosSurface">Index into the EnvCell's surfaces.</param>
/// <param name="NegSurface">Index into the EnvCell's surfaces (ignored by ACE when SidesType is 1).</param>
/// <param name="VertexIds">Vertex keys, in winding order.</param>
/// <param name="PosUvs">Positive-side UV indices (none when stippling has NoPos).</param>
/// <param name="NegUvs">Negative-side UV indices (only with SidesType 2 and no NoNeg).</param>
public sealed record DatPolygon(ushort Id, byte Stippling, int SidesType, short PosSurface, short NegSurface, IReadOnlyList<short> VertexIds, IReadOnlyList<byte> PosUvs, IReadOnlyList<byte> NegUvs)
{
    /// <summary>Stippling bit: no positive UVs.</summary>
    public const byte NoPos = 4;

    /// <summary>Stippling bit: no negative UVs.</summary>
    public const byte NoNeg = 8;

    /// <summary>Gets a value indicating whether the positive UV indices are stored.</summary>
    public bool HasPosUvs => (Stippling & NoPos) == 0;

    /// <summary>Gets a value indicating whether the negative UV indices are stored (the NoUVS trap: 0x14 still stores them).</summary>
    public bool HasNegUvs => SidesType == 2 && (Stippling & NoNeg) == 0;
}
