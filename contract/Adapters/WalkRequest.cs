using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>
/// A whole walk asked at once (<see cref="ICellPhysics.FindCellWalk"/>, protocol op <c>find_cell_walk</c>): where it
/// starts, the body's spheres and every move. The implementation threads its own current cell and frame by
/// <see cref="WalkThread"/>, the one rule the tool's walk runners use (docs/protocol.md, "Whole walks").
/// </summary>
/// <param name="Scene">The scene, or null for open land with every block loaded.</param>
/// <param name="StartCell">The cell whose block frame <paramref name="Start"/> is in (the first query's cell).</param>
/// <param name="Start">The block-frame start position (the open-land query's origin).</param>
/// <param name="Body">The body's spheres: centre offsets from the position, and radii; sphere 0 decides the pick.</param>
/// <param name="Steps">The moves (dx, dy) in metres, each in the frame the position is held in at that step.</param>
public sealed record WalkRequest(Scene? Scene, CellId StartCell, Vector3 Start, IReadOnlyList<Sphere> Body, IReadOnlyList<Vector2> Steps)
{
    /// <summary>Gets the current cell before the first query (<see cref="CellId.None"/>: none, as the tool's walks start).</summary>
    public CellId Current { get; init; }

    /// <summary>Gets a value indicating whether every step is asked as a movement transition (LoadCells true: no visibility filter, facts §6.14).</summary>
    public bool LoadCells { get; init; }

    /// <summary>Gets how many queries the walk makes: the start and one per step.</summary>
    public int Queries => Steps.Count + 1;
}
