using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using FsCheck;
using FsCheck.Fluent;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// Issue 41's generators: exact bounds in the cell frame and interiors side by side — that they reach what they claim
/// (distributions printed), and TIES-PINNED-INDOOR as a property of the reference.
/// </summary>
public sealed class InteriorCornerTests(ITestOutputHelper output)
{
    private static readonly Rnd Seed = new(41, 0x9E3779B97F4A7C15UL);

    [Fact(DisplayName = "TIES-PINNED-INDOOR: at an exact bound in the cell frame retail's comparison is false")]
    public void TiesPinned() => PropertyRun.Check(IndoorTieInvariants.TiesPinned, output);

    [Fact(DisplayName = "Exact bounds: every generated plan's tie is exactly at ±(r + pad) in the tested cell's frame, in float32 after GlobalToLocal")]
    public void TieIsExactInTheCellFrame()
    {
        var plans = Gen.Sample(InteriorGens.ExactBounds, 400, Seed, 50);
        var counts = new Dictionary<string, int>();
        foreach (var plan in plans)
        {
            var (d, bound) = plan.TieDistance();
            Assert.True(d == bound, $"{plan}: d = {d:R} in the cell's frame, bound {bound:R}");
            Assert.Equal(plan.Bound, plan.Radius + plan.Pad); // R = r + pad is one float32 sum, as retail computes it (facts §1.5)
            foreach (var tag in plan.Classes())
            {
                counts[tag] = counts.GetValueOrDefault(tag) + 1;
            }
        }

        output.WriteLine(string.Join(", ", counts.OrderBy(kv => kv.Key).Select(kv => $"{kv.Key} {kv.Value}")));
        Assert.All(new[] { "exact:neighbour", "exact:building", "exact:exit-plane", "exact:hint-plane", "frame:half-turn" }, tag => Assert.True(counts.GetValueOrDefault(tag) >= 40, $"{tag}: {counts.GetValueOrDefault(tag)} of 400"));
    }

    [Fact(DisplayName = "Exact bounds: the reference answers the tie as retail (Outside, no straddle, no hint) and one float32 ulp inside it as reaching")]
    public void ReferenceAtAndPastTheTie()
    {
        var impl = new ReferenceAdapter();
        int atTie = 0;
        foreach (var plan in Gen.Sample(InteriorGens.ExactBounds, 120, Seed, 50))
        {
            var recipe = new SceneRecipe(null, null, SceneRoute.ExactBound, 0, plan.Radius, false, plan.Radius, SceneGens.Jitters[0], int.MaxValue) { Plan = plan };
            var steps = SceneWalkRunner.Run(impl, recipe.Build(), true);
            var tie = steps.First(s => s.Index == (plan.StartAt % 2 == 1 ? 0 : 1)); // the second of the four positions is the tie
            var other = plan.Block.BlockCell.WithLow((ushort)(plan.Target == NearTarget.Building ? 0x100 : 0x101));
            bool reached = plan.Target == NearTarget.ExitPlane ? tie.Cells.Any(c => c.IsLand) : tie.Cells.Contains(other);
            Assert.False(reached, $"{plan}: the reference reaches at the exact tie: [{string.Join(", ", tie.Cells)}]");
            atTie++;
        }

        output.WriteLine($"{atTie} ties answered as retail");
    }

    [Fact(DisplayName = "Side by side: leaving room A by its door the body touches room B, which the reference enters by the building of the land cell across the line")]
    public void SideBySideTouchesTheNeighbour()
    {
        var impl = new ReferenceAdapter();
        var counts = new Dictionary<string, int>();
        foreach (var plan in Gen.Sample(InteriorGens.SideBySide, 150, Seed, 50))
        {
            var recipe = new SceneRecipe(null, null, SceneRoute.SideBySide, 0, 0.75f, false, 0.25f, SceneGens.Jitters[0], int.MaxValue) { Plan = plan };
            var walk = recipe.Build();
            var a = plan.Block.BlockCell.WithLow(0x100);
            var b = plan.Block.BlockCell.WithLow(0x101);
            var steps = SceneWalkRunner.Run(impl, walk, true);
            // Some query with sphere 0's centre west of the line (A's side) has B as a candidate: building entry from the east
            // land cell. Houses apart by more than the radius (a share of them) are touched only from across the line.
            float west = (float)(plan.WorldX - (192.0 * plan.Block.X)) + (plan.Layout == SideLayout.Apart && plan.GapFraction >= 1 ? plan.HalfGap(0.75f) : 0);
            bool touched = steps.Any(s => s.Query.Spheres[0].Center.X < west && s.Cells.Contains(b) && s.Containing != b);
            Assert.True(touched, $"{plan}: B is never a candidate while the body is west of the line (of B's wall, for houses more than a radius apart)");
            Assert.True(b == steps[^1].Containing, $"{plan}: the walk ends in {steps[^1].Containing}, not B; containing cells {string.Join(" ", steps.Select(s => s.Containing).Distinct())}"); // and the walk ends in B
            Assert.Contains(steps, s => s.Containing == a);
            foreach (var tag in plan.Classes())
            {
                counts[tag] = counts.GetValueOrDefault(tag) + 1;
            }
        }

        output.WriteLine(string.Join(", ", counts.OrderBy(kv => kv.Key).Select(kv => $"{kv.Key} {kv.Value}")));
        Assert.Equal(3, counts.Count);
    }

