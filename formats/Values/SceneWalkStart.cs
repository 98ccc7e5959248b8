using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Values;

/// <summary>
/// The rule for where a scene walk starts, wherever one is read (corpus files, record folders): an env-cell start must
/// be a cell the scene holds. A walk from an undeclared env cell checked nothing: every invariant was VACUOUS and the
/// run passed (issue 28).
/// </summary>
internal static class SceneWalkStart
{
    /// <summary>Returns what is wrong with a scene walk's start cell, or null when it is valid.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="start">The walk's start cell.</param>
    /// <returns>The problem (no location), or null.</returns>
    public static string? Problem(Scene scene, CellId start) =>
        !start.IsEnv || scene.Cells.Any(c => c.Id == start) ? null
            : $"the walk starts in env cell {start}, which the scene does not hold (its cells: {string.Join(", ", scene.Cells.Take(8).Select(c => c.Id))}{(scene.Cells.Count > 8 ? ", …" : string.Empty)})";
}
