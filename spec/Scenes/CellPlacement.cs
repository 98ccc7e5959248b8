using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// Where a cell's own frame sits in its building's frame: an origin and a whole number of quarter turns about z. Maps
/// building-frame geometry (boxes, portal planes) into the cell's local frame exactly (quarter turns swap and negate
/// axes), so that two cells sharing a wall agree on its world plane whatever frames they have (facts §5.8).
/// </summary>
/// <param name="Origin">The cell frame's origin, building frame.</param>
/// <param name="Turns">Quarter turns about +z, 0 to 3.</param>
public readonly record struct CellPlacement(Vector3 Origin, int Turns)
{
    /// <summary>Gets the rotation relative to the building.</summary>
    public Quaternion Rotation => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (Turns & 3) * MathF.PI / 2);

    /// <summary>Maps a building-frame point into the cell frame.</summary>
    /// <param name="p">The point.</param>
    /// <returns>The local point.</returns>
    public Vector3 ToLocal(Vector3 p) => Unturn(p - Origin);

    /// <summary>Maps a building-frame box into the cell frame (still axis-aligned).</summary>
    /// <param name="min">Minimum corner.</param>
    /// <param name="max">Maximum corner.</param>
    /// <returns>The local piece.</returns>
    public ScenePiece ToLocal(Vector3 min, Vector3 max)
    {
        Vector3 a = ToLocal(min), b = ToLocal(max);
        return ScenePiece.FromBox(Vector3.Min(a, b), Vector3.Max(a, b));
    }

    /// <summary>Maps a building-frame plane into the cell frame: N' = R⁻¹N, D' = D + N·origin.</summary>
    /// <param name="plane">The plane.</param>
    /// <returns>The local plane.</returns>
    public CellPlane ToLocal(CellPlane plane) => new(Unturn(plane.Normal), plane.D + Vector3.Dot(plane.Normal, Origin));

    /// <summary>Returns the cell's frame in the block, given its building's frame there.</summary>
    /// <param name="building">The building frame.</param>
    /// <returns>The cell frame.</returns>
    public Frame InBlock(Frame building) => new(building.LocalToGlobal(Origin), Quaternion.Concatenate(Rotation, building.Rotation));

    // R⁻¹ for a quarter-turn rotation R (x, y) → (−y, x) per turn: exact, no trigonometry.
    private Vector3 Unturn(Vector3 v) => (Turns & 3) switch
    {
        1 => new Vector3(v.Y, -v.X, v.Z),
        2 => new Vector3(-v.X, -v.Y, v.Z),
        3 => new Vector3(-v.Y, v.X, v.Z),
        _ => v,
    };
}
