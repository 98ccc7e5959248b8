using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The parts objects of issue 53 item 2 on the pr cases: Always2D parts (1 in 4 non-anchor parts, the anchor on 1 step
/// in 4) whose outdoor extent is the square ±r around the raw origin (facts §3.4); parts held in a portal neighbour
/// of the anchor's cell or in another block's env cell, which the reference answers as if held in the anchor's cell
/// (§5.2, §5.8: one world position); and PARTS-BUILDING-ENTRY judged on scenes with a building only. Counts printed.
/// </summary>
public sealed class PartsObjectFacts(ITestOutputHelper output)
{
    private const int Cases = 600;

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (facts §3.4): about 1 in 4 parts are Always2D, each contributing the square ±r around its raw origin, and from an indoor anchor the square changes the land cells an exit lists on some pr case")]
    public void Always2DPartsAreTheFacts()
    {
        var judge = PartsIndoorInvariants.Soundness;
        int anchors = 0, anchors2D = 0, others = 0, others2D = 0, decided = 0;
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            foreach (var (index, parts) in ScenePartsQueries.Of(w))
            {
                anchors++;
                anchors2D += parts[0].Always2D ? 1 : 0;
                others += parts.Length - 1;
                others2D += parts.Skip(1).Count(p => p.Always2D);
                foreach (var p in parts.Where(p => p.Always2D))
                {
                    // §3.4: the square of the sphere around the raw origin, in the anchor's block frame.
                    var land = parts[0].Cell.WithLow(1);
                    var o = p.Frame.Origin - LandDefs.GetBlockOffset(p.Cell, land);
                    var (min, max) = OutdoorParts.Extent(p, land);
                    Assert.Equal(new Vector2(o.X - p.Radius, o.Y - p.Radius), min);
                    Assert.Equal(new Vector2(o.X + p.Radius, o.Y + p.Radius), max);
                }

                if (parts[0].Cell.IsEnv && parts.Any(p => p.Always2D))
                {
                    var listed = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, true).Cells;
                    var boxes = ReferenceAdapter.Instance.FindCellParts(w.Scene, [.. parts.Select(p => p with { Always2D = false })], true).Cells;
                    decided += listed.SequenceEqual(boxes) ? 0 : 1;
                }
            }

            return true;
        });
        output.WriteLine($"{Cases} pr cases of {judge.Id}: Always2D anchors {anchors2D:N0} of {anchors:N0}, other parts {others2D:N0} of {others:N0}; indoor queries whose list the squares change {decided:N0}");
        Assert.InRange(anchors2D / (double)anchors, 0.15, 0.35);
        Assert.InRange(others2D / (double)others, 0.18, 0.32);
        Assert.True(decided > 0, "no indoor query whose list an Always2D square changes");
    }

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE (facts §5.2, §5.8): parts held in a portal neighbour or in another block's env cell occur on pr cases, at the same world position, and the reference lists the same cells as with each held in the anchor's cell")]
    public void HeldPartsAreFramedByTheirOwnCell()
    {
        var judge = PartsIndoorInvariants.Conformance;
        int neighbour = 0, otherBlock = 0, queries = 0;
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            // The anchor queries (PartAnchors) re-seat the anchor alone: their other parts stay in the step's cell.
            var reseated = ScenePartsQueries.Anchors(w).Select(a => a.Parts).ToHashSet(ReferenceEqualityComparer.Instance);
            foreach (var (index, parts) in ScenePartsQueries.Of(w).Where(q => !reseated.Contains(q.Parts)))
            {
                var anchor = parts[0].Cell;
                var held = parts.Select((p, k) => (p, k)).Where(t => t.k > 0 && t.p.Cell.IsEnv && t.p.Cell != anchor).ToArray();
                if (held.Length == 0)
                {
                    continue;
                }

                queries++;
                var asAnchor = (Part[])parts.Clone();
                foreach (var (p, k) in held)
                {
                    bool same = (p.Cell.Value & LandDefs.BlockMask) == (anchor.Value & LandDefs.BlockMask);
                    neighbour += same ? 1 : 0;
                    otherBlock += same ? 0 : 1;
                    var origin = p.Frame.Origin + LandDefs.GetBlockOffset(anchor, p.Cell);
                    Assert.True(Vector3.Distance(origin, parts[0].Frame.Origin) < 40f, $"step {index}: part {k} held in {p.Cell} lies {Vector3.Distance(origin, parts[0].Frame.Origin)} m from the anchor");
                    asAnchor[k] = p with { Cell = anchor, Frame = p.Frame with { Origin = origin } };
                }

                foreach (bool loadCells in new[] { false, true })
                {
                    var got = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, loadCells);
                    var want = ReferenceAdapter.Instance.FindCellParts(w.Scene, asAnchor, loadCells);
                    Assert.True(got.Cells.SequenceEqual(want.Cells), $"step {index} (loadCells {loadCells}): held [{string.Join(", ", got.Cells)}], in the anchor's cell [{string.Join(", ", want.Cells)}]");
                }
            }

            return true;
        });
        output.WriteLine($"{Cases} pr cases of {judge.Id}: {queries:N0} queries with held parts; held in a neighbour {neighbour:N0}, in another block's env cell {otherBlock:N0}");
        Assert.True(neighbour > 0 && otherBlock > 0, $"held in a neighbour {neighbour}, in another block {otherBlock}");
    }

    [Fact(DisplayName = "PARTS-BUILDING-ENTRY is judged on scenes with a building only (its own domain), every pr case")]
    public void BuildingEntryCasesHaveABuilding()
    {
        var judge = PartsIndoorInvariants.BuildingEntry;
        int cases = 0;
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            cases++;
            Assert.NotEmpty(w.Scene.Buildings);
            return true;
        });
        Assert.Equal(Cases, cases);
    }
}
