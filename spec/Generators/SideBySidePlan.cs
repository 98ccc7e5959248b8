using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Generators;

/// <summary>How two interiors stand side by side (issue 41).</summary>
public enum SideLayout
{
    /// <summary>Two one-room houses sharing a sealed wall on a 24 m land line: each building on its own land cell.</summary>
    RowHouses,

    /// <summary>One building: a room and, beside it across a sealed wall on the land line, a closet with its own outside door.</summary>
    Closet,

    /// <summary>
    /// Two one-room houses less than (or, for a share, more than) a body's radius apart across the land line, their doors
    /// side by side, so a body still in one house reaches the other's room across the gap.
    /// </summary>
    Apart,
}

/// <summary>
/// Interiors reachable only from outside, side by side (issue 41; facts §4 step 4a, §5.1, §5.3): room A west of a 24 m
/// land line, room B east of it, no cell portal between them, each with its own door (an exit portal) in the south
/// facade and a building portal. A body starts in A next to the line, leaves through A's door while it still touches B
/// (the exit adds the land cells on both sides of the line; the east one's building is B's), walks east along the
/// facade and enters B by its door. A port that asks only the building of the land cell under the body, or the first
/// building it finds, misses B while the body is in A's land cell.
/// </summary>
/// <param name="Layout">The layout.</param>
/// <param name="WorldX">World x of the land line between the rooms (a multiple of 24).</param>
/// <param name="WorldY">World y of the south facade (6–12 m into a land row).</param>
/// <param name="Width">Room A's width (and B's, except a closet's 1.5 m), metres.</param>
/// <param name="Depth">Depth of the rooms, metres.</param>
/// <param name="Inset">How far from the line the body walks, as a fraction of its radius (below 1: it touches both sides).</param>
/// <param name="Flips">Bit 0 flips A's door plane, bit 1 B's (PortalSide false).</param>
/// <param name="GapFraction">The gap between the houses of <see cref="SideLayout.Apart"/> as a fraction of the body's
/// radius (below 1 − <paramref name="Inset"/>: a body still in A reaches B's room); unused by the other layouts.</param>
public sealed record SideBySidePlan(SideLayout Layout, double WorldX, double WorldY, float Width, float Depth, float Inset, int Flips, float GapFraction = SideBySidePlan.NarrowGap) : ISceneWalkPlan
{
    /// <summary>The closet's width, metres.</summary>
    public const float ClosetWidth = 1.5f;

    /// <summary>The narrowest gap of <see cref="SideLayout.Apart"/>, as a fraction of the radius (what shrinking tries).</summary>
    public const float NarrowGap = 0.125f;

    /// <inheritdoc/>
    public string Shape => Layout switch
    {
        SideLayout.RowHouses => "row-houses",
        SideLayout.Closet => "room-closet",
        _ => "houses-apart",
    };

    /// <summary>Gets the block holding the rooms.</summary>
    public LandblockId Block => new((byte)Math.Floor((WorldX - 1) / 192), (byte)Math.Floor(WorldY / 192));

    private float LineX => (float)(WorldX - (192.0 * Block.X));

    private float FacadeY => (float)(WorldY - (192.0 * Block.Y));

    /// <inheritdoc/>
    public IEnumerable<string> Classes()
    {
        yield return Layout switch
        {
            SideLayout.RowHouses => "interiors:row-houses",
            SideLayout.Closet => "interiors:closet-door",
            _ => "interiors:doors-apart",
        };
    }

    /// <summary>
    /// Returns the classes the built walk reaches: <c>interiors:indoors-reach-other</c> (two houses; with
    /// <c>interiors:doors-apart-reach</c> when they stand apart) or <c>interiors:indoors-reach-closet</c> when at some
    /// position sphere 0's centre is still inside room A while a sphere straddles A's door plane and overlaps room B —
    /// the body leaving A by its door while it touches B. Conservative: strict, unpadded, so retail surely adds the land
    /// cell across the line by the exit (facts §5.1: −(r + EPS) &lt; d &lt; r + EPS) and B by that cell's building
    /// (§5.3, §5.7: Outside only when d ≤ −(r + 0.01)).
    /// </summary>
    /// <param name="w">The walk this plan built.</param>
    /// <returns>Tags.</returns>
    internal IEnumerable<string> WalkClasses(SceneWalk w)
    {
        if (w.Walk.Body.Count == 0 || !Reaches(w))
        {
            yield break;
        }

        if (Layout == SideLayout.Closet)
        {
            yield return "interiors:indoors-reach-closet";
            yield break;
        }

        yield return "interiors:indoors-reach-other";
        if (Layout == SideLayout.Apart)
        {
            yield return "interiors:doors-apart-reach";
        }
    }

