using AcPhys.Contract;

namespace AcPhys.Spec.Faults;

/// <summary>Planted faults that are only data: the scene as the buggy loader would hand it to the reference query.</summary>
internal static class FaultyScenes
{
    /// <summary>Returns the scene a fault's loader produces, or the scene itself for a fault that is not data.</summary>
    /// <param name="fault">The fault.</param>
    /// <param name="scene">The scene.</param>
    /// <returns>The transformed scene.</returns>
    public static Scene Transform(PlantedFault fault, Scene scene)
    {
        if (fault == IndoorFaults.InvertedPortalSide)
        {
            return scene with { Cells = [.. scene.Cells.Select(c => c with { Portals = [.. c.Portals.Select(p => p with { PortalSide = !p.PortalSide })] })] };
        }

        if (fault == IndoorFaults.NoExitTransit)
        {
            return scene with { Cells = [.. scene.Cells.Select(c => c with { Portals = [.. c.Portals.Where(p => !p.IsExit)] })] };
        }

        if (fault == IndoorPortFaults.BuildingFirstPortalOnly)
        {
            return scene with { Buildings = [.. scene.Buildings.Select(b => b with { Portals = [.. b.Portals.Take(1)] })] };
        }

        return scene;
    }
}
