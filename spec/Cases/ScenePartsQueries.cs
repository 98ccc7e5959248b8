using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The parts queries a scene walk stands for (issue 41, the parts variant indoors): the reference walks the body as a
/// retail client (movement transitions), and at each query the body's spheres become parts in the same cell and block
/// frame — one part per sphere, centred on it, its box a cube of half-side 0.4·r yawed by 37° per step, its radius r.
/// The scene kits, their routes (through doors, along walls, across block lines) and the shrinker are the sphere
/// walks'; the parts queries follow from the case alone, whatever the implementation answers.
/// </summary>
/// <remarks>
/// Half-side 0.4·r keeps every corner of the box's axis-aligned hull in a yawed frame within 0.9·r of the centre
/// (√5·0.4 &lt; 1), so a box that crosses a portal's plane passes the part's sphere gate (facts §5.2, §5.3) — the oracles
/// still test the sphere gate themselves.
/// </remarks>
internal static class ScenePartsQueries
{
    /// <summary>Half-side of a part's box as a fraction of its sphere's radius.</summary>
    public const float HalfSide = 0.4f;

    /// <summary>Returns the parts queries of a scene walk, one per query of the walk, in order.</summary>
    /// <param name="w">The scene walk.</param>
    /// <returns>The step index and its parts (the first is the anchor); steps with no sphere are left out.</returns>
    public static IReadOnlyList<(int Index, Part[] Parts)> Of(SceneWalk w)
    {
        var trace = SceneWalkRunner.Run(ReferenceAdapter.Instance, w, true);
        var queries = new List<(int, Part[])>(trace.Count);
        foreach (var s in trace)
        {
            if (s.Query.Spheres.Count == 0)
            {
                continue;
            }

            var yaw = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (s.Index * 37 % 360) * MathF.PI / 180f);
            queries.Add((s.Index, s.Query.Spheres.Select(sp => PartOf(s.Query.Cell, sp, yaw)).ToArray()));
        }

        return queries;
    }

    /// <summary>Returns the part a sphere stands for.</summary>
    /// <param name="cell">The position's cell (the part's cell: its block frame is the sphere's).</param>
    /// <param name="sphere">The sphere.</param>
    /// <param name="rotation">The part's rotation.</param>
    /// <returns>The part.</returns>
    public static Part PartOf(CellId cell, Sphere sphere, Quaternion rotation)
    {
        float h = HalfSide * sphere.Radius;
        return new Part(cell, new Frame(sphere.Center, rotation), new Box(new Vector3(-h), new Vector3(h)), sphere.Radius, false);
    }

    /// <summary>The kind to ask an implementation in: the transition when <paramref name="preferTransition"/> and it offers it, else the kind it offers.</summary>
    /// <param name="ops">Its operations.</param>
    /// <param name="preferTransition">True to prefer the transition (no filter), false static placement.</param>
    /// <returns>LoadCells.</returns>
    public static bool Kind(Op ops, bool preferTransition) =>
        preferTransition ? (ops & Op.FindCellPartsTransition) != 0 : (ops & Op.FindCellPartsScene) == 0;
}