    /// <inheritdoc/>
    public IEnumerable<ISceneWalkPlan> Shrink()
    {
        if (Layout == SideLayout.Apart)
        {
            // Two one-room houses either way: sharing a wall is the smaller scene to read; else the narrowest gap.
            yield return this with { Layout = SideLayout.RowHouses };
            if (GapFraction != NarrowGap)
            {
                yield return this with { GapFraction = NarrowGap };
            }
        }

        if (Flips != 0)
        {
            yield return this with { Flips = 0 };
        }

        if (Width != 4)
        {
            yield return this with { Width = 4 };
        }

        if (Depth != 4)
        {
            yield return this with { Depth = 4 };
        }
    }

    /// <inheritdoc/>
    public SceneWalk Build(SceneRecipe recipe)
    {
        float r = recipe.Radius, half = HalfGap(r);
        var scene = BuildScene(half);
        // Apart: the body walks Inset·r inside A's wall, so with GapFraction + Inset below 1 it still stands in A while it
        // overlaps B's room across the gap (the other layouts keep at least half a metre from the line).
        float e = Layout == SideLayout.Apart ? Inset * r : Math.Max(Inset * r, 0.5f);
        // Into the closet a quarter metre past the line, so the body still reaches the land cell its building is attached to.
        float bx = Layout == SideLayout.Closet ? LineX + 0.25f : LineX + half + e;
        Vector3[] points =
        [
            new(LineX - half - e, FacadeY + (Depth / 2), 0),
            new(LineX - half - e, FacadeY - (r / 2), 0),
            new(bx, FacadeY - (r / 2), 0),
            new(bx, FacadeY + (Depth / 2), 0),
        ];
        var steps = new List<Vector2>();
        float stepMax = Math.Max(recipe.StepMax, 1f / 16);
        for (int i = 1; i < points.Length; i++)
        {
            var d = new Vector2(points[i].X - points[i - 1].X, points[i].Y - points[i - 1].Y);
            int n = (int)System.Numerics.BitOperations.RoundUpToPowerOf2((uint)Math.Max(1, (int)MathF.Ceiling(d.Length() / stepMax)));
            for (int k = 0; k < n; k++)
            {
                steps.Add(d / n);
            }
        }

        BodySphere[] body = recipe.TwoSpheres
            ? [new BodySphere(new Vector3(0, 0, 0.6f), r), new BodySphere(new Vector3(0, 0, 1.3f), r)]
            : [new BodySphere(new Vector3(0, 0, 0.6f), r)];
        return new SceneWalk(scene, new Walk(CellId(0), points[0], body, [.. steps.Take(recipe.Take)])) { Recipe = recipe };
    }

    /// <inheritdoc/>
    public override string ToString() =>
        FormattableString.Invariant($"side-by-side {Layout} at ({WorldX:R}, {WorldY:R}) {Width}x{Depth} inset {Inset} flips {Flips}{(Layout == SideLayout.Apart ? $" gap {GapFraction}r" : string.Empty)}");

    /// <summary>Returns half the gap between the two rooms for a body of radius <paramref name="radius"/>, metres.</summary>
    /// <param name="radius">Sphere 0's radius.</param>
    /// <returns>Zero unless <see cref="SideLayout.Apart"/>.</returns>
    internal float HalfGap(float radius) => Layout == SideLayout.Apart ? GapFraction * radius / 2 : 0;

    private CellId CellId(int i) => Block.BlockCell.WithLow((ushort)(0x100 + i));

