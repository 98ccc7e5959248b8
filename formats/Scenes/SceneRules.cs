using System.Globalization;
using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Scenes;

/// <summary>
/// The rules a scene must keep (docs/indoor.md, "Scene files"), on typed values: the scene file reader
/// (<see cref="SceneJson"/>) applies them while it reads, and <see cref="Check"/> applies them to a scene already built
/// (one read from dat records), in the reader's order, so both refuse a scene with the same first message.
/// </summary>
/// <param name="source">A name for messages.</param>
public sealed class SceneRules(string source)
{
    /// <summary>The most items of any list in a scene.</summary>
    public const int MaxItems = 10_000;

    /// <summary>Checks a built scene as <see cref="SceneJson.Read(System.Text.Json.JsonElement, string, string)"/> checks the same scene read from its JSON.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="at">The scene's JSON path, for messages (<c>$</c>).</param>
    /// <returns>The scene.</returns>
    /// <exception cref="InputFormatException">The first broken rule, with the JSON path it would have in the scene's file.</exception>
    public Scene Check(Scene scene, string at)
    {
        // The paths are spelt only for a message (issue 26: spelling every field's path was most of this check's time
        // on a served gate); the rules, their order and their messages are the JSON reader's.
        var root = new At(at);
        var blocks = Paths(scene.Blocks, at, "blocks");
        var unloadedBlocks = Paths(scene.UnloadedBlocks, at, "unloadedBlocks");
        var declared = Declared(blocks.Concat(unloadedBlocks));
        var unloadedCells = Paths(scene.UnloadedCells, at, "unloadedCells");
        foreach (var (id, path) in unloadedCells)
        {
            EnvCell(id, path);
        }

        Count(scene.Cells.Count, root.Then(".cells"));
        for (int i = 0; i < scene.Cells.Count; i++)
        {
            Cell(scene.Cells[i], root.Index(".cells", i));
        }

        Count(scene.Buildings.Count, root.Then(".buildings"));
        for (int i = 0; i < scene.Buildings.Count; i++)
        {
            Building(scene.Buildings[i], root.Index(".buildings", i));
        }

        References(at, declared, scene.Cells, unloadedCells, scene.Buildings);
        return scene;
    }

    /// <summary>Throws the scene's format error when a rule is broken.</summary>
    /// <param name="ok">True when the rule holds.</param>
    /// <param name="path">The JSON path of the value.</param>
    /// <param name="message">What is wrong.</param>
    /// <exception cref="InputFormatException">When <paramref name="ok"/> is false.</exception>
    public void Require(bool ok, string path, string message)
    {
        if (!ok)
        {
            throw new InputFormatException($"{source}: {path}: {message}");
        }
    }

    /// <summary>Throws the scene's format error when a rule is broken; the message is written only then.</summary>
    /// <param name="ok">True when the rule holds.</param>
    /// <param name="path">The JSON path of the value.</param>
    /// <param name="message">What is wrong (an interpolated string, formatted only when <paramref name="ok"/> is false: issue 26).</param>
    /// <exception cref="InputFormatException">When <paramref name="ok"/> is false.</exception>
    public void Require(bool ok, string path, [System.Runtime.CompilerServices.InterpolatedStringHandlerArgument("ok")] ref AcPhys.Formats.Dat.FailureText message) =>
        Require(ok, new At(path), ref message);

    /// <summary>A list holds at most <see cref="MaxItems"/> items.</summary>
    /// <param name="count">Its length.</param>
    /// <param name="path">Its path.</param>
    public void Count(int count, string path) => Count(count, new At(path));

    /// <summary>Every declared block (loaded or not) lies on the map and is declared once.</summary>
    /// <param name="blocks">The blocks with their paths, loaded first.</param>
    /// <returns>The declared blocks.</returns>
    public HashSet<LandblockId> Declared(IEnumerable<(LandblockId Block, string Path)> blocks)
    {
        var declared = new HashSet<LandblockId>();
        foreach (var (b, path) in blocks)
        {
            Require(b.IsOnMap, path, $"block {b} is off the map (byte 0xFF)");
            Require(declared.Add(b), path, $"duplicate block {b}");
        }

        return declared;
    }

