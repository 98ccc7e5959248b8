using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Issue 41: a sphere exactly at a comparison's bound where retail takes it — in the tested cell's frame, in float32,
/// after <c>GlobalToLocal</c>: the BSP sphere test at d = −(r + 0.01) (a portal neighbour, facts §5.1, §5.7; a building's
/// room from outside, §5.3), the exit straddle at |d| = r + EPS and the load-hint side test at its bound (§5.1, §5.4).
/// Every retail comparison there is false at the tie (d ≤ −R is Outside; −R &lt; d &lt; R; PortalSide d &gt; −R, else d &lt; R).
/// Cells lie in a row along +x, each in a frame of its own (origin off the grid, unturned or turned half round), and the
/// positions are built from the cell-frame target: the centre is placed at block-frame x = wall − R, R = r + pad a
/// multiple of 1/1024 m, every coordinate on the 1/1024 m grid, so the float32 transform and the double one both land on
/// the bound exactly (<see cref="TieDistance"/> checks it). The walk visits the tie twice, with clear positions between.
/// </summary>
/// <param name="Target">The test taken at its bound.</param>
/// <param name="WorldX">World x of cell 0's west wall (a multiple of 1/1024).</param>
/// <param name="WorldY">World y of the cells' south walls (a multiple of 1/1024).</param>
/// <param name="Length">Cell length along x (a multiple of 1/4).</param>
/// <param name="Mesh">The threshold r + pad is Mesh / 1024 m.</param>
/// <param name="Offsets">Cell i's origin sits (k / 1024, k' / 1024) off its south-west corner, k from bits 8i.. of this.</param>
/// <param name="Turns">Bit i turns cell i's frame half round.</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true).</param>
/// <param name="StartAt">Which of the four positions the walk starts at.</param>
public sealed record ExactBoundPlan(NearTarget Target, double WorldX, double WorldY, float Length, int Mesh, int Offsets, int Turns, int Flips, int StartAt) : ISceneWalkPlan
{
    /// <summary>Width of the cells across the walk, metres.</summary>
    public const float Width = 4f;

    /// <summary>Gets the padding of the target's test: the BSP's 0.01 or the portal planes' EPS (facts §1.5).</summary>
    public float Pad => Target is NearTarget.Neighbour or NearTarget.Building ? 0.01f : LandDefs.Epsilon;

    /// <summary>Gets the bound R = r + pad, exact in float32: the first multiple of 1/1024 from Mesh/1024 whose radius a double-arithmetic port also puts on retail's side of the tie.</summary>
    public float Bound => CellFrameKit.ThresholdFrom(Mesh, Pad);

    /// <summary>Gets the sphere's radius (r + <see cref="Pad"/> == <see cref="Bound"/> in float32).</summary>
    public float Radius => CellFrameKit.RadiusFor(Bound, Pad);

    /// <inheritdoc/>
    public string Shape => Target switch
    {
        NearTarget.Neighbour => "exact-neighbour",
        NearTarget.Building => "exact-building",
        NearTarget.ExitPlane => "exact-exit",
        _ => "exact-hint",
    };

    /// <summary>Gets the block holding the cells.</summary>
    public LandblockId Block => new((byte)Math.Floor(WorldX / 192), (byte)Math.Floor(WorldY / 192));

