using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>Builds a core scene as <see cref="SceneBuild"/> does (BSP cells), with every cell's volume wrapped by a faulty decorator.</summary>
internal static class FaultySceneBuild
{
    /// <summary>Builds the scene.</summary>
    /// <param name="scene">The description.</param>
    /// <param name="wrap">Wraps a cell's retail volume, given the cell's pieces.</param>
    /// <returns>The core scene.</returns>
    public static CellScene Build(Scene scene, Func<ICellVolume, IReadOnlyList<ConvexPiece>, ICellVolume> wrap) => new(
        scene.Blocks,
        scene.Cells.Select(c =>
        {
            var retail = SceneBuild.Cell(c, VolumeMode.Bsp);
            var volume = wrap(retail.Volume, [.. c.Pieces.Select(p => p.ToConvex())]);
            return new EnvCell(retail.Id, retail.Frame, volume, retail.Portals.ToArray(), c.Visible);
        }),
        scene.Buildings.Select(b => new Building(b.Block, b.Origin, [.. b.Portals.Select(p => new BldPortal(0, p.Cell, p.Portal))])));
}