    /// <summary>A cell id names an env cell.</summary>
    /// <param name="cell">The id.</param>
    /// <param name="path">Its path.</param>
    public void EnvCell(CellId cell, string path) => EnvCell(cell, new At(path));

    /// <summary>A low word names an env cell.</summary>
    /// <param name="low">The low word.</param>
    /// <param name="path">Its path.</param>
    public void EnvLow(ushort low, string path) => EnvLow(low, new At(path));

    /// <summary>A cell's rotation is a unit quaternion (±<see cref="SceneJson.UnitTolerance"/>).</summary>
    /// <param name="rotation">The rotation.</param>
    /// <param name="path">The rotation's path.</param>
    public void UnitRotation(Quaternion rotation, string path) => UnitRotation(rotation, new At(path));

    /// <summary>A box is below its max corner on every axis.</summary>
    /// <param name="min">The min corner.</param>
    /// <param name="max">The max corner.</param>
    /// <param name="path">The box's path.</param>
    public void Box(Vector3 min, Vector3 max, string path) => Box(min, max, new At(path));

    /// <summary>A plane's normal has a direction and a finite length.</summary>
    /// <param name="normal">The normal.</param>
    /// <param name="path">The plane's path.</param>
    public void Normal(Vector3 normal, string path) => Normal(normal, new At(path));

    /// <summary>A piece's planes bound a convex piece.</summary>
    /// <param name="planes">The planes.</param>
    /// <param name="path">The piece's path.</param>
    public void Convex(IReadOnlyList<CellPlane> planes, string path) => Convex(planes, new At(path));

