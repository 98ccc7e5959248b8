using System.Globalization;
using System.Numerics;
using System.Text;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Scenes;

/// <summary>
/// Reads and writes scenes (docs/indoor.md, "Scene files"). Reading validates everything and refuses the scene
/// whole on the first problem, naming its JSON path: malformed values, duplicate ids, non-unit quaternions,
/// degenerate or non-finite planes, unknown cell references, cells in blocks the scene does not declare.
/// </summary>
public static class SceneJson
{
    /// <summary>Tolerance on a quaternion's length.</summary>
    public const float UnitTolerance = 1e-4f;

    private const int MaxItems = SceneRules.MaxItems;

    /// <summary>Serialises a scene as a standalone JSON object.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The text.</returns>
    public static string Write(Scene scene)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true }))
        {
            WriteValue(w, scene);
        }

        return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
    }

    /// <summary>Serialises a scene on one line (no whitespace), as protocol v1 sends it in <c>find_cell</c>.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The compact text.</returns>
    public static string WriteCompact(Scene scene)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = false }))
        {
            WriteValue(w, scene);
        }

        return Encoding.UTF8.GetString(buffer.ToArray());
    }

    /// <summary>Writes a scene object at the writer's position.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="scene">The scene.</param>
    public static void WriteValue(Utf8JsonWriter w, Scene scene)
    {
        w.WriteStartObject();
        Blocks(w, "blocks", scene.Blocks);
        Blocks(w, "unloadedBlocks", scene.UnloadedBlocks);
        w.WriteStartArray("unloadedCells");
        foreach (var c in scene.UnloadedCells)
        {
            w.WriteStringValue(CellIdText.Format(c));
        }

        w.WriteEndArray();
        w.WriteStartArray("buildings");
        foreach (var b in scene.Buildings)
        {
            w.WriteStartObject();
            w.WriteString("block", b.Block.ToString());
            Vec(w, "origin", b.Origin);
            w.WriteStartArray("portals");
            foreach (var p in b.Portals)
            {
                w.WriteStartObject();
                w.WriteString("cell", Hex16(p.Cell));
                w.WriteNumber("portal", p.Portal);
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("cells");
        foreach (var c in scene.Cells)
        {
            w.WriteStartObject();
            w.WriteString("id", CellIdText.Format(c.Id));
            w.WriteStartObject("frame");
            Vec(w, "origin", c.Origin);
            w.WriteStartArray("rotation");
            foreach (var v in new[] { c.Rotation.W, c.Rotation.X, c.Rotation.Y, c.Rotation.Z })
            {
                w.WriteRawValue(FloatText.Format(v));
            }

            w.WriteEndArray();
            w.WriteEndObject();
            w.WriteStartArray("pieces");
            foreach (var p in c.Pieces)
            {
                w.WriteStartObject();
                if (p.Box is { } box)
                {
                    w.WriteStartObject("box");
                    Vec(w, "min", box.Min);
                    Vec(w, "max", box.Max);
                    w.WriteEndObject();
                }
                else
                {
                    w.WriteStartArray("planes");
                    foreach (var plane in p.Planes!)
                    {
                        PlaneValue(w, plane);
                    }

                    w.WriteEndArray();
                }

                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteStartArray("portals");
            foreach (var p in c.Portals)
            {
                w.WriteStartObject();
                w.WritePropertyName("plane");
                PlaneValue(w, p.Plane);
                w.WriteString("other", p.IsExit ? "outside" : Hex16(p.Other));
                w.WriteBoolean("portalSide", p.PortalSide);
                w.WriteNumber("otherPortal", p.OtherPortal);
                if (p.Polygon is { } polygon)
                {
                    w.WriteStartArray("polygon");
                    foreach (var v in polygon)
                    {
                        w.WriteStartArray();
                        w.WriteRawValue(FloatText.Format(v.X));
                        w.WriteRawValue(FloatText.Format(v.Y));
                        w.WriteRawValue(FloatText.Format(v.Z));
                        w.WriteEndArray();
                    }

                    w.WriteEndArray();
                }

                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteStartArray("visible");
            foreach (var v in c.Visible)
            {
                w.WriteStringValue(CellIdText.Format(v));
            }

            w.WriteEndArray();
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Parses and validates a scene.</summary>
    /// <param name="json">The text.</param>
    /// <param name="source">A name for messages.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path.</exception>
    public static Scene Read(string json, string source)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new InputFormatException($"{source}: $: not JSON ({e.Message})");
        }

        using (doc)
        {
            // Unreadable text first: the duplicate-key search reads every property name, and a lone surrogate
            // escape in one throws InvalidOperationException (found by the scene-json fuzz target).
            if (AcPhys.Formats.Corpus.JsonStrings.FirstUnreadable(doc.RootElement, "$") is { } bad)
            {
                throw new InputFormatException($"{source}: {bad}: not valid text (a lone UTF-16 surrogate escape)");
            }

            if (AcPhys.Formats.Corpus.JsonKeys.FirstDuplicate(doc.RootElement) is { } duplicate)
            {
                throw new InputFormatException($"{source}: {AcPhys.Formats.Corpus.JsonKeys.Message(duplicate)}");
            }

            return Read(doc.RootElement, source, "$");
        }
    }

    /// <summary>Reads and validates a scene object.</summary>
    /// <param name="e">The element.</param>
    /// <param name="source">A name for messages.</param>
    /// <param name="at">The element's JSON path.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path.</exception>
    public static Scene Read(JsonElement e, string source, string at)
    {
        var r = new Reader(source);
        r.Require(e.ValueKind == JsonValueKind.Object, at, "expected an object");
        if (AcPhys.Formats.Corpus.JsonStrings.FirstUnreadable(e, at) is { } bad)
        {
            throw new InputFormatException($"{source}: {bad}: not valid text (a lone UTF-16 surrogate escape)");
        }

        var blocks = r.BlockList(e, "blocks", at, required: true);
        var unloadedBlocks = r.BlockList(e, "unloadedBlocks", at, required: false);
        var declared = r.Rules.Declared(blocks.Concat(unloadedBlocks));

        var unloadedCells = new List<(CellId Id, string Path)>();
        foreach (var (item, path) in r.Items(e, "unloadedCells", at, required: false))
        {
            unloadedCells.Add((r.EnvCellId(item, path), path));
        }

        var cellElements = r.Items(e, "cells", at, required: true);
        var cells = new List<SceneCell>();
        foreach (var (c, path) in cellElements)
        {
            cells.Add(r.Cell(c, path));
        }

        var buildings = new List<SceneBuilding>();
        foreach (var (b, path) in r.Items(e, "buildings", at, required: false))
        {
            buildings.Add(r.Building(b, path));
        }

        // Cross-references: ids unique, every cell in a declared block, every reference known.
        r.Rules.References(at, declared, cells, unloadedCells, buildings);

        return new Scene([.. blocks.Select(b => b.Block)], buildings, cells)
        {
            UnloadedBlocks = [.. unloadedBlocks.Select(b => b.Block)],
            UnloadedCells = [.. unloadedCells.Select(c => c.Id)],
        };
    }

    private static string Hex16(ushort v) => "0x" + v.ToString("X4", CultureInfo.InvariantCulture);

    private static void Blocks(Utf8JsonWriter w, string name, IReadOnlyList<LandblockId> blocks)
    {
        w.WriteStartArray(name);
        foreach (var b in blocks)
        {
            w.WriteStringValue(b.ToString());
        }

        w.WriteEndArray();
    }

    private static void Vec(Utf8JsonWriter w, string name, Vector3 v)
    {
        w.WriteStartArray(name);
        w.WriteRawValue(FloatText.Format(v.X));
        w.WriteRawValue(FloatText.Format(v.Y));
        w.WriteRawValue(FloatText.Format(v.Z));
        w.WriteEndArray();
    }

    private static void PlaneValue(Utf8JsonWriter w, CellPlane p)
    {
        w.WriteStartObject();
        Vec(w, "n", p.Normal);
        w.WritePropertyName("d");
        w.WriteRawValue(FloatText.Format(p.D));
        w.WriteEndObject();
    }

    private sealed class Reader(string source)
    {
        public SceneRules Rules { get; } = new(source);

        public void Require(bool ok, string path, string message) => Rules.Require(ok, path, message);

        public JsonElement Prop(JsonElement parent, string name, string at)
        {
            Require(parent.TryGetProperty(name, out var e), $"{at}.{name}", "missing");
            return e;
        }

        public List<(JsonElement Item, string Path)> Items(JsonElement parent, string name, string at, bool required)
        {
            if (!parent.TryGetProperty(name, out var e))
            {
                Require(!required, $"{at}.{name}", "missing");
                return [];
            }

            Require(e.ValueKind == JsonValueKind.Array, $"{at}.{name}", $"expected an array of at most {MaxItems} items");
            Rules.Count(e.GetArrayLength(), $"{at}.{name}");
            return [.. e.EnumerateArray().Select((x, i) => (x, $"{at}.{name}[{i}]"))];
        }

        public List<(LandblockId Block, string Path)> BlockList(JsonElement parent, string name, string at, bool required) =>
            [.. Items(parent, name, at, required).Select(x => (Block(x.Item, x.Path), x.Path))];

        public LandblockId Block(JsonElement e, string path)
        {
            string text = e.ValueKind == JsonValueKind.String ? e.GetString()! : string.Empty;
            bool ok = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) && text.Length == 6
                && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var v);
            Require(ok, path, $"expected a block id \"0x\" and 4 hex digits, got {AcPhys.Formats.Values.InputQuote.Json(e)}");
            return new LandblockId(ushort.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture));
        }

        public CellId EnvCellId(JsonElement e, string path)
        {
            Require(e.ValueKind == JsonValueKind.String && CellIdText.TryParse(e.GetString()!, out var id), path, $"expected a cell id \"0x\" and 8 hex digits, got {AcPhys.Formats.Values.InputQuote.Json(e)}");
            CellIdText.TryParse(e.GetString()!, out var cell);
            Rules.EnvCell(cell, path);
            return cell;
        }

        public ushort Low16(JsonElement e, string path, bool env)
        {
            string text = e.ValueKind == JsonValueKind.String ? e.GetString()! : string.Empty;
            bool ok = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) && text.Length == 6
                && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out _);
            Require(ok, path, $"expected a low word \"0x\" and 4 hex digits{(env ? string.Empty : " or \"outside\"")}, got {AcPhys.Formats.Values.InputQuote.Json(e)}");
            ushort v = ushort.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture);
            Rules.EnvLow(v, path);
            return v;
        }

        public float Number(JsonElement e, string path)
        {
            bool ok = AcPhys.Formats.Values.Float32Json.TryRead(e, nonFiniteNames: false, out float f, out string? problem);
            Require(ok, path, problem ?? string.Empty);
            return f;
        }

        public float[] Numbers(JsonElement parent, string name, string at, int count)
        {
            var e = Prop(parent, name, at);
            string path = $"{at}.{name}";
            Require(e.ValueKind == JsonValueKind.Array && e.GetArrayLength() == count, path, $"expected an array of {count} numbers");
            return [.. e.EnumerateArray().Select((x, i) => Number(x, $"{path}[{i}]"))];
        }

        public Vector3 Vec(JsonElement parent, string name, string at)
        {
            var v = Numbers(parent, name, at, 3);
            return new Vector3(v[0], v[1], v[2]);
        }

        // The optional "polygon": [[x, y, z], ...] of a portal; its derived plane must be the plane given (issue #29).
        public IReadOnlyList<Vector3>? PortalPolygon(JsonElement portal, CellPlane plane, string at)
        {
            if (!portal.TryGetProperty("polygon", out var e) || e.ValueKind == JsonValueKind.Null)
            {
                return null;
            }

            string path = at + ".polygon";
            Require(e.ValueKind == JsonValueKind.Array && e.GetArrayLength() is >= 3 and <= 64, path, "expected an array of 3 to 64 vertices [x, y, z]");
            var vertices = e.EnumerateArray().Select((v, i) =>
            {
                Require(v.ValueKind == JsonValueKind.Array && v.GetArrayLength() == 3, $"{path}[{i}]", "expected [x, y, z]");
                var xyz = v.EnumerateArray().Select((x, k) => Number(x, $"{path}[{i}][{k}]")).ToArray();
                return new Vector3(xyz[0], xyz[1], xyz[2]);
            }).ToArray();
            var derived = AcPhys.Formats.Dat.PolygonPlane.Of(vertices);
            Require(derived is not null, path, "the polygon spans no area");
            var got = derived.GetValueOrDefault();
            var given = AcPhys.Formats.Dat.PolygonPlane.Unit(plane);
            Require(
                Vector3.Dot(got.Normal, given.Normal) > 1 - 1e-5f && MathF.Abs(got.D - given.D) <= 1e-3f,
                path,
                $"the polygon's plane (n {got.Normal}, d {got.D}) is not the portal's plane (n {given.Normal}, d {given.D}): wound the other way, or not on the plane");
            return vertices;
        }

        public CellPlane Plane(JsonElement e, string path)
        {
            Require(e.ValueKind == JsonValueKind.Object, path, "expected an object {\"n\": [x, y, z], \"d\": d}");
            var n = Vec(e, "n", path);
            float d = Number(Prop(e, "d", path), path + ".d");
            Rules.Normal(n, path);
            return new CellPlane(n, d);
        }

        public SceneCell Cell(JsonElement c, string at)
        {
            Require(c.ValueKind == JsonValueKind.Object, at, "expected an object");
            var id = EnvCellId(Prop(c, "id", at), at + ".id");
            var frame = Prop(c, "frame", at);
            Require(frame.ValueKind == JsonValueKind.Object, at + ".frame", "expected an object {\"origin\", \"rotation\"}");
            var origin = Vec(frame, "origin", at + ".frame");
            var q = Numbers(frame, "rotation", at + ".frame", 4);
            var rotation = new Quaternion(q[1], q[2], q[3], q[0]);
            Rules.UnitRotation(rotation, at + ".frame.rotation");

            var pieces = new List<ScenePiece>();
            var pieceItems = Items(c, "pieces", at, required: true);
            Require(pieceItems.Count > 0, at + ".pieces", "a cell needs at least one piece");
            foreach (var (p, path) in pieceItems)
            {
                pieces.Add(Piece(p, path));
            }

            var portals = new List<ScenePortal>();
            foreach (var (p, path) in Items(c, "portals", at, required: true))
            {
                Require(p.ValueKind == JsonValueKind.Object, path, "expected an object");
                var plane = Plane(Prop(p, "plane", path), path + ".plane");
                var otherElement = Prop(p, "other", path);
                ushort other = otherElement.ValueKind == JsonValueKind.String && otherElement.GetString() == "outside"
                    ? CellPortal.Outside
                    : Low16(otherElement, path + ".other", env: false);
                var side = Prop(p, "portalSide", path);
                Require(side.ValueKind is JsonValueKind.True or JsonValueKind.False, path + ".portalSide", "expected true or false");
                ushort otherPortal = 0xFFFF;
                if (p.TryGetProperty("otherPortal", out var op))
                {
                    Require(op.ValueKind == JsonValueKind.Number && op.TryGetUInt16(out otherPortal), path + ".otherPortal", "expected an integer 0..65535");
                }

                portals.Add(new ScenePortal(plane, other, side.GetBoolean(), otherPortal) { Polygon = PortalPolygon(p, plane, path) });
            }

            var visible = Items(c, "visible", at, required: false).Select(v => EnvCellId(v.Item, v.Path)).ToList();
            return new SceneCell(id, origin, rotation, pieces, portals, visible);
        }

        public SceneBuilding Building(JsonElement b, string at)
        {
            Require(b.ValueKind == JsonValueKind.Object, at, "expected an object");
            var block = Block(Prop(b, "block", at), at + ".block");
            var origin = Vec(b, "origin", at);
            var portals = new List<SceneBldPortal>();
            foreach (var (p, path) in Items(b, "portals", at, required: true))
            {
                Require(p.ValueKind == JsonValueKind.Object, path, "expected an object");
                ushort cell = Low16(Prop(p, "cell", path), path + ".cell", env: true);
                var portal = Prop(p, "portal", path);
                Require(portal.ValueKind == JsonValueKind.Number && portal.TryGetUInt16(out ushort index), path + ".portal", "expected an integer 0..65535");
                portals.Add(new SceneBldPortal(cell, portal.GetUInt16()));
            }

            return new SceneBuilding(block, origin, portals);
        }

        private ScenePiece Piece(JsonElement p, string at)
        {
            Require(p.ValueKind == JsonValueKind.Object, at, "expected an object with \"box\" or \"planes\"");
            if (p.TryGetProperty("box", out var box))
            {
                var min = Vec(box, "min", at + ".box");
                var max = Vec(box, "max", at + ".box");
                Rules.Box(min, max, at + ".box");
                return ScenePiece.FromBox(min, max);
            }

            var planes = Items(p, "planes", at, required: true).Select(x => Plane(x.Item, x.Path)).ToList();
            Rules.Convex(planes, at);

            return new ScenePiece(null, planes);
        }
    }
}
