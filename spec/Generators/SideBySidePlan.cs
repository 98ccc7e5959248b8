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

    /// <summary>Two one-room houses a body-width apart across the land line, their doors side by side.</summary>
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
public sealed record SideBySidePlan(SideLayout Layout, double WorldX, double WorldY, float Width, float Depth, float Inset, int Flips) : ISceneWalkPlan
{
    /// <summary>The closet's width, metres.</summary>
    public const float ClosetWidth = 1.5f;

    /// <summary>The gap between the houses of <see cref="SideLayout.Apart"/>, metres (about a body's width).</summary>
    public const float Gap = 0.75f;

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

    /// <inheritdoc/>
    public IEnumerable<ISceneWalkPlan> Shrink()
    {
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
        var scene = BuildScene();
        float r = recipe.Radius, g = Inset * r, half = Layout == SideLayout.Apart ? Gap / 2 : 0;
        // Into the closet a quarter metre past the line, so the body still reaches the land cell its building is attached to.
        float bx = Layout == SideLayout.Closet ? LineX + 0.25f : LineX + half + Math.Max(g, 0.5f);
        Vector3[] points =
        [
            new(LineX - half - Math.Max(g, 0.5f), FacadeY + (Depth / 2), 0),
            new(LineX - half - Math.Max(g, 0.5f), FacadeY - (r / 2), 0),
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
        FormattableString.Invariant($"side-by-side {Layout} at ({WorldX:R}, {WorldY:R}) {Width}x{Depth} inset {Inset} flips {Flips}");

    private CellId CellId(int i) => Block.BlockCell.WithLow((ushort)(0x100 + i));

    private Scene BuildScene()
    {
        float half = Layout == SideLayout.Apart ? Gap / 2 : 0, y0 = FacadeY, h = CottagePlan.Height;
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
