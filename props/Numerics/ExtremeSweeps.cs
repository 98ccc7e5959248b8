using AcPhys.Contract;
using AcPhys.Spec.Faults;
using AcPhys.Studies.Numerics;
using Xunit.Abstractions;

namespace AcPhys.Props.Numerics;

/// <summary>
/// Issue #8 extremes, swept whole: every 24 m / 192 m line ± 1..4 ULP in every block frame, block corners, and the
/// special values. LandDefs invariants hold, AdjustToOutside is the exact answer rounded once, the float32 outdoor
/// set differs from the exact one only where a named float32 rounding explains it, and the double mode never does.
/// </summary>
public sealed class ExtremeSweeps(ITestOutputHelper output)
{
    [Fact(DisplayName = "NUMERICS: every x = 24k line of every block frame (k = -8..16) +-4 ULP matches the exact oracle")]
    public void EveryVerticalLine() => AssertExact(NumericSweep.Run("x lines", ExtremePoints.Lines(alongX: true), ReferenceAdapter.Instance, ReferenceAdapter.Double), expectTies: true);

    [Fact(DisplayName = "NUMERICS: every y = 24k line of every block frame (k = -8..16) +-4 ULP matches the exact oracle")]
    public void EveryHorizontalLine() => AssertExact(NumericSweep.Run("y lines", ExtremePoints.Lines(alongX: false), ReferenceAdapter.Instance, ReferenceAdapter.Double), expectTies: true);

    [Fact(DisplayName = "NUMERICS: disc edges 24k +- r (r = 0, subnormal, 0.3, 12, 12+ULP) +-4 ULP match the exact oracle")]
    public void DiscEdges() => AssertExact(NumericSweep.Run("disc edges", ExtremePoints.DiscEdges(), ReferenceAdapter.Instance, ReferenceAdapter.Double), expectTies: true);

    [Fact(DisplayName = "NUMERICS: block corners +-4 ULP on the map's diagonal, corners and edges match the exact oracle")]
    public void BlockCorners() => AssertExact(NumericSweep.Run("corners", ExtremePoints.Corners(), ReferenceAdapter.Instance, ReferenceAdapter.Double), expectTies: true);

    [Fact(DisplayName = "NUMERICS: EPS band edges, +-1e6, +-MaxValue, NaN, +-Inf, -0 and subnormals in edge and 0xFF blocks match the exact oracle")]
    public void SpecialValues() => AssertExact(NumericSweep.Run("special values", ExtremePoints.SpecialValues(), ReferenceAdapter.Instance, ReferenceAdapter.Double), expectTies: false);

    [Theory(DisplayName = "NUMERICS: the line sweep bites planted LandDefs faults")]
    [InlineData("trunc-floor")]
    [InlineData("no-eps-snap")]
    [InlineData("drop-block-length")]
    public void LineSweepCatchesFaults(string fault)
    {
        var sweep = NumericSweep.Run("x lines", ExtremePoints.Lines(alongX: true), PlantedFaults.Create(fault), ReferenceAdapter.Double);
        output.WriteLine(sweep.Failures.FirstOrDefault() ?? "none");
        Assert.NotEmpty(sweep.Failures);
    }

    [Fact(DisplayName = "NUMERICS: the special values include every class issue #8 names")]
    public void SpecialsCoverTheClasses()
    {
        var classes = ExtremePoints.Specials.Select(AcPhys.Spec.Cases.BoundaryClasses.OfCoordinate).ToHashSet();
        output.WriteLine(string.Join(", ", classes.Order()));
        Assert.Superset(new HashSet<string> { "nonfinite", "huge", "neg-zero", "subnormal", "eps-band", "eps-edge", "line-24", "line-192" }, classes);
        Assert.Contains(ExtremePoints.Specials, float.IsNaN);
        Assert.Contains(ExtremePoints.Specials, v => v == float.MaxValue);
        Assert.Contains(ExtremePoints.Specials, v => v == -float.MaxValue);
    }

    private void AssertExact(NumericSweepResult sweep, bool expectTies)
    {
        output.WriteLine($"{sweep.Domain}: {sweep.Points:N0} points, {sweep.LandChecks:N0} LandDefs checks, {sweep.OutdoorQueries:N0} outdoor queries x 2 modes in {sweep.Elapsed.TotalMilliseconds:F0} ms ({Environment.ProcessorCount} cores)");
        foreach (var (reason, n) in sweep.Float32Disagreements.OrderBy(k => k.Key))
        {
            output.WriteLine($"  float32 != exact, {reason}: {n:N0}  e.g. {sweep.Example[reason]}");
        }

        output.WriteLine($"  double != exact: {sweep.DoubleDisagreements}");
        Assert.Empty(sweep.Failures);
        Assert.Equal(0, sweep.DoubleDisagreements);
        Assert.True(sweep.OutdoorQueries > 0);
        if (expectTies)
        {
            // The sweep reaches the float32 tie band: without this the comparison could pass by never leaving exact arithmetic.
            Assert.True(sweep.Float32Disagreements.Values.Sum() > 0, "no float32 disagreement at all: the sweep does not reach the tie band");
        }
    }
}
