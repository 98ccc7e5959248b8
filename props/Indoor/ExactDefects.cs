using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Indoor;

/// <summary>What a port could get wrong where retail is exact: each a <see cref="DefectiveSceneAdapter"/> over the reference.</summary>
internal static class ExactDefects
{
    /// <summary>Gets a port that sets HitsInteriorCell only when it picks an env cell (not on building entry).</summary>
    public static DefectiveSceneAdapter HitsOnlyFromPick { get; } = new(
        "HitsInteriorCell set only by the interior pick",
        q => q.Answer with { HitsInteriorCell = q.Position.IsIndoorByLowWord || q.Answer.Containing.IsEnv });

    /// <summary>Gets a port whose closure walks a snapshot of the seeded entries (cells appended during the walk are not walked).</summary>
    public static DefectiveSceneAdapter SnapshotClosure { get; } = new(
        "a transit closure over a snapshot of the seed",
        q => q.Keep(id => !id.IsEnv || FirstGeneration(q, id)));

    /// <summary>Gets a port that stops after the first building portal: from land, the second portal's cell is not entered (unless a portal of another candidate leads there).</summary>
    public static DefectiveSceneAdapter DropsSecondBuildingPortal { get; } = new(
        "only the first building portal entered",
        q => q.Position.IsLand ? q.Keep(id => !SecondPortalCell(q, id) || BehindCandidatePortal(q, id)) : q.Answer);

    /// <summary>Gets a port that adds a loaded neighbour when a sphere straddles the portal's plane, without the neighbour's volume test.</summary>
    public static DefectiveSceneAdapter NeighbourByPlane { get; } = new(
        "neighbours added by the portal plane alone",
        q => q.Append(NeighboursByPlane(q)));

    /// <summary>Gets a port that enters building portals whose portal index is 0xFFFF.</summary>
    public static DefectiveSceneAdapter EntersInvalidBuildingPortal { get; } = new(
        "building portals with index 0xFFFF entered",
        q => q.Append(InvalidPortalCells(q)));

    /// <summary>Gets a port that adds the outdoor cells whenever a walked cell has an exit, straddled or not.</summary>
    public static DefectiveSceneAdapter ExitWithoutStraddle { get; } = new(
        "outdoor cells added for any exit, straddled or not",
        q => q.LoadCells && q.Position.IsEnv && q.Answer.Cells.Any(id => HasExit(q, id))
            ? q.Append(ReferenceAdapter.Instance.OutsideCells(q.Position, q.Spheres).Select(id => (id, q.Built.IsLoaded(id.Landblock))))
            : q.Answer);

    /// <summary>Gets a port that never adds the outdoor cells from an exit portal in a transition.</summary>
    public static DefectiveSceneAdapter NoOutdoorCellsOnExit { get; } = new(
        "no outdoor cells from exit portals in transitions",
        q => q.LoadCells && q.Position.IsEnv ? q.Keep(id => !id.IsLand) : q.Answer);

    /// <summary>Gets a port whose interior pick keeps the last env candidate that contains the centre (reversed).</summary>
    public static DefectiveSceneAdapter LastEnvWins { get; } = new(
        "the last env hit wins the pick",
        q => q.Answer with { Containing = Containing(q, q.Spheres[0], q.Answer.Cells.Reverse()) ?? q.Answer.Containing });

    /// <summary>Gets a port whose interior pick tests the body's last sphere instead of sphere 0.</summary>
    public static DefectiveSceneAdapter LastSphereDecides { get; } = new(
        "the last sphere decides the pick",
        q => q.Answer with { Containing = Containing(q, q.Spheres[^1], q.Answer.Cells) ?? q.Answer.Containing });

    private static bool FirstGeneration(SceneQueryAnswer q, CellId id)
    {
        if (id == q.Position)
        {
            return true;
        }

        if (q.Position.IsEnv)
        {
            return q.Built.GetEnvCell(q.Position) is { } own && own.Portals.ToArray().Any(p => own.Id.WithLow(p.OtherCellId) == id);
        }

        return q.Answer.Cells.Any(l => l.IsLand && q.Built.GetBuilding(l) is { } b && b.Portals.Any(p => l.WithLow(p.OtherCellId) == id));
    }

    private static bool SecondPortalCell(SceneQueryAnswer q, CellId id) =>
        q.Scene.Buildings.Any(b => b.Portals.Count > 1 && b.Block.BlockCell.WithLow(b.Portals[1].Cell) == id);

    private static bool BehindCandidatePortal(SceneQueryAnswer q, CellId id) =>
        q.Answer.Cells.Any(c => c != id && q.Built.GetEnvCell(c) is { } cell && cell.Portals.ToArray().Any(p => c.WithLow(p.OtherCellId) == id));

    private static IEnumerable<(CellId, bool)> NeighboursByPlane(SceneQueryAnswer q)
    {
        foreach (var id in q.Answer.Cells)
        {
            if (q.Built.GetEnvCell(id) is not { } cell)
            {
                continue;
            }

            foreach (var portal in cell.Portals.ToArray())
            {
                var next = id.WithLow(portal.OtherCellId);
                if (!portal.LeadsOutside(default) && q.Built.GetEnvCell(next) is not null
                    && q.Spheres.Any(s => MathF.Abs(portal.Plane.Distance(cell.Frame.GlobalToLocal(s.Center))) < s.Radius + LandDefs.Epsilon))
                {
                    yield return (next, true);
                }
            }
        }
    }

    private static IEnumerable<(CellId, bool)> InvalidPortalCells(SceneQueryAnswer q) =>
        from land in q.Answer.Cells
        where land.IsLand
        let building = q.Built.GetBuilding(land)
        where building is not null
        from p in building.Portals
        where p.OtherPortalId == BldPortal.None
        let env = q.Built.GetEnvCell(land.WithLow(p.OtherCellId))
        where env is not null && q.Spheres.Any(s => env.Volume.SphereIntersects(new Sphere(env.Frame.GlobalToLocal(s.Center), s.Radius)) != BoundingType.Outside)
        select (env.Id, true);

    private static bool HasExit(SceneQueryAnswer q, CellId id) => q.Built.GetEnvCell(id) is { } cell && cell.Portals.ToArray().Any(p => p.LeadsOutside(default));

    private static CellId? Containing(SceneQueryAnswer q, Sphere sphere, IEnumerable<CellId> order) =>
        order.Where(id => id.IsEnv && q.Built.GetEnvCell(id) is not null && SceneQuery.Contains(q.Built, q.Position, id, sphere.Center, default))
            .Select(id => (CellId?)id).FirstOrDefault();
}
