using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>The distribution classes of a hub walk (<see cref="HubPlan"/>).</summary>
internal static class HubClasses
{
    /// <summary>Gets every hub class tag, in report order.</summary>
    public static IReadOnlyList<string> All { get; } = ["see:blind-neighbour", "filter:mid-removal", "filter:recheck-order"];

    /// <summary>Returns the classes of a hub walk.</summary>
    /// <param name="plan">The hub.</param>
    /// <param name="w">The built walk.</param>
    /// <returns>Tags.</returns>
    public static IEnumerable<string> Of(HubPlan plan, SceneWalk w)
    {
        if (plan.BlindNeighbour)
        {
            yield return "see:blind-neighbour"; // facts §5.1, §7 #10: Q0 does not list a portal neighbour in its VisibleCells
        }

        // Facts §5.9: at some point of the walk, a static query from Q0 leaves another order with an order-preserving
        // filter than with retail's swap-removal (a removal in the middle with two or more survivors behind it).
        var scene = SceneBuild.Build(w.Scene);
        var q0 = plan.QuadrantId(0);
        var array = new CellArray();
        bool mid = false, recheck = false;
        foreach (var centre in Centres(w.Walk))
        {
            Sphere[] spheres = [.. w.Walk.Body.Select(b => new Sphere(centre + b.Offset, b.Radius))];
            SceneQuery.FindCellList(array, scene, q0, spheres, q0, CellQueryOptions.RetailTransition);
            var retail = FilterOrder.Filtered(array, scene, q0, FilterWay.Retail);
            mid |= !retail.SequenceEqual(FilterOrder.Filtered(array, scene, q0, FilterWay.Stable));
            recheck |= !retail.SequenceEqual(FilterOrder.Filtered(array, scene, q0, FilterWay.LiveRecheck));
        }

        if (mid)
        {
            yield return "filter:mid-removal";
        }

        if (recheck)
        {
            yield return "filter:recheck-order";
        }
    }

    private static IEnumerable<System.Numerics.Vector3> Centres(Walk walk)
    {
        var p = walk.Start;
        yield return p;
        foreach (var s in walk.Steps)
        {
            p += new System.Numerics.Vector3(s, 0);
            yield return p;
        }
    }
}
