using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>
/// A four-cell dungeon hub for issue 27's "load hint ahead in the closure" corner (facts §4 step 4a): cell 0 with an
/// east neighbour (cell 1, declared but <b>not loaded</b>) listed first among its portals and a north neighbour (cell 2,
/// loaded) listed after it; cell 3 lies north-east, reachable only through cell 2. A body in cell 0's north-east
/// corner makes the closure array [0, 1 (hint), 2, 3]: the hint comes early in breadth-first order and cell 3 is found
/// only by walking cell 2, which comes after it. <see cref="Mirror"/> swaps the axes (hint north, loaded east).
/// </summary>
/// <param name="WorldX">Origin, world x (whole metres; the hub lies inside one block).</param>
/// <param name="WorldY">Origin, world y.</param>
/// <param name="Size">Cell side, metres.</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true).</param>
/// <param name="Mirror">Whether the hint lies north and the loaded neighbour east.</param>
/// <param name="Corner">How deep into the corner the walk goes, as a fraction of the radius (0 = centre on both walls).</param>
public sealed record HintHubPlan(double WorldX, double WorldY, float Size, int Flips, bool Mirror, float Corner)
{
    /// <summary>Gets the block containing the origin.</summary>
    public LandblockId Block => new((byte)Math.Floor(WorldX / 192), (byte)Math.Floor(WorldY / 192));

    /// <summary>Gets the origin in the block's frame.</summary>
    public Vector3 Origin => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)), 0f);

    /// <summary>Builds the scene.</summary>
    /// <returns>The scene: cells 0, 2, 3 loaded, cell 1 a declared unloaded cell.</returns>
    public Scene Scene()
    {
        float s = Size, h = CottagePlan.Height;
        var ids = Enumerable.Range(0, 4).Select(i => Block.BlockCell.WithLow((ushort)(0x100 + i))).ToArray();
        int flip = 0;
        // As SceneKit's portals: PortalSide true ⇔ the owning cell on the plane's negative side (facts §5.4).
        ScenePortal Portal(Vector3 outward, Vector3 point, int other)
        {
            bool f = ((Flips >> (flip++ % 31)) & 1) != 0;
            return new ScenePortal(CellPlane.Through(f ? -outward : outward, Map(point)), ids[other].Low, PortalSide: !f);
        }

        // Cell-local layout before mirroring: 0 = [0,s]², 1 east of 0, 2 north of 0, 3 north-east (east of 2, north of 1).
        var ex = Axis(Vector3.UnitX);
        var ey = Axis(Vector3.UnitY);
        var portals = new List<ScenePortal>[4];
        portals[0] = [Portal(ex, new Vector3(s, s / 2, 0), 1), Portal(ey, new Vector3(s / 2, s, 0), 2)]; // the hint first (dat order)
        portals[1] = [];
        portals[2] = [Portal(-ey, new Vector3(s / 2, s, 0), 0), Portal(ex, new Vector3(s, 1.5f * s, 0), 3)];
        // Cell 3 has no portal to cell 1 (as generated since issue 27; kept so the case stream does not shift). With one,
        // its infinite plane hints cell 1 from cell 3 while the sphere is wholly on cell 0's side of cell 0's own portal
        // (facts §5.1); PORTAL-TRANSIT's load-hint clause follows the closure for that (props HintThroughClosureTests).
        portals[3] = [Portal(-ex, new Vector3(s, 1.5f * s, 0), 2)];
        Vector3[] corners = [new(0, 0, 0), new(s, 0, 0), new(0, s, 0), new(s, s, 0)];
        var cells = new List<SceneCell>();
        foreach (int i in new[] { 0, 2, 3 })
        {
            var a = Map(corners[i]);
            var b = Map(corners[i] + new Vector3(s, s, h));
            var box = ScenePiece.FromBox(Vector3.Min(a, b), Vector3.Max(a, b));
            cells.Add(new SceneCell(ids[i], Origin, Quaternion.Identity, [box], [.. portals[i].Select(p => p with { OtherPortal = OtherPortal(portals, i, p) })], [.. ids.Where(x => x != ids[i])]));
        }

        var blocks = new List<LandblockId>();
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                blocks.Add(new LandblockId((byte)(Block.X + dx), (byte)(Block.Y + dy)));
            }
        }

        return new Scene(blocks, [], cells) { UnloadedCells = [ids[1]] };
    }

    /// <summary>Returns the walk's points in the block frame: cell 0's middle, its north-east corner, the middle again.</summary>
    /// <param name="radius">Sphere 0's radius.</param>
    /// <returns>The points.</returns>
    public IReadOnlyList<Vector3> Points(float radius)
    {
        float a = Corner * radius;
        var mid = new Vector3(Size / 2, Size / 2, 0);
        var corner = new Vector3(Size - a, Size - a, 0);
        return [Origin + mid, Origin + corner, Origin + mid];
    }

    /// <summary>Builds the scene walk: from cell 0's middle into its corner and back, steps of at most half the radius.</summary>
    /// <param name="recipe">The recipe carrying this plan (radius, second sphere, Take).</param>
    /// <returns>The case.</returns>
    public SceneWalk Build(SceneRecipe recipe)
    {
        var points = Points(recipe.Radius);
        var steps = new List<Vector2>();
        for (int i = 1; i < points.Count; i++)
        {
            var d = new Vector2(points[i].X - points[i - 1].X, points[i].Y - points[i - 1].Y);
            int n = (int)System.Numerics.BitOperations.RoundUpToPowerOf2((uint)Math.Max(1, (int)MathF.Ceiling(d.Length() / (recipe.Radius / 2))));
            steps.AddRange(Enumerable.Repeat(d / n, n));
        }

        BodySphere[] body = recipe.TwoSpheres
            ? [new BodySphere(new Vector3(0, 0, 0.6f), recipe.Radius), new BodySphere(new Vector3(0, 0, 1.3f), recipe.Radius)]
            : [new BodySphere(new Vector3(0, 0, 0.6f), recipe.Radius)];
        var walk = new Walk(Block.BlockCell.WithLow(0x100), points[0], body, [.. steps.Take(recipe.Take)]);
        return new SceneWalk(Scene(), walk) { Recipe = recipe };
    }

    /// <inheritdoc/>
    public override string ToString() =>
        FormattableString.Invariant($"hub at ({WorldX:R}, {WorldY:R}) size {Size} flips {Flips}{(Mirror ? " mirrored" : string.Empty)} corner {Corner}");

    private static ushort OtherPortal(List<ScenePortal>[] portals, int i, ScenePortal p)
    {
        int other = p.Other - 0x100;
        int k = portals[other].FindIndex(q => q.Other == 0x100 + i);
        return k < 0 ? (ushort)0xFFFF : (ushort)k;
    }

    private Vector3 Axis(Vector3 v) => Mirror ? new Vector3(v.Y, v.X, v.Z) : v;

    private Vector3 Map(Vector3 p) => Mirror ? new Vector3(p.Y, p.X, p.Z) : p;
}
