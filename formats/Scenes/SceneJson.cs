using System.Globalization;
using System.Numerics;
using System.Text;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// Reads and writes scenes (docs/indoor.md, "Scene files"). Reading validates everything and refuses the scene
/// whole on the first problem, naming its JSON path: malformed values, duplicate ids, non-unit quaternions,
/// degenerate or non-finite planes, unknown cell references, cells in blocks the scene does not declare.
/// </summary>
public static class SceneJson
{
    /// <summary>Tolerance on a quaternion's length.</summary>
    public const float UnitTolerance = 1e-4f;

    private const int MaxItems = 10_000;

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
    /// <exception cref="SceneFormatException">Any defect, with its JSON path.</exception>
    public static Scene Read(string json, string source)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new SceneFormatException($"{source}: $: not JSON ({e.Message})");
        }

        using (doc)
        {
            // Unreadable text first: the duplicate-key search reads every property name, and a lone surrogate
            // escape in one throws InvalidOperationException (found by the scene-json fuzz target).
            if (Corpus.JsonStrings.FirstUnreadable(doc.RootElement, "$") is { } bad)
            {
                throw new SceneFormatException($"{source}: {bad}: not valid text (a lone UTF-16 surrogate escape)");
            }

            if (AcPhys.Spec.Corpus.JsonKeys.FirstDuplicate(doc.RootElement) is { } duplicate)
            {
                throw new SceneFormatException($"{source}: {AcPhys.Spec.Corpus.JsonKeys.Message(duplicate)}");
            }

            return Read(doc.RootElement, source, "$");
        }
    }

    /// <summary>Reads and validates a scene object.</summary>
    /// <param name="e">The element.</param>
    /// <param name="source">A name for messages.</param>
    /// <param name="at">The element's JSON path.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="SceneFormatException">Any defect, with its JSON path.</exception>
    public static Scene Read(JsonElement e, string source, string at)
    {
        var r = new Reader(source);
        r.Require(e.ValueKind == JsonValueKind.Object, at, "expected an object");
        if (Corpus.JsonStrings.FirstUnreadable(e, at) is { } bad)
        {
            throw new SceneFormatException($"{source}: {bad}: not valid text (a lone UTF-16 surrogate escape)");
        }

        var blocks = r.BlockList(e, "blocks", at, required: true);
        var unloadedBlocks = r.BlockList(e, "unloadedBlocks", at, required: false);
        var declared = new HashSet<LandblockId>();
        foreach (var (b, path) in blocks.Concat(unloadedBlocks))
        {
            r.Require(b.IsOnMap, path, $"block {b} is off the map (byte 0xFF)");
            r.Require(declared.Add(b), path, $"duplicate block {b}");
        }

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
        var known = new Dictionary<CellId, string>();
        for (int i = 0; i < cells.Count; i++)
        {
            string path = $"{cellElements[i].Path}.id";
            r.Require(known.TryAdd(cells[i].Id, path), path, $"duplicate cell {cells[i].Id} (first at {known.GetValueOrDefault(cells[i].Id)})");
            r.Require(declared.Contains(cells[i].Id.Landblock), path, $"cell {cells[i].Id} lies in block {cells[i].Id.Landblock}, which the scene does not declare");
        }

        foreach (var (id, path) in unloadedCells)
        {
            r.Require(known.TryAdd(id, path), path, $"duplicate cell {id} (first at {known.GetValueOrDefault(id)})");
            r.Require(declared.Contains(id.Landblock), path, $"cell {id} lies in block {id.Landblock}, which the scene does not declare");
        }

        for (int i = 0; i < cells.Count; i++)
        {
            var c = cells[i];
            string at0 = cellElements[i].Path;
            for (int p = 0; p < c.Portals.Count; p++)
            {
                var portal = c.Portals[p];
                if (portal.IsExit)
                {
                    continue;
                }

                var other = c.Id.WithLow(portal.Other);
                r.Require(known.ContainsKey(other), $"{at0}.portals[{p}].other", $"unknown cell {other} (not declared in cells or unloadedCells)");
                r.Require(other != c.Id, $"{at0}.portals[{p}].other", $"a portal of {c.Id} leads to itself");
            }

            for (int v = 0; v < c.Visible.Count; v++)
            {
                r.Require(known.ContainsKey(c.Visible[v]), $"{at0}.visible[{v}]", $"unknown cell {c.Visible[v]} (not declared in cells or unloadedCells)");
            }
        }

        for (int i = 0; i < buildings.Count; i++)
        {
            var b = buildings[i];
            string at0 = $"{at}.buildings[{i}]";
            r.Require(declared.Contains(b.Block), at0 + ".block", $"block {b.Block} is not declared by the scene");
            for (int p = 0; p < b.Portals.Count; p++)
            {
                var id = b.Block.BlockCell.WithLow(b.Portals[p].Cell);
                r.Require(known.ContainsKey(id), $"{at0}.portals[{p}].cell", $"unknown cell {id} (not declared in cells or unloadedCells)");
                if (b.Portals[p].Portal != BldPortal.None && cells.FirstOrDefault(c => c.Id == id) is { } target)
                {
                    // A building portal names one of its cell's portals, or carries retail's invalid marker 0xFFFF
                    // (facts §5, EnvTransit; generated "invalid doors"); issue 28: portal 99 of a 2-portal cell was accepted.
                    // A cell with no portals (a sealed closet entered only by its building portal) is named by portal 0:
                    // the sphere path never reads the index beyond the 0xFFFF test (facts §5.3).
                    int count = Math.Max(1, target.Portals.Count);
                    r.Require(b.Portals[p].Portal < count, $"{at0}.portals[{p}].portal", $"cell {id} has {target.Portals.Count} portals (0..{count - 1}, or 65535 for none), not portal {b.Portals[p].Portal}");
                }
            }
        }

        var owners = new Dictionary<CellId, int>();
        for (int i = 0; i < buildings.Count; i++)
        {
            var b = buildings[i];
            var owner = new Building(b.Block, b.Origin, []).OwningCell();
            if (!owner.IsNone)
            {
                r.Require(owners.TryAdd(owner, i), $"{at}.buildings[{i}].origin", $"land cell {owner} already holds building {owners.GetValueOrDefault(owner)} (a land cell holds at most one)");
            }
        }

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
        public void Require(bool ok, string path, string message)
        {
            if (!ok)
            {
                throw new SceneFormatException($"{source}: {path}: {message}");
            }
        }

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

            Require(e.ValueKind == JsonValueKind.Array && e.GetArrayLength() <= MaxItems, $"{at}.{name}", $"expected an array of at most {MaxItems} items");
            return [.. e.EnumerateArray().Select((x, i) => (x, $"{at}.{name}[{i}]"))];
        }

        public List<(LandblockId Block, string Path)> BlockList(JsonElement parent, string name, string at, bool required) =>
            [.. Items(parent, name, at, required).Select(x => (Block(x.Item, x.Path), x.Path))];

        public LandblockId Block(JsonElement e, string path)
        {
            string text = e.ValueKind == JsonValueKind.String ? e.GetString()! : string.Empty;
            bool ok = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) && text.Length == 6
                && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var v);
            Require(ok, path, $"expected a block id \"0x\" and 4 hex digits, got {Values.InputQuote.Json(e)}");
            return new LandblockId(ushort.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture));
        }

        public CellId EnvCellId(JsonElement e, string path)
        {
            Require(e.ValueKind == JsonValueKind.String && CellIdText.TryParse(e.GetString()!, out var id), path, $"expected a cell id \"0x\" and 8 hex digits, got {Values.InputQuote.Json(e)}");
            CellIdText.TryParse(e.GetString()!, out var cell);
            Require(cell.IsEnv, path, $"{cell} is not an env cell id (low word 0x0100..0xFFFD)");
            return cell;
        }

        public ushort Low16(JsonElement e, string path, bool env)
        {
            string text = e.ValueKind == JsonValueKind.String ? e.GetString()! : string.Empty;
            bool ok = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) && text.Length == 6
                && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out _);
            Require(ok, path, $"expected a low word \"0x\" and 4 hex digits{(env ? string.Empty : " or \"outside\"")}, got {Values.InputQuote.Json(e)}");
            ushort v = ushort.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture);
            Require(v is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId, path, $"0x{v:X4} is not an env cell low word (0x0100..0xFFFD)");
            return v;
        }

        public float Number(JsonElement e, string path)
        {
            bool ok = Values.Float32Json.TryRead(e, nonFiniteNames: false, out float f, out string? problem);
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
            var derived = Spec.Dat.PolygonPlane.Of(vertices);
            Require(derived is not null, path, "the polygon spans no area");
            var got = derived.GetValueOrDefault();
            var given = Spec.Dat.PolygonPlane.Unit(plane);
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
            Require(n.Length() > 1e-6f, path + ".n", $"degenerate plane: normal ({n.X}, {n.Y}, {n.Z}) has no direction");
            Require(float.IsFinite(n.Length()), path + ".n", "non-finite plane normal (its length overflows)");
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
            float length = rotation.Length();
            Require(MathF.Abs(length - 1f) <= UnitTolerance, at + ".frame.rotation", $"quaternion (W, X, Y, Z) has length {length.ToString("R", CultureInfo.InvariantCulture)}, not 1 (±{UnitTolerance})");

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
                Require(min.X < max.X && min.Y < max.Y && min.Z < max.Z, at + ".box", "degenerate box: min must be below max on every axis");
                return ScenePiece.FromBox(min, max);
            }

            var planes = Items(p, "planes", at, required: true).Select(x => Plane(x.Item, x.Path)).ToList();
            try
            {
                _ = new ConvexPiece(planes);
            }
            catch (ArgumentException e)
            {
                throw new SceneFormatException($"{source}: {at}.planes: {e.Message.Split(" (Parameter", 2)[0]}");
            }

            return new ScenePiece(null, planes);
        }
    }
}