    /// <summary>
    /// Whether some query of the built walk is asked from room A (its position's cell, the previous answer) while a
    /// sphere straddles A's door plane and overlaps room B. Strict: sphere 0's centre is still inside A, and the
    /// comparisons are unpadded (what retail surely reaches). Liberal: the previous centre was in A (the query starts
    /// there) and the comparisons are padded past retail's (r + EPS for the exit, r + 0.01 for the BSP): every query in
    /// which building entry from A can reach B.
    /// </summary>
    /// <param name="w">The walk this plan built.</param>
    /// <param name="liberal">False for the strict test.</param>
    /// <returns>True when such a query exists.</returns>
    internal bool Reaches(SceneWalk w, bool liberal = false)
    {
        float half = HalfGap(w.Walk.Body[0].Radius), y0 = FacadeY, y1 = FacadeY + Depth, h = CottagePlan.Height, pad = liberal ? 0.02f : 0;
        float ax0 = LineX - half - Width, ax1 = LineX - half, bx0 = LineX + half, bx1 = bx0 + (Layout == SideLayout.Closet ? ClosetWidth : Width);
        bool InA(Vector3 c) => liberal
            ? c.X >= ax0 - pad && c.X <= ax1 + pad && c.Y >= y0 - pad && c.Y <= y1 + pad
            : c.X > ax0 && c.X < ax1 && c.Y > y0 && c.Y < y1;
        var p = w.Walk.Start;
        bool fromA = true; // the walk starts in A
        for (int i = 0; i <= w.Walk.Steps.Count; i++)
        {
            if (i > 0)
            {
                fromA = InA(p + w.Walk.Body[0].Offset);
                p += new Vector3(w.Walk.Steps[i - 1], 0);
            }

            if (!(liberal ? fromA : InA(p + w.Walk.Body[0].Offset)))
            {
                continue; // not indoors in A
            }

            bool straddles = false, touches = false;
            foreach (var s in w.Walk.Body)
            {
                var c = p + s.Offset;
                straddles |= MathF.Abs(c.Y - y0) < s.Radius + pad;
                var nearest = Vector3.Clamp(c, new Vector3(bx0, y0, 0), new Vector3(bx1, y1, h));
                touches |= Vector3.Distance(c, nearest) < s.Radius + pad;
            }

            if (straddles && touches)
            {
                return true;
            }
        }

        return false;
    }

    private Scene BuildScene(float half)
    {
        float y0 = FacadeY, h = CottagePlan.Height;
        float ax0 = LineX - half - Width, ax1 = LineX - half, bx0 = LineX + half, bx1 = bx0 + (Layout == SideLayout.Closet ? ClosetWidth : Width);
        SceneCell Room(int i, float x0, float x1, IReadOnlyList<CellId> visible)
        {
            var origin = new Vector3(x0, y0, 0);
            bool flip = ((Flips >> i) & 1) != 0;
            // The door: an exit in the south facade; unflipped its normal points out of the room (PortalSide true).
            var door = new ScenePortal(CellPlane.Through(flip ? Vector3.UnitY : -Vector3.UnitY, new Vector3((x1 - x0) / 2, 0, 0)), CellPortal.Outside, PortalSide: !flip);
            return new SceneCell(CellId(i), origin, Quaternion.Identity, [ScenePiece.FromBox(Vector3.Zero, new Vector3(x1 - x0, Depth, h))], [door], visible);
        }

        var a = Room(0, ax0, ax1, Layout == SideLayout.Closet ? [CellId(1)] : []);
        var b = Room(1, bx0, bx1, Layout == SideLayout.Closet ? [CellId(0)] : []);
        // Each building's origin half a metre inside its room, so each attaches to the land cell its room stands on
        // (facts §5.3); the closet belongs to the room's building, attached west of the line.
        var west = new SceneBuilding(Block, new Vector3(ax1 - 0.5f, y0 + 0.5f, 0), Layout == SideLayout.Closet
            ? [new SceneBldPortal(CellId(0).Low, 0), new SceneBldPortal(CellId(1).Low, 0)]
            : [new SceneBldPortal(CellId(0).Low, 0)]);
        var east = new SceneBuilding(Block, new Vector3(bx0 + 0.5f, y0 + 0.5f, 0), [new SceneBldPortal(CellId(1).Low, 0)]);
        return new Scene(CellFrameKit.BlocksAround(Block), Layout == SideLayout.Closet ? [west] : [west, east], [a, b]);
    }
}