    [Fact(DisplayName = "Side by side: in a good share of the cases a body still in room A (its centre inside A) overlaps room B while it leaves A by its door, and the reference's transition then lists B (distribution printed)")]
    public void IndoorsReachTheOther()
    {
        var impl = new ReferenceAdapter();
        var perLayout = new Dictionary<SideLayout, (int Cases, int Reach)>();
        foreach (var recipe in Gen.Sample(InteriorGens.Recipes, 400, Seed, 50).Where(r => r.Plan is SideBySidePlan))
        {
            var plan = (SideBySidePlan)recipe.Plan!;
            var walk = recipe.Build();
            var classes = SceneDomain.Instance.Classes(walk).ToHashSet();
            bool reach = classes.Contains(plan.Layout == SideLayout.Closet ? "interiors:indoors-reach-closet" : "interiors:indoors-reach-other");
            Assert.Equal(reach && plan.Layout == SideLayout.Apart, classes.Contains("interiors:doors-apart-reach"));
            var (cases, hits) = perLayout.GetValueOrDefault(plan.Layout);
            perLayout[plan.Layout] = (cases + 1, hits + (reach ? 1 : 0));
            if (!reach)
            {
                continue;
            }

            // The class is conservative: where it says so, retail (the reference) lists B while A still contains the centre
            // (facts §5.1: A's exit adds the land cell across the line; §5.3: that cell's building enters B).
            var a = plan.Block.BlockCell.WithLow(0x100);
            var b = plan.Block.BlockCell.WithLow(0x101);
            var steps = SceneWalkRunner.Run(impl, walk, true);
            Assert.True(steps.Any(s => s.Containing == a && s.Cells.Contains(b)), $"{recipe}: tagged as reaching B from inside A, but no transition in A lists B");
        }

        output.WriteLine(string.Join(", ", perLayout.OrderBy(kv => kv.Key).Select(kv => $"{kv.Key}: {kv.Value.Reach} of {kv.Value.Cases} reach the other room from indoors")));
        Assert.All(perLayout, kv => Assert.True(kv.Value.Reach * 4 >= kv.Value.Cases, $"{kv.Key}: only {kv.Value.Reach} of {kv.Value.Cases} reach the other room from indoors"));
        Assert.Equal(3, perLayout.Count);
    }

    [Fact(DisplayName = "building-entry-own-building-only is caught by BUILDING-ENTRY-COMPLETE and shrinks to the smallest scene that shows it: two one-room buildings, 4 m square")]
    public void OwnBuildingOnlyShrinksToTwoOneRoomHouses()
    {
        var impl = PlantedFaults.Create(InteriorFaults.BuildingEntryOwnBuildingOnly.Id);
        var result = InvariantCatalogue.Find("BUILDING-ENTRY-COMPLETE")!.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor("BUILDING-ENTRY-COMPLETE"), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var shrunk = Assert.IsType<AnyCase.WalkInScene>(result.Violation!.Case).Walk;
        output.WriteLine($"shrunk: {shrunk.Recipe}");
        output.WriteLine(result.Violation.Message);
        var plan = Assert.IsType<SideBySidePlan>(Assert.IsType<SceneRecipe>(shrunk.Recipe).Plan);
        Assert.NotEqual(SideLayout.Closet, plan.Layout); // the own building's closet is still entered: two buildings are needed
        Assert.Equal(2, shrunk.Scene.Cells.Count);
        Assert.Equal(2, shrunk.Scene.Buildings.Count);
        Assert.All(shrunk.Scene.Buildings, building => Assert.Single(building.Portals));
        Assert.Equal((4f, 4f, 0), (plan.Width, plan.Depth, plan.Flips));
    }

    [Fact(DisplayName = "building-entry-own-building-only is exposed only by a body leaving one house by its door while it touches the other: every pr case BUILDING-ENTRY-COMPLETE judges violated under it has a query from inside house A that straddles A's door and reaches house B")]
    public void OwnBuildingOnlyNeedsTheGeometry()
    {
        var impl = PlantedFaults.Create(InteriorFaults.BuildingEntryOwnBuildingOnly.Id);
        var judge = IndoorClosureInvariants.BuildingEntryComplete;
        int violated = 0, ofClass = 0;
        var others = new List<string>();
        CaseSweep.Each(judge.Domain, Profile.Pr.CasesPerInvariant, AcPhys.Spec.Running.Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), c =>
        {
            ofClass += judge.Domain.Classes(c).Contains("interiors:indoors-reach-other") ? 1 : 0;
            // The geometry, liberally: a query from inside house A in which a sphere straddles A's door and comes within
            // reach of house B (the strict class needs sphere 0's centre still in A; the step out of the door is asked from A too).
            bool reach = c.Recipe is SceneRecipe { Plan: SideBySidePlan { Layout: not SideLayout.Closet } plan } && plan.Reaches(c, liberal: true);
            if (judge.Check(impl, c).IsViolation)
            {
                violated++;
                if (!reach)
                {
                    others.Add(string.Join(" ", judge.Domain.Classes(c).Where(t => t.StartsWith("scene:", StringComparison.Ordinal) || t.StartsWith("route:", StringComparison.Ordinal))));
                }
            }

            return true;
        });
        output.WriteLine($"{violated} violated cases, {ofClass} of class interiors:indoors-reach-other; outside it: {others.Count}");
        Assert.True(violated > 0, "the fault is never judged violated on the pr cases");
        Assert.True(others.Count == 0, "violated outside the class: " + string.Join("; ", others.Distinct()));
    }
}
