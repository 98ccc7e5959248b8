using System.Globalization;
using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

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
    /// <exception cref="SceneFormatException">The first broken rule, with the JSON path it would have in the scene's file.</exception>
    public Scene Check(Scene scene, string at)
    {
        var blocks = Paths(scene.Blocks, at, "blocks");
        var unloadedBlocks = Paths(scene.UnloadedBlocks, at, "unloadedBlocks");
        var declared = Declared(blocks.Concat(unloadedBlocks));
        var unloadedCells = Paths(scene.UnloadedCells, at, "unloadedCells");
        foreach (var (id, path) in unloadedCells)
        {
            EnvCell(id, path);
        }

        Count(scene.Cells.Count, $"{at}.cells");
        for (int i = 0; i < scene.Cells.Count; i++)
        {
            Cell(scene.Cells[i], $"{at}.cells[{i}]");
        }

        Count(scene.Buildings.Count, $"{at}.buildings");
        for (int i = 0; i < scene.Buildings.Count; i++)
        {
            Building(scene.Buildings[i], $"{at}.buildings[{i}]");
        }

        References(at, declared, scene.Cells, unloadedCells, scene.Buildings);
        return scene;
    }

    /// <summary>Throws the scene's format error when a rule is broken.</summary>
    /// <param name="ok">True when the rule holds.</param>
    /// <param name="path">The JSON path of the value.</param>
    /// <param name="message">What is wrong.</param>
    /// <exception cref="SceneFormatException">When <paramref name="ok"/> is false.</exception>
    public void Require(bool ok, string path, string message)
    {
        if (!ok)
        {
            throw new SceneFormatException($"{source}: {path}: {message}");
        }
    }

    /// <summary>A list holds at most <see cref="MaxItems"/> items.</summary>
    /// <param name="count">Its length.</param>
    /// <param name="path">Its path.</param>
    public void Count(int count, string path) => Require(count <= MaxItems, path, $"expected an array of at most {MaxItems} items");

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
    public void EnvCell(CellId cell, string path) => Require(cell.IsEnv, path, $"{cell} is not an env cell id (low word 0x0100..0xFFFD)");

    /// <summary>A low word names an env cell.</summary>
    /// <param name="low">The low word.</param>
    /// <param name="path">Its path.</param>
    public void EnvLow(ushort low, string path) =>
        Require(low is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId, path, $"0x{low:X4} is not an env cell low word (0x0100..0xFFFD)");

    /// <summary>A cell's rotation is a unit quaternion (±<see cref="SceneJson.UnitTolerance"/>).</summary>
    /// <param name="rotation">The rotation.</param>
    /// <param name="path">The rotation's path.</param>
    public void UnitRotation(Quaternion rotation, string path)
    {
        float length = rotation.Length();
        Require(MathF.Abs(length - 1f) <= SceneJson.UnitTolerance, path, $"quaternion (W, X, Y, Z) has length {length.ToString("R", CultureInfo.InvariantCulture)}, not 1 (±{SceneJson.UnitTolerance})");
    }

    /// <summary>A box is below its max corner on every axis.</summary>
    /// <param name="min">The min corner.</param>
    /// <param name="max">The max corner.</param>
    /// <param name="path">The box's path.</param>
    public void Box(Vector3 min, Vector3 max, string path) =>
        Require(min.X < max.X && min.Y < max.Y && min.Z < max.Z, path, "degenerate box: min must be below max on every axis");

    /// <summary>A plane's normal has a direction and a finite length.</summary>
    /// <param name="normal">The normal.</param>
    /// <param name="path">The plane's path.</param>
    public void Normal(Vector3 normal, string path)
    {
        Require(normal.Length() > 1e-6f, path + ".n", $"degenerate plane: normal ({normal.X}, {normal.Y}, {normal.Z}) has no direction");
        Require(float.IsFinite(normal.Length()), path + ".n", "non-finite plane normal (its length overflows)");
    }

    /// <summary>A piece's planes bound a convex piece.</summary>
    /// <param name="planes">The planes.</param>
    /// <param name="path">The piece's path.</param>
    public void Convex(IReadOnlyList<CellPlane> planes, string path)
    {
        try
        {
            _ = new ConvexPiece(planes);
        }
        catch (ArgumentException e)
        {
            throw new SceneFormatException($"{source}: {path}.planes: {e.Message.Split(" (Parameter", 2)[0]}");
        }
    }

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
        var known = new Dictionary<CellId, string>();
        for (int i = 0; i < cells.Count; i++)
        {
            string path = $"{at}.cells[{i}].id";
            Require(known.TryAdd(cells[i].Id, path), path, $"duplicate cell {cells[i].Id} (first at {known.GetValueOrDefault(cells[i].Id)})");
            Require(declared.Contains(cells[i].Id.Landblock), path, $"cell {cells[i].Id} lies in block {cells[i].Id.Landblock}, which the scene does not declare");
        }

        foreach (var (id, path) in unloadedCells)
        {
            Require(known.TryAdd(id, path), path, $"duplicate cell {id} (first at {known.GetValueOrDefault(id)})");
            Require(declared.Contains(id.Landblock), path, $"cell {id} lies in block {id.Landblock}, which the scene does not declare");
        }

        for (int i = 0; i < cells.Count; i++)
        {
            var c = cells[i];
            string at0 = $"{at}.cells[{i}]";
            for (int p = 0; p < c.Portals.Count; p++)
            {
                var portal = c.Portals[p];
                if (portal.IsExit)
                {
                    continue;
                }

                var other = c.Id.WithLow(portal.Other);
                Require(known.ContainsKey(other), $"{at0}.portals[{p}].other", $"unknown cell {other} (not declared in cells or unloadedCells)");
                Require(other != c.Id, $"{at0}.portals[{p}].other", $"a portal of {c.Id} leads to itself");
            }

            for (int v = 0; v < c.Visible.Count; v++)
            {
                Require(known.ContainsKey(c.Visible[v]), $"{at0}.visible[{v}]", $"unknown cell {c.Visible[v]} (not declared in cells or unloadedCells)");
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

    // A value the scene file holds as a JSON number: records give float32 values, and arithmetic on them (a portal
    // polygon's plane) could overflow, which a scene file cannot hold.
    private void Finite(Vector3 v, string path) => Require(float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z), path, "non-finite value (a scene holds finite numbers)");

    private void Plane(CellPlane plane, string path)
    {
        Finite(plane.Normal, path + ".n");
        Require(float.IsFinite(plane.D), path + ".d", "non-finite value (a scene holds finite numbers)");
        Normal(plane.Normal, path);
    }

    private void Cell(SceneCell c, string at)
    {
        EnvCell(c.Id, at + ".id");
        Finite(c.Origin, at + ".frame.origin");
        UnitRotation(c.Rotation, at + ".frame.rotation");
        Count(c.Pieces.Count, at + ".pieces");
        Require(c.Pieces.Count > 0, at + ".pieces", "a cell needs at least one piece");
        for (int i = 0; i < c.Pieces.Count; i++)
        {
            string path = $"{at}.pieces[{i}]";
            if (c.Pieces[i].Box is { } box)
            {
                Finite(box.Min, path + ".box.min");
                Finite(box.Max, path + ".box.max");
                Box(box.Min, box.Max, path + ".box");
                continue;
            }

            var planes = c.Pieces[i].Planes!;
            Count(planes.Count, path + ".planes");
            for (int k = 0; k < planes.Count; k++)
            {
                Plane(planes[k], $"{path}.planes[{k}]");
            }

            Convex(planes, path);
        }

        Count(c.Portals.Count, at + ".portals");
        for (int i = 0; i < c.Portals.Count; i++)
        {
            string path = $"{at}.portals[{i}]";
            Plane(c.Portals[i].Plane, path + ".plane");
            if (!c.Portals[i].IsExit)
            {
                EnvLow(c.Portals[i].Other, path + ".other");
            }
        }

        Count(c.Visible.Count, at + ".visible");
        for (int i = 0; i < c.Visible.Count; i++)
        {
            EnvCell(c.Visible[i], $"{at}.visible[{i}]");
        }
    }

    private void Building(SceneBuilding b, string at)
    {
        Finite(b.Origin, at + ".origin");
        Count(b.Portals.Count, at + ".portals");
        for (int i = 0; i < b.Portals.Count; i++)
        {
            EnvLow(b.Portals[i].Cell, $"{at}.portals[{i}].cell");
        }
    }
}
