using System.Runtime.CompilerServices;
using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>Turns a validated scene description into the core's <see cref="CellScene"/>, cached per scene instance and mode.</summary>
public static class SceneBuild
{
    private static readonly ConditionalWeakTable<Scene, CellScene[]> Cache = [];

    /// <summary>Builds (or returns the cached) core scene.</summary>
    /// <param name="scene">The description.</param>
    /// <param name="mode">BSP or AABB cells.</param>
    /// <returns>The core scene.</returns>
    public static CellScene Build(Scene scene, VolumeMode mode = VolumeMode.Bsp)
    {
        var slots = Cache.GetValue(scene, _ => new CellScene[2]);

        // Every query of a walk asks for its scene: the built scene is read without the lock once it exists (issue 51,
        // the lock was a third of a scene invariant's time); only the first build of a scene and mode takes it.
        if (Volatile.Read(ref slots[(int)mode]) is { } built)
        {
            return built;
        }

        lock (slots)
        {
            return slots[(int)mode] ??= Create(scene, mode);
        }
    }

    /// <summary>Builds one cell.</summary>
    /// <param name="c">The cell description.</param>
    /// <param name="mode">BSP or AABB.</param>
    /// <returns>The env cell.</returns>
    public static EnvCell Cell(SceneCell c, VolumeMode mode)
    {
        var pieces = c.Pieces.Select(p => p.ToConvex()).ToArray();
        ICellVolume volume = mode == VolumeMode.Bsp ? new CellBsp(pieces) : new CellAabb(pieces);
        var portals = c.Portals.Select((p, i) => new CellPortal(
            CellPortal.FlagsFor(p.PortalSide, p.IsExit),
            (ushort)i,
            p.Other,
            p.OtherPortal,
            new CellPlane(System.Numerics.Vector3.Normalize(p.Plane.Normal), p.Plane.D / p.Plane.Normal.Length()))).ToArray();
        return new EnvCell(c.Id, new Frame(c.Origin, c.Rotation), volume, portals, c.Visible);
    }

    private static CellScene Create(Scene scene, VolumeMode mode) => new(
        scene.Blocks,
        scene.Cells.Select(c => Cell(c, mode)),
        scene.Buildings.Select(b => new Building(b.Block, b.Origin, [.. b.Portals.Select(p => new BldPortal(0, p.Cell, p.Portal))])));
}
