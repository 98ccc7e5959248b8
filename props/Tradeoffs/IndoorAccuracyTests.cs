using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using AcPhys.Studies.Numerics;
using Xunit.Abstractions;

namespace AcPhys.Props.Tradeoffs;

/// <summary>The indoor rows of the accuracy table: the boundary classes mean what they say, and the measurement finds what it should.</summary>
public sealed class IndoorAccuracyTests(ITestOutputHelper output)
{
    private static readonly CottagePlan Plan = IndoorBenchCases.Plan; // rooms 6 × 5 m along +x, front door at local (3, 0)

    [Theory(DisplayName = "ACCURACY-INDOOR: a body is classed by the nearest boundary it touches (cottage-local point, radius)")]
    [InlineData("interior", 9f, 2.5f, 0.5f)] // room 1's centre
    [InlineData("portal-straddle", 3f, 0.2f, 0.5f)] // across the front door's plane
    [InlineData("portal-straddle", 5.8f, 2.5f, 0.5f)] // across the door to room 1
    [InlineData("wall", 3f, 4.8f, 0.5f)] // against room 0's north wall (no portal there)
    [InlineData("outdoor-near", 3f, -1.5f, 0.5f)] // in front of the door, 1 m clear
    [InlineData("outdoor", 3f, -6f, 0.5f)] // well away
    public void ClassOfABoxRoomBody(string expected, float x, float y, float r)
    {
        var centre = Plan.ToBlock(new Vector3(x, y, 1.5f));
        Assert.Equal(expected, IndoorAccuracyClass.Of(IndoorBenchCases.BoxCottage, Plan.RoomId(0), [new Sphere(centre, r)]));
    }

    [Fact(DisplayName = "ACCURACY-INDOOR: in an L-shaped room's second arm the class is union-arm (outside the piece the BSP sees)")]
    public void UnionArm()
    {
        var centre = Plan.ToBlock(new Vector3(1.5f, 4.2f, 1.5f));
        Assert.Equal("union-arm", IndoorAccuracyClass.Of(IndoorBenchCases.UnionCottage, Plan.RoomId(0), [new Sphere(centre, 0.3f)]));
        Assert.Equal("interior", IndoorAccuracyClass.Of(IndoorBenchCases.BoxCottage, Plan.RoomId(0), [new Sphere(centre, 0.3f)]));
    }

    [Fact(DisplayName = "ACCURACY-INDOOR: box rooms agree off the tolerance bands; unions disagree in their arms")]
    public void SmallRun()
    {
        var report = IndoorAccuracyRun.Run(8, 12, 12);
        long Any(string shape, params string[] classes) => report.Rows.Where(r => r.Shape == shape && classes.Contains(r.Class)).Sum(r => r.Any);
        long Queries(string shape, params string[] classes) => report.Rows.Where(r => r.Shape == shape && classes.Contains(r.Class)).Sum(r => r.Queries);
        foreach (var r in report.Rows.Where(r => r.Queries > 0))
        {
            output.WriteLine($"{r.Source} / {r.Shape} / {r.Class}: {r.Any} of {r.Queries}");
        }

        Assert.True(Queries("box", "interior", "outdoor-near") > 0, "the run must reach box interiors and the outside");
        Assert.Equal(0, Any("box", "interior", "union-arm", "outdoor-near", "outdoor"));
        Assert.True(Any("l-shape", "union-arm") + Any("stairs", "union-arm") > 0, "an AABB covers a union's further pieces, which the BSP does not see");
    }

    [Fact(DisplayName = "ACCURACY-INDOOR: two runs with one seed give the same counts (no dependence on thread scheduling)")]
    public void Deterministic()
    {
        static string Counts(IndoorAccuracyReport r) => string.Join(";", r.Rows.Select(x => $"{x.Source}/{x.Shape}/{x.Class}:{x.Queries}/{x.Any}"));
        Assert.Equal(Counts(IndoorAccuracyRun.Run(3, 6, 8)), Counts(IndoorAccuracyRun.Run(3, 6, 8)));
    }
}
