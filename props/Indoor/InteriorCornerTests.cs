using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
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
            // Some query with sphere 0's centre west of the line (A's side) has B as a candidate: building entry from the east land cell.
            bool touched = steps.Any(s => s.Query.Spheres[0].Center.X < (float)(plan.WorldX - (192.0 * plan.Block.X)) && s.Cells.Contains(b) && s.Containing != b);
            Assert.True(touched, $"{plan}: B is never a candidate while the body is west of the line");
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
}
