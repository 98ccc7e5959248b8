using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The parts queries a scene walk stands for (issue 41, the parts variant indoors): the reference walks the body as a
/// retail client (movement transitions), and at each query each body sphere becomes a part whose origin is its centre, radius r,
/// its box and rotation <see cref="PartShapes"/>'s (off-centre boxes of unequal sides, yawed, and pitched and rolled
/// on odd steps), held in the position's cell and block frame — or, for every other non-anchor part near a block line,
/// in a land cell of the neighbouring block (<see cref="PartFrames"/>), or in another env cell: a portal neighbour, or
/// one of another block (<see cref="PartCells"/>); some parts are Always2D (<see cref="PartShapes.Always2D"/>). The scene kits, their routes (through doors,
/// along walls, across block lines) and the shrinker are the sphere walks'; the parts queries follow from the case
/// alone, whatever the implementation answers.
/// </summary>
/// <remarks>
/// Boxes are retail-like (<see cref="PartShapes"/>): some poke out of their sphere, so a box may cross a portal's plane
/// while its sphere gate (facts §5.2, §5.3) shuts it out, or while the one-sided gate lets it through with the centre
/// beyond r; a sphere may cross a plane while its box lies wholly on one side, where the box test decides (facts §7
/// #14 at a door: the class <c>parts:box-beside-door</c>). The oracles test the gate and the box themselves.
/// </remarks>
internal static class ScenePartsQueries
{
    private static readonly ConditionalWeakTable<SceneWalk, Derived> Cache = [];

    /// <summary>Returns the parts queries of a scene walk, one per query of the walk and after it its anchor query if it has one (<see cref="PartAnchors"/>), in order (computed once per walk).</summary>
    /// <param name="w">The scene walk.</param>
    /// <returns>The step index and its parts (the first is the anchor); steps with no sphere are left out.</returns>
    public static IReadOnlyList<(int Index, Part[] Parts)> Of(SceneWalk w) => Cache.GetValue(w, Derive).All;

    /// <summary>Returns the anchor queries among a scene walk's parts queries (<see cref="PartAnchors"/>), with their kinds.</summary>
    /// <param name="w">The scene walk.</param>
    /// <returns>The step index, the kind and the parts.</returns>
    public static IReadOnlyList<(int Index, AnchorKind Kind, Part[] Parts)> Anchors(SceneWalk w) => Cache.GetValue(w, Derive).Anchors;

    /// <summary>Returns part <paramref name="k"/> of a step: the sphere's part, held in the position's cell or across a block line.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The sphere's index (0 = the anchor).</param>
    /// <param name="cell">The position's cell (its block frame is the sphere's).</param>
    /// <param name="sphere">The sphere.</param>
    /// <returns>The part.</returns>
    public static Part PartOf(int step, int k, CellId cell, Sphere sphere)
    {
        var part = new Part(cell, new Frame(sphere.Center, PartShapes.Rotation(step, k)), PartShapes.Bounds(step, k, sphere.Radius), sphere.Radius, PartShapes.Always2D(step, k));
        if (PartFrames.Across(step, k) && PartFrames.AcrossLine(cell, sphere.Center) is { } across)
        {
            part = part with { Cell = across.Cell, Frame = part.Frame with { Origin = across.Origin } };
        }

        return part;
    }

    private static Derived Derive(SceneWalk w)
    {
        var trace = SceneWalkRunner.Run(ReferenceAdapter.Instance, w, true);
        var scene = SceneBuild.Build(w.Scene);
        var queries = new List<(int, Part[])>(trace.Count + (trace.Count / PartAnchors.Every));
        var anchors = new List<(int, AnchorKind, Part[])>();
        foreach (var s in trace)
        {
            if (s.Query.Spheres.Count == 0)
            {
                continue;
            }

            var parts = new Part[s.Query.Spheres.Count];
            for (int k = 0; k < parts.Length; k++)
            {
                parts[k] = PartCells.Hold(w.Scene, scene, s.Index, k, s.Query.Cell, PartOf(s.Index, k, s.Query.Cell, s.Query.Spheres[k]));
            }

            queries.Add((s.Index, parts));
            if (PartAnchors.Of(scene, s.Index, parts) is { } extra)
            {
                queries.Add((s.Index, extra.Parts));
                anchors.Add((s.Index, extra.Kind, extra.Parts));
            }
        }

        return new Derived(queries, anchors);
    }

    private sealed record Derived(IReadOnlyList<(int Index, Part[] Parts)> All, IReadOnlyList<(int Index, AnchorKind Kind, Part[] Parts)> Anchors);

    /// <summary>The kind to ask an implementation in: the transition when <paramref name="preferTransition"/> and it offers it, else the kind it offers.</summary>
    /// <param name="ops">Its operations.</param>
    /// <param name="preferTransition">True to prefer the transition (no filter), false static placement.</param>
    /// <returns>LoadCells.</returns>
    public static bool Kind(Op ops, bool preferTransition) =>
        preferTransition ? (ops & Op.FindCellPartsTransition) != 0 : (ops & Op.FindCellPartsScene) == 0;
}
