using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// Reads a CellStruct back into scene geometry: the cell BSP's positive chains are the convex pieces (the root's chain
/// first, then the chains found under negative children, depth first — the order <see cref="CellStructBuilder"/> and
/// core's <see cref="CellBsp"/> lay them out); portal planes come from their polygons' vertices.
/// </summary>
public static class CellStructPieces
{
    /// <summary>Returns the pieces of a cell BSP. Six axis planes in box order (−x, +x, −y, +y, −z, +z faces) come back as a box.</summary>
    /// <param name="root">The cell BSP.</param>
    /// <param name="where">Record and field, for messages.</param>
    /// <returns>The pieces.</returns>
    /// <exception cref="InputFormatException">A chain does not end in a leaf, or its planes bound no convex piece.</exception>
    public static List<ScenePiece> Of(BspNode root, string where)
    {
        var pieces = new List<ScenePiece>();
        Collect(root, where, pieces);
        return pieces;
    }

    /// <summary>Returns a piece from its planes in chain order: a box when they are <see cref="ConvexPiece.FromBox"/>'s six planes.</summary>
    /// <param name="planes">The planes.</param>
    /// <returns>The piece.</returns>
    public static ScenePiece PieceOf(IReadOnlyList<CellPlane> planes)
    {
        if (planes.Count == 6
            && planes[0].Normal == Vector3.UnitX && planes[1].Normal == -Vector3.UnitX
            && planes[2].Normal == Vector3.UnitY && planes[3].Normal == -Vector3.UnitY
            && planes[4].Normal == Vector3.UnitZ && planes[5].Normal == -Vector3.UnitZ)
        {
            var min = new Vector3(-planes[0].D, -planes[2].D, -planes[4].D);
            var max = new Vector3(planes[1].D, planes[3].D, planes[5].D);
            if (min.X < max.X && min.Y < max.Y && min.Z < max.Z)
            {
                return ScenePiece.FromBox(min, max);
            }
        }

        return new ScenePiece(null, [.. planes]);
    }

    /// <summary>Returns the plane of a portal polygon.</summary>
    /// <param name="cs">The CellStruct.</param>
    /// <param name="polygonId">The polygon id.</param>
    /// <param name="where">Record and field, for messages.</param>
    /// <returns>The plane.</returns>
    /// <exception cref="InputFormatException">The polygon or one of its vertices is missing, or it spans no area.</exception>
    public static CellPlane PortalPlane(CellStructRecord cs, ushort polygonId, string where)
    {
        var polygon = cs.Polygons.FirstOrDefault(p => p.Id == polygonId)
            ?? throw new InputFormatException($"{where}: polygon {polygonId} is not in CellStruct {cs.Key}");
        if (!cs.PortalPolygonIds.Contains(polygonId))
        {
            throw new InputFormatException($"{where}: polygon {polygonId} is not in CellStruct {cs.Key}'s portal polygon ids");
        }

        var points = new List<Vector3>();
        foreach (short id in polygon.VertexIds)
        {
            var v = cs.Vertices.FirstOrDefault(x => x.Id == (ushort)id)
                ?? throw new InputFormatException($"{where}: polygon {polygonId} names vertex {id}, which CellStruct {cs.Key} lacks");
            points.Add(v.Origin);
        }

        return PolygonPlane.Of(points) ?? throw new InputFormatException($"{where}: polygon {polygonId} spans no area (no plane)");
    }

    // Whether the planes are exactly those ConvexPiece.FromBox makes for the box, in its order.
    private static bool AreBoxPlanes(CellPlane[] planes, Box box)
    {
        static bool Same(CellPlane p, Vector3 n, float d) =>
            BitConverter.SingleToUInt32Bits(p.Normal.X) == BitConverter.SingleToUInt32Bits(n.X)
            && BitConverter.SingleToUInt32Bits(p.Normal.Y) == BitConverter.SingleToUInt32Bits(n.Y)
            && BitConverter.SingleToUInt32Bits(p.Normal.Z) == BitConverter.SingleToUInt32Bits(n.Z)
            && BitConverter.SingleToUInt32Bits(p.D) == BitConverter.SingleToUInt32Bits(d);

        return Same(planes[0], Vector3.UnitX, -box.Min.X) && Same(planes[1], -Vector3.UnitX, box.Max.X)
            && Same(planes[2], Vector3.UnitY, -box.Min.Y) && Same(planes[3], -Vector3.UnitY, box.Max.Y)
            && Same(planes[4], Vector3.UnitZ, -box.Min.Z) && Same(planes[5], -Vector3.UnitZ, box.Max.Z);
    }

    private static void Collect(BspNode node, string where, List<ScenePiece> pieces)
    {
        var planes = new List<CellPlane>();
        var chain = new List<BspNode>();
        var n = node;
        while (!n.IsLeaf)
        {
            planes.Add(n.Plane);
            chain.Add(n);
            n = n.Positive ?? throw new InputFormatException($"{where}: node at byte {n.Offset} ('{BspTags.Name(n.Tag)}') ends a positive chain without a LEAF");
        }

        CellPlane[] own = [.. planes];
        ConvexPiece built;
        try
        {
            built = new ConvexPiece(own);
        }
        catch (ArgumentException e)
        {
            throw new InputFormatException($"{where}: the positive chain from byte {node.Offset} is no convex piece ({planes.Count} planes): {e.Message.Split(" (Parameter", 2)[0]}");
        }

        // The piece checked here is the one queried: a box's too, when its six planes are FromBox's, bit for bit (a
        // normal's zero may carry either sign and still read as a box; such a box's piece is built from the box).
        var piece = PieceOf(own);
        pieces.Add(piece.Box is not { } box ? ScenePiece.OfChecked(own, built)
            : AreBoxPlanes(own, box) ? ScenePiece.OfCheckedBox(box.Min, box.Max, built)
            : piece);
        foreach (var c in chain)
        {
            if (c.Negative is { } neg)
            {
                Collect(neg, where, pieces);
            }
        }
    }
}