    /// <summary>
    /// The cross-references of a scene: cell ids unique and in declared blocks, every portal, visible cell and building
    /// portal naming a known cell (and a building portal an existing portal of it), one building per land cell.
    /// </summary>
    /// <param name="at">The scene's path.</param>
    /// <param name="declared">The declared blocks.</param>
    /// <param name="cells">The loaded cells (at <c>{at}.cells[i]</c>).</param>
    /// <param name="unloadedCells">The unloaded cells with their paths.</param>
    /// <param name="buildings">The buildings (at <c>{at}.buildings[i]</c>).</param>
    public void References(string at, HashSet<LandblockId> declared, IReadOnlyList<SceneCell> cells, IReadOnlyList<(CellId Id, string Path)> unloadedCells, IReadOnlyList<SceneBuilding> buildings)
    {
        var root = new At(at);
        var known = new Dictionary<CellId, At>();
        for (int i = 0; i < cells.Count; i++)
        {
            var path = root.Index(".cells", i).Then(".id");
            Require(known.TryAdd(cells[i].Id, path), path, $"duplicate cell {cells[i].Id} (first at {known.GetValueOrDefault(cells[i].Id)})");
            Require(declared.Contains(cells[i].Id.Landblock), path, $"cell {cells[i].Id} lies in block {cells[i].Id.Landblock}, which the scene does not declare");
        }

        foreach (var (id, text) in unloadedCells)
        {
            var path = new At(text);
            Require(known.TryAdd(id, path), path, $"duplicate cell {id} (first at {known.GetValueOrDefault(id)})");
            Require(declared.Contains(id.Landblock), path, $"cell {id} lies in block {id.Landblock}, which the scene does not declare");
        }

        for (int i = 0; i < cells.Count; i++)
        {
            var c = cells[i];
            var at0 = root.Index(".cells", i);
            for (int p = 0; p < c.Portals.Count; p++)
            {
                var portal = c.Portals[p];
                if (portal.IsExit)
                {
                    continue;
                }

                var other = c.Id.WithLow(portal.Other);
                Require(known.ContainsKey(other), at0.Index(".portals", p).Then(".other"), $"unknown cell {other} (not declared in cells or unloadedCells)");
                Require(other != c.Id, at0.Index(".portals", p).Then(".other"), $"a portal of {c.Id} leads to itself");
            }

            for (int v = 0; v < c.Visible.Count; v++)
            {
                Require(known.ContainsKey(c.Visible[v]), at0.Index(".visible", v), $"unknown cell {c.Visible[v]} (not declared in cells or unloadedCells)");
            }
        }

        for (int i = 0; i < buildings.Count; i++)
        {
            var b = buildings[i];
            string at0 = $"{at}.buildings[{i}]";
            Require(declared.Contains(b.Block), at0 + ".block", $"block {b.Block} is not declared by the scene");
            for (int p = 0; p < b.Portals.Count; p++)
            {
                var id = b.Block.BlockCell.WithLow(b.Portals[p].Cell);
                Require(known.ContainsKey(id), $"{at0}.portals[{p}].cell", $"unknown cell {id} (not declared in cells or unloadedCells)");
                if (b.Portals[p].Portal != BldPortal.None && cells.FirstOrDefault(c => c.Id == id) is { } target)
                {
                    // A building portal names one of its cell's portals, or carries retail's invalid marker 0xFFFF
                    // (facts §5, EnvTransit; generated "invalid doors"); issue 28: portal 99 of a 2-portal cell was accepted.
                    // A cell with no portals (a sealed closet entered only by its building portal) is named by portal 0:
                    // the sphere path never reads the index beyond the 0xFFFF test (facts §5.3).
                    int count = Math.Max(1, target.Portals.Count);
                    Require(b.Portals[p].Portal < count, $"{at0}.portals[{p}].portal", $"cell {id} has {target.Portals.Count} portals (0..{count - 1}, or 65535 for none), not portal {b.Portals[p].Portal}");
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
                Require(owners.TryAdd(owner, i), $"{at}.buildings[{i}].origin", $"land cell {owner} already holds building {owners.GetValueOrDefault(owner)} (a land cell holds at most one)");
            }
        }
    }

    private List<(T Item, string Path)> Paths<T>(IReadOnlyList<T> items, string at, string name)
    {
        Count(items.Count, $"{at}.{name}");
        return [.. items.Select((x, i) => (x, $"{at}.{name}[{i}]"))];
    }

    // The rules on a lazily spelt path (At): the public methods above give them a spelt one.
    private void Require(bool ok, At path, [System.Runtime.CompilerServices.InterpolatedStringHandlerArgument("ok")] ref AcPhys.Formats.Dat.FailureText message)
    {
        if (!ok)
        {
            throw new InputFormatException($"{source}: {path}: {message.Text()}");
        }
    }

    private void Count(int count, At path) => Require(count <= MaxItems, path, $"expected an array of at most {MaxItems} items");

    private void EnvCell(CellId cell, At path) => Require(cell.IsEnv, path, $"{cell} is not an env cell id (low word 0x0100..0xFFFD)");

    private void EnvLow(ushort low, At path) =>
        Require(low is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId, path, $"0x{low:X4} is not an env cell low word (0x0100..0xFFFD)");

    private void UnitRotation(Quaternion rotation, At path)
    {
        float length = rotation.Length();
        Require(MathF.Abs(length - 1f) <= SceneJson.UnitTolerance, path, $"quaternion (W, X, Y, Z) has length {length.ToString("R", CultureInfo.InvariantCulture)}, not 1 (±{SceneJson.UnitTolerance})");
    }

    private void Box(Vector3 min, Vector3 max, At path) =>
        Require(min.X < max.X && min.Y < max.Y && min.Z < max.Z, path, $"degenerate box: min must be below max on every axis");

    private void Normal(Vector3 normal, At path)
    {
        Require(normal.Length() > 1e-6f, path.Then(".n"), $"degenerate plane: normal ({normal.X}, {normal.Y}, {normal.Z}) has no direction");
        Require(float.IsFinite(normal.Length()), path.Then(".n"), $"non-finite plane normal (its length overflows)");
    }

    private void Convex(IReadOnlyList<CellPlane> planes, At path) => Convex(() => new ConvexPiece(planes), path);

    // A built scene's piece: the core piece it queries with (ToConvex, built once and kept) is the one checked.
    private void Convex(ScenePiece piece, At path) => Convex(piece.ToConvex, path);

    private void Convex(Func<ConvexPiece> build, At path)
    {
        try
        {
            _ = build();
        }
        catch (ArgumentException e)
        {
            throw new InputFormatException($"{source}: {path}.planes: {e.Message.Split(" (Parameter", 2)[0]}");
        }
    }

    // A value the scene file holds as a JSON number: records give float32 values, and arithmetic on them (a portal
    // polygon's plane) could overflow, which a scene file cannot hold.
    private void Finite(Vector3 v, At path) => Require(float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z), path, $"non-finite value (a scene holds finite numbers)");

    private void Plane(CellPlane plane, At path)
    {
        Finite(plane.Normal, path.Then(".n"));
        Require(float.IsFinite(plane.D), path.Then(".d"), $"non-finite value (a scene holds finite numbers)");
        Normal(plane.Normal, path);
    }

    private void Cell(SceneCell c, At at)
    {
        EnvCell(c.Id, at.Then(".id"));
        Finite(c.Origin, at.Then(".frame.origin"));
        UnitRotation(c.Rotation, at.Then(".frame.rotation"));
        Count(c.Pieces.Count, at.Then(".pieces"));
        Require(c.Pieces.Count > 0, at.Then(".pieces"), $"a cell needs at least one piece");
        for (int i = 0; i < c.Pieces.Count; i++)
        {
            var path = at.Index(".pieces", i);
            if (c.Pieces[i].Box is { } box)
            {
                Finite(box.Min, path.Then(".box.min"));
                Finite(box.Max, path.Then(".box.max"));
                Box(box.Min, box.Max, path.Then(".box"));
                continue;
            }

            var planes = c.Pieces[i].Planes!;
            Count(planes.Count, path.Then(".planes"));
            for (int k = 0; k < planes.Count; k++)
            {
                Plane(planes[k], path.Index(".planes", k));
            }

            Convex(c.Pieces[i], path);
        }

        Count(c.Portals.Count, at.Then(".portals"));
        for (int i = 0; i < c.Portals.Count; i++)
        {
            var path = at.Index(".portals", i);
            Plane(c.Portals[i].Plane, path.Then(".plane"));
            if (!c.Portals[i].IsExit)
            {
                EnvLow(c.Portals[i].Other, path.Then(".other"));
            }
        }

        Count(c.Visible.Count, at.Then(".visible"));
        for (int i = 0; i < c.Visible.Count; i++)
        {
            EnvCell(c.Visible[i], at.Index(".visible", i));
        }
    }

    private void Building(SceneBuilding b, At at)
    {
        Finite(b.Origin, at.Then(".origin"));
        Count(b.Portals.Count, at.Then(".portals"));
        for (int i = 0; i < b.Portals.Count; i++)
        {
            EnvLow(b.Portals[i].Cell, at.Index(".portals", i).Then(".cell"));
        }
    }

    // A JSON path spelt only when asked (ToString): a root, up to three list items (".cells[2]", ".pieces[0]",
    // ".planes[5]") and one tail of plain names (".frame.origin", ".n").
    private readonly struct At(string root, string? n1 = null, int i1 = 0, string? n2 = null, int i2 = 0, string? n3 = null, int i3 = 0, string? tail = null)
    {
        public At Index(string name, int index) =>
            tail is not null || n3 is not null ? new At(ToString() + name + "[" + index.ToString(CultureInfo.InvariantCulture) + "]")
            : n1 is null ? new At(root, name, index)
            : n2 is null ? new At(root, n1, i1, name, index)
            : new At(root, n1, i1, n2, i2, name, index);

        public At Then(string name) => new(root, n1, i1, n2, i2, n3, i3, tail is null ? name : tail + name);

        public override string ToString()
        {
            var text = new System.Text.StringBuilder(root);
            foreach (var (name, index) in new[] { (n1, i1), (n2, i2), (n3, i3) })
            {
                if (name is not null)
                {
                    text.Append(name).Append('[').Append(index.ToString(CultureInfo.InvariantCulture)).Append(']');
                }
            }

            return text.Append(tail).ToString();
        }
    }
}
