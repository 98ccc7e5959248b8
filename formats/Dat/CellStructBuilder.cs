using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// Builds a cell's CellStruct (docs/dat-scenes.md, "Environment"): per piece its corner vertices and face polygons;
/// then one quad polygon per portal lying in the portal's plane and wound so its plane (<see cref="PolygonPlane"/>)
/// is the portal plane; the cell BSP and the physics BSP shaped as core's <see cref="CellBsp"/> builds them
/// (piece 0's planes the positive chain, further pieces under negative children, facts §5.7).
/// </summary>
public static class CellStructBuilder
{
    /// <summary>The dummy surface index every polygon uses (the EnvCell lists one surface).</summary>
    public const short Surface = 0;

    /// <summary>Builds the CellStruct; portal i's polygon id is <c>PortalPolygonIds[i]</c>.</summary>
    /// <param name="key">The CellStruct key.</param>
    /// <param name="cell">The cell.</param>
    /// <returns>The record.</returns>
    public static CellStructRecord Build(uint key, SceneCell cell)
    {
        var pieces = cell.Pieces.Select(p => p.ToConvex()).ToArray();
        var vertices = new List<DatVertex>();
        var polygons = new List<DatPolygon>();
        var facesOf = new List<ushort[]>();
        foreach (var piece in pieces)
        {
            int first = vertices.Count;
            var corners = piece.Vertices;
            for (int i = 0; i < corners.Count; i++)
            {
                vertices.Add(Vertex(first + i, corners[i]));
            }

            var faces = new List<ushort>(piece.Planes.Count);
            var on = new int[corners.Count];
            for (int k = 0; k < piece.Planes.Count; k++)
            {
                var plane = piece.Planes[k];
                int n = 0;
                for (int i = 0; i < corners.Count; i++)
                {
                    if (MathF.Abs(plane.Distance(corners[i])) <= 1e-3f)
                    {
                        on[n++] = i;
                    }
                }

                if (n < 3)
                {
                    continue;
                }

                faces.Add(checked((ushort)polygons.Count));
                polygons.Add(Polygon(polygons.Count, Wind(on.AsSpan(0, n), corners, plane.Normal, first)));
            }

            facesOf.Add([.. faces]);
        }

        var bounds = ConvexPiece.BoundsOf(pieces);
        var portalIds = new List<ushort>();
        foreach (var portal in cell.Portals)
        {
            int first = vertices.Count;
            vertices.AddRange(PortalQuad(PolygonPlane.Unit(portal.Plane), bounds).Select((v, i) => Vertex(first + i, v)));
            portalIds.Add(checked((ushort)polygons.Count));
            polygons.Add(Polygon(polygons.Count, [(short)first, (short)(first + 1), (short)(first + 2), (short)(first + 3)]));
        }

        var physicsPolygons = polygons.Take(polygons.Count - portalIds.Count).ToList();
        var cellBsp = Tree(pieces, facesOf, physics: false);
        var physicsBsp = Tree(pieces, facesOf, physics: true);
        return new CellStructRecord(key, vertices, polygons, portalIds, cellBsp, physicsPolygons, physicsBsp, null);
    }

    /// <summary>Returns the four corners of the portal quad: centred on the cell's bounds, spanning them, wound so u × v = N.</summary>
    /// <param name="plane">The unit portal plane.</param>
    /// <param name="bounds">The cell's bounds.</param>
    /// <returns>The corners, counter-clockwise seen from the normal's side.</returns>
    public static Vector3[] PortalQuad(CellPlane plane, Box bounds)
    {
        var n = plane.Normal;
        var (u, v) = PolygonPlane.Tangents(n);
        var centre = (bounds.Min + bounds.Max) / 2;
        float s = MathF.Ceiling((Vector3.Distance(bounds.Min, bounds.Max) / 2) + 1);
        if (PolygonPlane.AxisOf(n) is { } axis)
        {
            // Exact: every corner has coordinate −D·N[axis] (N[axis] = ±1) on the axis, so the plane read back is bit-exact.
            centre[axis] = -plane.D * n[axis];
        }
        else
        {
            centre -= plane.Distance(centre) * n;
        }

        Vector3 C(float a, float b)
        {
            var p = centre + (a * s * u) + (b * s * v);
            if (PolygonPlane.AxisOf(n) is { } k)
            {
                p[k] = centre[k];
            }

            return p;
        }

        return [C(-1, -1), C(1, -1), C(1, 1), C(-1, 1)];
    }

    private static BspNode Tree(ConvexPiece[] pieces, List<ushort[]> faces, bool physics)
    {
        // As CellBsp: the root is piece 0's chain; piece i's chain root hangs under piece i−1's chain root's negative child.
        BspNode? negative = null;
        for (int i = pieces.Length - 1; i >= 1; i--)
        {
            negative = Chain(pieces[i], i, faces[i], physics, negative);
        }

        return Chain(pieces[0], 0, faces[0], physics, negative);
    }

    private static BspNode Chain(ConvexPiece piece, int index, ushort[] faces, bool physics, BspNode? negative)
    {
        var b = piece.Bounds;
        var sphere = new Sphere((b.Min + b.Max) / 2, Vector3.Distance(b.Min, b.Max) / 2);
        BspNode next = physics ? BspNode.NewLeaf(index) with { Solid = 1, Sphere = sphere, Polygons = faces } : BspNode.NewLeaf(index);
        for (int i = piece.Planes.Count - 1; i >= 0; i--)
        {
            var node = BspNode.Internal(piece.Planes[i], next, i == 0 ? negative : null);
            next = physics ? node with { Sphere = sphere } : node;
        }

        return next;
    }

    // The face's corners counter-clockwise about its normal: by angle around their centroid, ties in corner order.
    private static short[] Wind(ReadOnlySpan<int> on, IReadOnlyList<Vector3> corners, Vector3 normal, int first)
    {
        var (u, v) = PolygonPlane.Tangents(Vector3.Normalize(normal));
        var sum = Vector3.Zero;
        foreach (int i in on)
        {
            sum += corners[i];
        }

        var centroid = sum / on.Length;
        var angle = new float[on.Length];
        var order = new int[on.Length];
        for (int k = 0; k < on.Length; k++)
        {
            var d = corners[on[k]] - centroid;
            angle[k] = MathF.Atan2(Vector3.Dot(d, v), Vector3.Dot(d, u));
            order[k] = k;
        }

        // Stable insertion sort with float.CompareTo (NaN first), the order a LINQ OrderBy on the angle gives.
        for (int k = 1; k < order.Length; k++)
        {
            int x = order[k], j = k - 1;
            while (j >= 0 && angle[order[j]].CompareTo(angle[x]) > 0)
            {
                order[j + 1] = order[j];
                j--;
            }

            order[j + 1] = x;
        }

        var ids = new short[on.Length];
        for (int k = 0; k < ids.Length; k++)
        {
            ids[k] = (short)(first + on[order[k]]);
        }

        return ids;
    }

    private static DatVertex Vertex(int id, Vector3 p) => new(checked((ushort)id), p, Vector3.UnitZ, [Vector2.Zero]);

    private static DatPolygon Polygon(int id, short[] vertexIds) =>
        new(checked((ushort)id), 0, 1, Surface, Surface, vertexIds, new byte[vertexIds.Length], []);
}
