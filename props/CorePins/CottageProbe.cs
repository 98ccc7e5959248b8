using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// What the cottage-based transit properties share: a generated cottage (yaw, 1–4 rooms, both PortalSide values, back
/// door, storey) with one room picked and perhaps one room left out of the scene, and probes placed at a signed
/// distance from one of that room's portal planes (exactly on the ±(r + EPS) gate edges, one nudge off, or well inside).
/// </summary>
internal static class CottageProbe
{
    /// <summary>Gets a cottage, its scene (perhaps without one room or the storey) and the room the probes aim at.</summary>
    public static Gen<Cottage> Cottages { get; } =
        from blockX in Gen.Choose(1, 250)
        from blockY in Gen.Choose(1, 250)
        from at in Gen.Zip(Gen.Choose(30, 150), Gen.Choose(30, 150))
        from yaw in Gen.Elements(0f, MathF.PI / 2, 0.3f, -1.1f)
        from rooms in Gen.Choose(1, 4)
        from size in Gen.Elements(4f, 6f, 9f)
        from flips in Gen.Choose(0, 15)
        from backDoor in Gen.Elements(false, true)
        from storey in Gen.Elements(false, true)
        let plan = new CottagePlan((blockX * 192.0) + at.Item1, (blockY * 192.0) + at.Item2, yaw, rooms, size, size, flips, backDoor, storey)
        let full = SceneBuild.Build(SceneKit.Cottage(plan))
        from room in Gen.Choose(0, rooms - 1)
        from missing in Gen.Choose(-1, rooms) // a room (or the storey) left out of the scene, or none
        let cell = full.GetEnvCell(plan.RoomId(room))!
        select new Cottage(plan, missing < 0 || missing == room ? full : Without(full, plan, missing), cell);

    /// <summary>Returns a probe by one of the cell's portal planes: a radius whose gate is exact, and a signed distance at, one nudge off, or away from ±(r + EPS).</summary>
    /// <param name="cell">The room.</param>
    /// <returns>The generator.</returns>
    public static Gen<GateProbe> Probes(EnvCell cell) =>
        from portal in Gen.Choose(0, cell.Portals.Length - 1)
        from radius in Gen.Frequency((1, Gen.Constant(0f)), (4, Gen.Elements(0.25f, 0.5f, 1.5f).Select(ExactGate)))
        from edge in Gen.Elements(-1, 0, 1, 2)
        from sign in Gen.Elements(-1f, 1f)
        from nudge in Gen.Frequency((3, Gen.Constant(0f)), (2, Gen.Elements(-0.001f, 0.001f, -0.5f, 0.5f, 3f)))
        from along in Gen.Zip(Gen.Choose(-30, 30), Gen.Choose(-30, 30))
        let distance = edge == 2 ? nudge : (sign * (radius + LandDefs.Epsilon) * edge) + nudge
        select new GateProbe(portal, radius, distance, new Vector2(along.Item1 * 0.1f, along.Item2 * 0.1f));

    /// <summary>Returns the radius r whose gate r + EPS is exactly <paramref name="gate"/> in float32, so that in an unrotated cottage a centre at ±gate from an axis plane sits exactly on the gate's edge (where &lt; and &lt;= differ).</summary>
    /// <param name="gate">The wanted r + EPS.</param>
    /// <returns>The radius.</returns>
    public static float ExactGate(float gate)
    {
        float r = gate - LandDefs.Epsilon;
        for (int i = 0; i < 8 && r + LandDefs.Epsilon != gate; i++)
        {
            r = r + LandDefs.Epsilon > gate ? MathF.BitDecrement(r) : MathF.BitIncrement(r);
        }

        return r;
    }

    /// <summary>Returns a block-frame point: the room's middle projected onto a portal plane, moved along the plane, then to a signed distance from it.</summary>
    /// <param name="cell">The room.</param>
    /// <param name="portal">The portal index (taken modulo the count).</param>
    /// <param name="distance">Signed distance from the plane (positive on the normal's side).</param>
    /// <param name="along">Offsets along two in-plane directions.</param>
    /// <returns>The point in the cell's block frame.</returns>
    public static Vector3 OnPlane(EnvCell cell, int portal, float distance, Vector2 along)
    {
        var plane = cell.Portals[portal % cell.Portals.Length].Plane;
        var mid = (cell.Volume.Bounds.Min + cell.Volume.Bounds.Max) / 2;
        var foot = mid - (plane.Normal * plane.Distance(mid));
        var t1 = Vector3.Normalize(Vector3.Cross(plane.Normal, MathF.Abs(plane.Normal.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitX));
        var t2 = Vector3.Cross(plane.Normal, t1);
        return cell.Frame.LocalToGlobal(foot + (t1 * along.X) + (t2 * along.Y) + (plane.Normal * distance));
    }

    /// <summary>Returns the block and the eight around it.</summary>
    /// <param name="block">The middle block.</param>
    /// <returns>Nine blocks.</returns>
    public static IEnumerable<LandblockId> Around(LandblockId block) =>
        Enumerable.Range(-1, 3).SelectMany(dx => Enumerable.Range(-1, 3).Select(dy => new LandblockId((byte)(block.X + dx), (byte)(block.Y + dy))));

    private static CellScene Without(CellScene full, CottagePlan plan, int missing)
    {
        var keep = Enumerable.Range(0, plan.Rooms + 1).Where(i => i != missing).Select(i => full.GetEnvCell(plan.RoomId(i))).OfType<EnvCell>();
        return new CellScene(Around(plan.Block), keep, full.Buildings.Values);
    }
}

/// <summary>A generated cottage.</summary>
/// <param name="Plan">Its plan.</param>
/// <param name="Scene">Its scene, perhaps without one room.</param>
/// <param name="Cell">The room probes aim at (always in the scene).</param>
internal sealed record Cottage(CottagePlan Plan, CellScene Scene, EnvCell Cell);

/// <summary>A probe by a portal plane.</summary>
/// <param name="Portal">The portal index.</param>
/// <param name="Radius">The sphere radius.</param>
/// <param name="Distance">Signed distance of the centre from the plane.</param>
/// <param name="Along">Offsets along the plane.</param>
internal readonly record struct GateProbe(int Portal, float Radius, float Distance, Vector2 Along);
