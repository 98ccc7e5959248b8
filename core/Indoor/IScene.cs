namespace AcPhys.Core;

/// <summary>
/// A landscape with indoor content: which blocks are loaded, the loaded env cells, and the building (if any) attached
/// to each land cell. Cells of unloaded blocks answer null: the query records them as load hints, never crashes.
/// </summary>
public interface IScene : ILandscape
{
    /// <summary>Returns a loaded env cell by full id, or null (unknown, or its block or the cell itself not loaded).</summary>
    /// <param name="id">A full id.</param>
    /// <returns>The cell, or null.</returns>
    EnvCell? GetEnvCell(CellId id);

    /// <summary>Returns the building attached to a loaded land cell (its SortCell), or null.</summary>
    /// <param name="landCell">A land cell id.</param>
    /// <returns>The building, or null.</returns>
    Building? GetBuilding(CellId landCell);
}
