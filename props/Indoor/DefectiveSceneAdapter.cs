using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Indoor;

/// <summary>One scene query as a defect sees it: the scene, the position, the spheres, the mode and the reference's answer.</summary>
/// <param name="Scene">The scene.</param>
/// <param name="Position">The position's cell id.</param>
/// <param name="Spheres">Centres in the position's block frame.</param>
/// <param name="LoadCells">True for a transition query.</param>
/// <param name="Answer">The reference's answer.</param>
internal sealed record SceneQueryAnswer(Scene Scene, CellId Position, IReadOnlyList<Sphere> Spheres, bool LoadCells, FindCellResult Answer)
{
    /// <summary>Gets the core scene.</summary>
    public CellScene Built => SceneBuild.Build(Scene);

    /// <summary>Returns the answer keeping only the entries a predicate accepts (load-hint flags kept in step).</summary>
    /// <param name="keep">The predicate.</param>
    /// <returns>The answer.</returns>
    public FindCellResult Keep(Func<CellId, bool> keep)
    {
        var flags = Answer.Loaded ?? [.. Answer.Cells.Select(_ => true)];
        var kept = Answer.Cells.Select((id, i) => (id, loaded: flags[i])).Where(e => keep(e.id)).ToList();
        return Answer with { Cells = [.. kept.Select(e => e.id)], Loaded = [.. kept.Select(e => e.loaded)] };
    }

    /// <summary>Returns the answer with entries appended (skipping ids already present).</summary>
    /// <param name="extra">Ids and their loaded flags.</param>
    /// <returns>The answer.</returns>
    public FindCellResult Append(IEnumerable<(CellId Id, bool Loaded)> extra)
    {
        var cells = Answer.Cells.ToList();
        var flags = (Answer.Loaded ?? [.. Answer.Cells.Select(_ => true)]).ToList();
        foreach (var (id, loaded) in extra)
        {
            if (!cells.Contains(id))
            {
                cells.Add(id);
                flags.Add(loaded);
            }
        }

        return Answer with { Cells = cells, Loaded = flags };
    }
}

/// <summary>
/// A test adapter: the retail reference with one defect applied to every scene answer (not a planted fault; each
/// props test that uses one shows an invariant catches what a port could get wrong).
/// </summary>
/// <param name="defect">What is wrong, for the adapter's name.</param>
/// <param name="apply">The defect: the query and the reference's answer to the defective answer.</param>
internal sealed class DefectiveSceneAdapter(string defect, Func<SceneQueryAnswer, FindCellResult> apply) : Support.Forwarding(ReferenceAdapter.Instance)
{
    public override string Name => "reference with " + defect;

    public override PickPolicy Pick => PickPolicy.Retail;

    public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells)
    {
        var answer = Inner.FindCell(scene, cell, spheres, current, loadCells);
        return scene is null ? answer : apply(new SceneQueryAnswer(scene, cell, spheres, loadCells, answer));
    }
}
