namespace AcPhys.Formats.Dat;

/// <summary>
/// Writes and reads BSP trees in retail's node layout (dat-records.md, BSP node): depth first, a node's children
/// right after its plane and before its own trailing fields; no ALIGN inside a tree.
/// </summary>
public static class BspCodec
{
    /// <summary>The deepest tree the reader accepts (a deeper one is refused, not a stack overflow).</summary>
    public const int MaxDepth = 256;

    /// <summary>Writes a tree.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="node">The root.</param>
    /// <param name="type">The tree type.</param>
    public static void Write(ByteWriter w, BspNode node, BspTreeType type)
    {
        w.U32(node.Tag);
        if (node.IsLeaf)
        {
            w.I32(node.LeafIndex);
            if (type == BspTreeType.Physics)
            {
                w.I32(node.Solid);
                w.Sphere(node.Sphere);
                Ids(w, node.Polygons);
            }

            return;
        }

        w.Plane(node.Plane);
        if (node.Positive is { } p)
        {
            Write(w, p, type);
        }

        if (node.Negative is { } n)
        {
            Write(w, n, type);
        }

        if (node.Tag == BspTags.Port)
        {
            if (type == BspTreeType.Drawing)
            {
                w.Sphere(node.Sphere);
                w.U32((uint)node.Polygons.Count);
                w.U32((uint)node.Portals.Count);
                for (int i = 0; i < node.Polygons.Count; i++)
                {
                    w.U16(node.Polygons[i]);
                }

                for (int i = 0; i < node.Portals.Count; i++)
                {
                    w.I16(node.Portals[i].Portal);
                    w.I16(node.Portals[i].Polygon);
                }
            }

            return;
        }

        if (type != BspTreeType.Cell)
        {
            w.Sphere(node.Sphere);
        }

        if (type == BspTreeType.Drawing)
        {
            Ids(w, node.Polygons);
        }
    }

    /// <summary>Reads a tree; unknown tags, missing children and trees deeper than <see cref="MaxDepth"/> are refused.</summary>
    /// <param name="r">The reader.</param>
    /// <param name="type">The tree type.</param>
    /// <param name="field">The field name for messages.</param>
    /// <returns>The root.</returns>
    public static BspNode Read(ByteReader r, BspTreeType type, string? field) => Node(r, type, field, 0);


    private static BspNode Node(ByteReader r, BspTreeType type, string? field, int depth)
    {
        int at = r.Position;
        r.Require(depth < MaxDepth, field, at, $"tree deeper than {MaxDepth} nodes");
        uint tag = r.U32(field + ".tag");
        var children = BspTags.Children(tag) ?? throw r.Error(field + ".tag", at, $"unknown BSP tag '{BspTags.Name(tag)}' (0x{tag:X8})");
        if (tag == BspTags.Leaf)
        {
            int index = r.I32(field + ".leafIndex");
            if (type != BspTreeType.Physics)
            {
                return BspNode.NewLeaf(index) with { Offset = at };
            }

            int solid = r.I32(field + ".solid");
            var sphere = r.Sphere(r.Path($"{field}.sphere"));
            return BspNode.NewLeaf(index) with { Offset = at, Solid = solid, Sphere = sphere, Polygons = Ids(r, r.Path($"{field}.polygons")) };
        }

        var plane = r.Plane(r.Path($"{field}.plane"));
        var pos = children.Positive ? Node(r, type, r.Path($"{field}.pos"), depth + 1) : null;
        var neg = children.Negative ? Node(r, type, r.Path($"{field}.neg"), depth + 1) : null;
        var node = new BspNode(tag, plane, pos, neg) { Offset = at };
        if (tag == BspTags.Port)
        {
            if (type != BspTreeType.Drawing)
            {
                return node;
            }

            var sphere = r.Sphere(r.Path($"{field}.sphere"));
            int cAt = r.Position;
            uint numPolys = r.U32(field + ".numPolys");
            uint numPortals = r.U32(field + ".numPortals");
            int polys = r.Count(numPolys, 2, field + ".numPolys", cAt);
            var ids = new ushort[polys];
            for (int i = 0; i < polys; i++)
            {
                ids[i] = r.U16(field + ".polygons");
            }

            int portals = r.Count(numPortals, 4, field + ".numPortals", cAt + 4);
            var pairs = new (short, short)[portals];
            for (int i = 0; i < portals; i++)
            {
                pairs[i] = (r.I16(field + ".portal"), r.I16(field + ".polygon"));
            }

            return node with { Sphere = sphere, Polygons = ids, Portals = pairs };
        }

        if (type == BspTreeType.Cell)
        {
            return node;
        }

        node = node with { Sphere = r.Sphere(r.Path($"{field}.sphere")) };
        return type == BspTreeType.Drawing ? node with { Polygons = Ids(r, r.Path($"{field}.polygons")) } : node;
    }

    private static void Ids(ByteWriter w, IReadOnlyList<ushort> ids)
    {
        w.U32((uint)ids.Count);
        for (int i = 0; i < ids.Count; i++)
        {
            w.U16(ids[i]);
        }
    }

    private static ushort[] Ids(ByteReader r, string? field)
    {
        int at = r.Position;
        int n = r.Count(r.U32(field + ".count"), 2, field + ".count", at);
        var ids = new ushort[n];
        for (int i = 0; i < n; i++)
        {
            ids[i] = r.U16(field);
        }

        return ids;
    }
}