    private Vector2 Corner => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)));

    private int CellCount => Target is NearTarget.Neighbour or NearTarget.HintPlane ? 2 : 1;

    /// <inheritdoc/>
    public IEnumerable<string> Classes()
    {
        yield return Target switch
        {
            NearTarget.Neighbour => "exact:neighbour",
            NearTarget.Building => "exact:building",
            NearTarget.ExitPlane => "exact:exit-plane",
            _ => "exact:hint-plane",
        };

        if ((Turns & ((1 << CellCount) - 1)) != 0)
        {
            yield return "frame:half-turn";
        }
    }

    /// <inheritdoc/>
    public IEnumerable<ISceneWalkPlan> Shrink()
    {
        if (Flips != 0)
        {
            yield return this with { Flips = 0 };
        }

        if (Turns != 0)
        {
            yield return this with { Turns = 0 };
        }

        if (Offsets != 0)
        {
            yield return this with { Offsets = 0 };
        }

        if (StartAt != 0)
        {
            yield return this with { StartAt = 0 };
        }

        if (Length != 6)
        {
            yield return this with { Length = 6 };
        }
    }

    /// <inheritdoc/>
    public SceneWalk Build(SceneRecipe recipe)
    {
        var scene = BuildScene();
        float tie = TieX();
        float[] xs = [tie - 0.25f, tie, tie - 0.125f, tie];
        int s = Math.Clamp(StartAt, 0, xs.Length - 1);
        float[] list = [.. xs.Skip(s), .. xs.Take(s)];
        float y = Corner.Y + (Width / 2);
        var steps = new List<Vector2>();
        for (int i = 1; i < list.Length; i++)
        {
            steps.Add(new Vector2(list[i] - list[i - 1], 0)); // exact: every x is on the 1/1024 grid near the wall
        }

        var start = Target == NearTarget.Building ? Block.BlockCell : CellId(0);
        var walk = new Walk(start, new Vector3(list[0], y, 0), [new BodySphere(new Vector3(0, 0, 0.6f), Radius)], [.. steps.Take(recipe.Take)]);
        return new SceneWalk(scene, start.IsEnv ? walk : walk.Normalised()) { Recipe = recipe };
    }

    /// <summary>
    /// Returns the float32 distance of the sphere's centre at the tie from the decisive plane, in the tested cell's frame
    /// (the neighbour's or the room's west wall as an inner half-space, or the portal's plane), and the bound it must equal.
    /// </summary>
    /// <returns>The distance and ±R (−R for the BSP and for a PortalSide hint, else the sign the plane gives).</returns>
    public (float Distance, float Bound) TieDistance()
    {
        var scene = BuildScene();
        var centre = new Vector3(TieX(), Corner.Y + (Width / 2), 0.6f);
        switch (Target)
        {
            case NearTarget.Neighbour:
            case NearTarget.Building:
                var room = scene.Cells[Target == NearTarget.Neighbour ? 1 : 0];
                var local = new Frame(room.Origin, room.Rotation).GlobalToLocal(centre);
                var box = room.Pieces[0].Box!.Value;
                // The west wall in the block frame is x = min.x locally (unturned) or x = max.x (turned): d = distance inside.
                float d = room.Rotation == Quaternion.Identity ? local.X - box.Min.X : box.Max.X - local.X;
                return (d, -Bound);
            default:
                var cell = scene.Cells[0];
                var portal = cell.Portals[^1];
                float dp = portal.Plane.Distance(new Frame(cell.Origin, cell.Rotation).GlobalToLocal(centre));
                return (dp, dp < 0 ? -Bound : Bound);
        }
    }

    /// <inheritdoc/>
    public override string ToString() =>
        FormattableString.Invariant($"exact {Target} at ({WorldX:R}, {WorldY:R}) length {Length} mesh {Mesh} offsets {Offsets} turns {Turns} flips {Flips} start {StartAt}");

    private CellId CellId(int i) => Block.BlockCell.WithLow((ushort)(0x100 + i));

    // The tie's block-frame x: R short of the decisive wall (the building's west wall from outside, else cell 0's east wall).
    private float TieX() => Target == NearTarget.Building ? Corner.X - Bound : Corner.X + Length - Bound;

    private Frame FrameOfCell(int i)
    {
        int bits = (Offsets >> (8 * i)) & 0xFF;
        var origin = new Vector3(Corner.X + (i * Length) + ((bits & 0xF) / 16f) + ((bits & 0xF) / 1024f), Corner.Y + ((bits >> 4) / 16f) + ((bits >> 4) / 1024f), 0);
        return CellFrameKit.FrameOf(origin, ((Turns >> i) & 1) != 0);
    }

    private Scene BuildScene()
    {
        var c = Corner;
        int flipIndex = 0;
        ScenePortal Portal(Frame f, float wallX, bool eastward, ushort other)
        {
            bool flip = ((Flips >> flipIndex++) & 1) != 0;
            // Unflipped, the normal points out of the owning cell and PortalSide is true (as SceneKit's cells).
            var outward = eastward ? Vector3.UnitX : -Vector3.UnitX;
            return new ScenePortal(CellPlane.Through(Vector3.Transform(flip ? -outward : outward, Quaternion.Conjugate(f.Rotation)), f.GlobalToLocal(new Vector3(wallX, c.Y + (Width / 2), 0))), other, PortalSide: !flip);
        }

        var cells = new List<SceneCell>();
        var f0 = FrameOfCell(0);
        var box0 = CellFrameKit.Box(f0, new Vector3(c.X, c.Y, 0), new Vector3(c.X + Length, c.Y + Width, CottagePlan.Height));
        var buildings = new List<SceneBuilding>();
        var unloaded = new List<CellId>();
        switch (Target)
        {
            case NearTarget.Building:
                // One room, its door in the west wall; the building's origin half a metre inside, in the land cell of the tie.
                cells.Add(new SceneCell(CellId(0), f0.Origin, f0.Rotation, [box0], [Portal(f0, c.X, false, CellPortal.Outside) with { OtherPortal = 0 }], []));
                buildings.Add(new SceneBuilding(Block, new Vector3(c.X + 0.5f, c.Y + (Width / 2), 0), [new SceneBldPortal(CellId(0).Low, 0)]));
                break;
            case NearTarget.ExitPlane:
                cells.Add(new SceneCell(CellId(0), f0.Origin, f0.Rotation, [box0], [Portal(f0, c.X + Length, true, CellPortal.Outside)], []));
                break;
            default:
                var f1 = FrameOfCell(1);
                var box1 = CellFrameKit.Box(f1, new Vector3(c.X + Length, c.Y, 0), new Vector3(c.X + (2 * Length), c.Y + Width, CottagePlan.Height));
                cells.Add(new SceneCell(CellId(0), f0.Origin, f0.Rotation, [box0], [Portal(f0, c.X + Length, true, CellId(1).Low) with { OtherPortal = 0 }], [CellId(1)]));
                if (Target == NearTarget.Neighbour)
                {
                    cells.Add(new SceneCell(CellId(1), f1.Origin, f1.Rotation, [box1], [Portal(f1, c.X + Length, false, CellId(0).Low) with { OtherPortal = 0 }], [CellId(0)]));
                }
                else
                {
                    unloaded.Add(CellId(1));
                }

                break;
        }

        return new Scene(CellFrameKit.BlocksAround(Block), buildings, cells) { UnloadedCells = unloaded };
    }
}
