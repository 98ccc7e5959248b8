using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>
/// Concrete scene walks for the exact indoor invariants' bite tests: a 2-room cottage (6 × 5 m rooms, yaw 0) wholly
/// inside land cell (1, 1) of block 0x8080 — so its owning land cell is a candidate whenever a sphere is near it —
/// with or without a back door, and two overlapping cells (a stairwell-like overlap).
/// </summary>
internal static class ExactSceneCases
{
    /// <summary>Gets the cottage with a back door (building portal 1 leads into room 1).</summary>
    public static CottagePlan BackDoor { get; } = new((192.0 * 0x80) + 26, (192.0 * 0x80) + 26, 0f, 2, 6f, 5f, 0, BackDoor: true, Storey: false);

    /// <summary>Gets the cottage without a back door (room 1 is reached only through room 0).</summary>
    public static CottagePlan FrontOnly { get; } = BackDoor with { BackDoor = false };

    /// <summary>Returns a one-query walk in a cottage: from the land cell under the point, or from an env cell.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plan">The cottage plan (for its frame).</param>
    /// <param name="local">Sphere 0's centre, cottage-local.</param>
    /// <param name="env">The env position, or null for the land cell under the point.</param>
    /// <param name="extra">Offsets of further spheres from sphere 0 (radius 0.5 each).</param>
    /// <returns>The scene walk.</returns>
    public static SceneWalk At(Scene scene, CottagePlan plan, Vector3 local, CellId? env = null, params Vector3[] extra)
    {
        var start = plan.ToBlock(local);
        BodySphere[] body = [new(Vector3.Zero, 0.5f), .. extra.Select(o => new BodySphere(o, 0.5f))];
        var walk = env is { } id ? new Walk(id, start, body, []) : new Walk(plan.Block.BlockCell.WithLow(1), start, body, []).Normalised();
        return new SceneWalk(scene, walk);
    }

    /// <summary>Returns the back-door cottage with building portal 1 made invalid (portal index 0xFFFF).</summary>
    /// <returns>The scene.</returns>
    public static Scene InvalidBackDoor()
    {
        var scene = SceneKit.Cottage(BackDoor);
        var building = scene.Buildings[0];
        return scene with { Buildings = [building with { Portals = [building.Portals[0], building.Portals[1] with { Portal = BldPortal.None }] }] };
    }

    /// <summary>Returns two portal-linked cells whose boxes overlap on x ∈ [4, 6] (cell-local), with a walk from the first whose centre is in both.</summary>
    /// <returns>The scene walk.</returns>
    public static SceneWalk Overlap()
    {
        var block = new LandblockId(0x80, 0x80);
        var a = block.BlockCell.WithLow(0x100);
        var b = block.BlockCell.WithLow(0x101);
        var origin = new Vector3(50, 50, 0);
        var wall = new Vector3(5, 2, 0);
        var cellA = new SceneCell(a, origin, Quaternion.Identity, [ScenePiece.FromBox(Vector3.Zero, new Vector3(6, 4, 3))], [new ScenePortal(CellPlane.Through(Vector3.UnitX, wall), b.Low, true, 0)], [b]);
        var cellB = new SceneCell(b, origin, Quaternion.Identity, [ScenePiece.FromBox(new Vector3(4, 0, 0), new Vector3(10, 4, 3))], [new ScenePortal(CellPlane.Through(-Vector3.UnitX, wall), a.Low, true, 0)], [a]);
        var scene = new Scene([block], [], [cellA, cellB]);
        return new SceneWalk(scene, new Walk(a, origin + new Vector3(5, 2, 1), [new BodySphere(Vector3.Zero, 0.5f)], []));
    }
}
