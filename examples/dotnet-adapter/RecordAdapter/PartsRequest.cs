using System.Numerics;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;

namespace RecordAdapter;

/// <summary>
/// The <c>parts</c> field of <c>find_cell_parts_scene</c> / <c>find_cell_parts_transition</c> (docs/protocol.md, "Parts
/// indoors"): <c>[{cell, origin:{x,y,z}, rotation:{x,y,z,w}, min:{x,y,z}, max:{x,y,z}, r, always2d}]</c>, read into
/// core's <see cref="Part"/> values, within the protocol's bounds so that no request costs unbounded work.
/// </summary>
internal static class PartsRequest
{
    // The protocol's bounds for a parts query (docs/protocol.md, "Parts indoors"): the cells add_cell_block visits grow
    // with the square of the parts' extent (facts §3.4 step 4). A landblock is 192 m.
    private const int MaxParts = 256;
    private const float MaxSize = 200f;
    private const float MaxOrigin = 500f;

    /// <summary>Reads the request's parts; the first is the anchor.</summary>
    /// <param name="request">The request object.</param>
    /// <returns>The parts, 1 to 256 of them.</returns>
    /// <exception cref="InputException">A part that is missing a field, malformed, or beyond the bounds.</exception>
    public static Part[] Read(JsonElement request)
    {
        if (!request.TryGetProperty("parts", out var list) || list.ValueKind != JsonValueKind.Array)
        {
            throw new InputException("field \"parts\" must be an array of {cell, origin, rotation, min, max, r, always2d}");
        }

        int count = list.GetArrayLength();
        if (count is < 1 or > MaxParts)
        {
            throw new InputException($"field \"parts\": expected 1 to {MaxParts} parts (the first is the anchor), got {count}");
        }

        var parts = new Part[count];
        int i = 0;
        foreach (var p in list.EnumerateArray())
        {
            parts[i] = ReadPart(p, i);
            CheckBounds(parts[i], parts[0], i);
            i++;
        }

        return parts;
    }

    private static Part ReadPart(JsonElement p, int i)
    {
        if (p.ValueKind != JsonValueKind.Object)
        {
            throw new InputException($"field \"parts[{i}]\" must be an object");
        }

        string at = $"parts[{i}]";
        var cell = p.TryGetProperty("cell", out var c) && c.ValueKind == JsonValueKind.String && CellIdText.TryParse(c.GetString(), out var id)
            ? id
            : throw new InputException($"field \"{at}.cell\" must be a cell id \"0xAABBCCCC\"");
        var q = Object(p, "rotation", at);
        var rotation = new Quaternion(Server.Float(q, "x", at + ".rotation"), Server.Float(q, "y", at + ".rotation"), Server.Float(q, "z", at + ".rotation"), Server.Float(q, "w", at + ".rotation"));
        var always2d = p.TryGetProperty("always2d", out var a) && a.ValueKind is JsonValueKind.True or JsonValueKind.False
            ? a.GetBoolean()
            : throw new InputException($"field \"{at}.always2d\" must be true or false");
        return new Part(
            cell,
            new Frame(Vector(p, "origin", at), rotation),
            new Box(Vector(p, "min", at), Vector(p, "max", at)),
            Server.Float(p, "r", at),
            always2d);
    }

    private static JsonElement Object(JsonElement p, string name, string at) =>
        p.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.Object ? v : throw new InputException($"field \"{at}.{name}\" must be an object");

    private static Vector3 Vector(JsonElement p, string name, string at)
    {
        var v = Object(p, name, at);
        return new Vector3(Server.Float(v, "x", $"{at}.{name}"), Server.Float(v, "y", $"{at}.{name}"), Server.Float(v, "z", $"{at}.{name}"));
    }

    // The bounds every part of one query keeps: origin x, y within ±500 m, box corners and radius within ±200 m, and
    // every part in the first part's block or a neighbour.
    private static void CheckBounds(Part part, Part first, int i)
    {
        if (Beyond(part.Frame.Origin.X, MaxOrigin) || Beyond(part.Frame.Origin.Y, MaxOrigin))
        {
            throw new InputException($"field \"parts[{i}].origin\": x and y must be within ±{MaxOrigin} m of the block frame");
        }

        if (Beyond(part.Bounds.Min, MaxSize) || Beyond(part.Bounds.Max, MaxSize) || Beyond(part.Radius, MaxSize))
        {
            throw new InputException($"field \"parts[{i}]\": box corners and r must be within ±{MaxSize} m (a landblock is 192 m)");
        }

        var here = part.Cell.Landblock;
        var there = first.Cell.Landblock;
        if (Math.Abs(here.X - there.X) > 1 || Math.Abs(here.Y - there.Y) > 1)
        {
            throw new InputException($"field \"parts[{i}].cell\": every part must lie in the first part's block or a neighbour");
        }
    }

    private static bool Beyond(float v, float max) => float.IsFinite(v) && Math.Abs(v) > max;

    private static bool Beyond(Vector3 v, float max) => Beyond(v.X, max) || Beyond(v.Y, max) || Beyond(v.Z, max);
}
