using System.Numerics;
using AcPhys.Contract;

namespace AcPhys.Spec.Scenes;

/// <summary>A door of an estate: the room it opens, its wall, whether its building portal is valid, building-frame points.</summary>
/// <param name="Room">The room index.</param>
/// <param name="Side">The wall.</param>
/// <param name="Valid">False when the building portal carries the invalid marker (facts §5.3: retail skips it).</param>
/// <param name="Point">The wall's midpoint at the walk's height (outer face of a vestibule), building frame.</param>
/// <param name="Outward">Unit outward normal, building frame.</param>
public sealed record EstateDoor(int Room, GridSide Side, bool Valid, Vector3 Point, Vector3 Outward)
{
    /// <summary>Gets a point 2.5 m in front of the door, outdoors.</summary>
    public Vector3 Outside => Point + (Outward * 2.5f);
}

/// <summary>An estate scene with what its routes need: the doors, room centres and shared-wall points (building frame), and the ids.</summary>
/// <param name="Scene">The scene.</param>
/// <param name="Plan">The plan it was built from.</param>
/// <param name="Doors">Door list (building 0), index = door number.</param>
/// <param name="Centres">Room centres at the walk's height, building frame.</param>
/// <param name="Positions">Grid positions of the rooms.</param>
public sealed record EstateModel(Scene Scene, EstatePlan Plan, IReadOnlyList<EstateDoor> Doors, IReadOnlyList<Vector3> Centres, (int X, int Y)[] Positions)
{
    /// <summary>Gets the storey's id (none without a storey).</summary>
    public AcPhys.Core.CellId StoreyId { get; init; }

    /// <summary>Gets the stairwell's id (none without a stairwell).</summary>
    public AcPhys.Core.CellId StairwellId { get; init; }

    /// <summary>Gets the lead-in dungeon's cell centres in the dungeon block's frame (empty without a lead).</summary>
    public IReadOnlyList<Vector3> LeadCentres { get; init; } = [];

    /// <summary>Gets the lead-in dungeon's first cell id (none without a lead).</summary>
    public AcPhys.Core.CellId LeadStart { get; init; }

    /// <summary>Returns the midpoint of the wall between two linked rooms at the walk's height, building frame.</summary>
    /// <param name="a">A room.</param>
    /// <param name="b">A room sharing a wall with it.</param>
    /// <returns>The point.</returns>
    public Vector3 Wall(int a, int b) => (Centres[a] + Centres[b]) / 2;

    /// <summary>Maps a building-frame point to the building's block frame, at the walk's height (z = 0).</summary>
    /// <param name="p">The point.</param>
    /// <returns>Block-frame point.</returns>
    public Vector3 ToBlock(Vector3 p)
    {
        var q = Plan.Frame.LocalToGlobal(p);
        return new Vector3(q.X, q.Y, 0);
    }
}
