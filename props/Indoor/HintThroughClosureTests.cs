using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Indoor;

/// <summary>
/// PORTAL-TRANSIT's load-hint clause follows the transit closure (facts §4 step 4a, §5.1): a hint for an unloaded cell
/// may come from any walked cell's portal to it, not only from the position's own portal.
/// </summary>
public sealed class HintThroughClosureTests
{
    private const float Size = 4, Radius = 0.5f;

    // The hint hub (cell 0; cell 1 east, not loaded; cell 2 north; cell 3 north-east) with one more portal: cell 3's
    // south wall leads to cell 1. The walk ends 5 mm short of cell 0's own portal to cell 1 (beyond r + EPS and the
    // 1 mm tie band) and 0.3 m over its north wall, so cell 3's BSP test (r + 0.01) takes it in through cell 2, and
    // cell 3's portal plane to cell 1, the sphere wholly past it, gives the hint.
    private static readonly HintHubPlan Plan = new((192.0 * 0x40) + 60, (192.0 * 0x50) + 60, Size, 0, false, 0);

    private static CellId Id(int i) => Plan.Block.BlockCell.WithLow((ushort)(0x100 + i));

    [Fact(DisplayName = "PORTAL-TRANSIT: a load hint given through another walked cell's portal (the position's own portal not reached) is no violation")]
    public void HintFromAnotherWalkedCellHolds()
    {
        var walk = Walk();
        var last = SceneWalkRunner.Run(ReferenceAdapter.Instance, walk)[^1];
        Assert.Contains(Id(3), last.Cells);
        Assert.Contains(Id(1), last.Cells); // retail's hint, through cell 3's portal
        Assert.Equal(Verdict.Holds, IndoorInvariants.PortalTransit.Check(ReferenceAdapter.Instance, walk).Verdict);
    }

    [Fact(DisplayName = "PORTAL-TRANSIT: a load hint no walked cell's portal reaches is still a violation")]
    public void HintFromNowhereFails()
    {
        var outcome = IndoorInvariants.PortalTransit.Check(new HintsAlways(Id(1)), Walk());
        Assert.True(outcome.IsViolation, outcome.Message);
        Assert.Equal(0, outcome.Step);
        Assert.Contains($"load hint {Id(1)} given although", outcome.Message, StringComparison.Ordinal);
    }

    private static SceneWalk Walk()
    {
        var scene = Plan.Scene();
        var toHint = new ScenePortal(CellPlane.Through(-Vector3.UnitY, new Vector3(1.5f * Size, Size, 0)), Id(1).Low, PortalSide: true);
        scene = scene with { Cells = [.. scene.Cells.Select(c => c.Id == Id(3) ? c with { Portals = [.. c.Portals, toHint] } : c)] };
        var start = Plan.Origin + new Vector3(Size / 2, Size / 2, 0);
        var end = Plan.Origin + new Vector3(Size - Radius - 0.005f, Size - Radius + 0.3f, 0);
        var step = new Vector2(end.X - start.X, end.Y - start.Y) / 8;
        var walk = new Walk(Id(0), start, [new BodySphere(new Vector3(0, 0, 0.6f), Radius)], [.. Enumerable.Repeat(step, 8)]);
        return new SceneWalk(scene, walk);
    }

    // Adds a load hint for one cell to every answer.
    private sealed class HintsAlways(CellId hint) : Forwarding(ReferenceAdapter.Instance)
    {
        public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells)
        {
            var r = Inner.FindCell(scene, cell, spheres, current, loadCells);
            return r.Cells.Contains(hint) ? r : r with { Cells = [.. r.Cells, hint], Loaded = r.Loaded is { } l ? [.. l, false] : null };
        }
    }
}
