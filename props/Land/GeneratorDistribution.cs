using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using FsCheck;
using FsCheck.Fluent;
using Xunit.Abstractions;

namespace AcPhys.Props.Land;

/// <summary>
/// The generators really hit the boundaries: every class is drawn at a measured rate, and no invariant passes by
/// being vacuous on most cases (a property that "passes" by discarding cases is a defect).
/// </summary>
public sealed class GeneratorDistribution(ITestOutputHelper output)
{
    private const int Samples = 20_000;

    private static readonly LandCase[] Drawn = Gen.Sample(LandGens.Cases, Samples, new Rnd(0xD157, 0x9E3779B97F4A7C15UL), 50);

    [Fact(DisplayName = "Every boundary class of coordinates, cells and lcoords is drawn at least 0.5 % of the time")]
    public void EveryClassIsHit()
    {
        var counts = new Dictionary<string, int>();
        foreach (var c in Drawn)
        {
            foreach (var tag in BoundaryClasses.Of(c))
            {
                counts[tag] = counts.GetValueOrDefault(tag) + 1;
            }
        }

        foreach (var kv in counts.OrderByDescending(k => k.Value))
        {
            output.WriteLine($"{kv.Key,-24} {kv.Value,6}  {100.0 * kv.Value / Samples,5:F1} %");
        }

        var expected = BoundaryClasses.CoordinateClasses.Select(c => "coord:" + c)
            .Concat(BoundaryClasses.CellClasses)
            .Concat(BoundaryClasses.LcoordClasses);
        Assert.All(expected, cls => Assert.True(counts.GetValueOrDefault(cls) >= Samples / 200, $"{cls} drawn {counts.GetValueOrDefault(cls)} times in {Samples}"));
    }

    [Fact(DisplayName = "No invariant is vacuous on more than 90 % of generated cases")]
    public void NoInvariantIsMostlyVacuous()
    {
        foreach (var invariant in InvariantCatalogue.Land)
        {
            int applicable = Drawn.Count(c => invariant.Check(ReferenceAdapter.Instance, c).Verdict == Verdict.Holds);
            output.WriteLine($"{invariant.Id,-28} applies to {100.0 * applicable / Samples,5:F1} % of cases");
            Assert.True(applicable >= Samples / 10, $"{invariant.Id} applies to only {applicable} of {Samples} cases");
        }
    }

    [Fact(DisplayName = "The same seed draws the same cases, bit for bit")]
    public void SameSeedSameCases()
    {
        var again = Gen.Sample(LandGens.Cases, Samples, new Rnd(0xD157, 0x9E3779B97F4A7C15UL), 50);
        Assert.True(Drawn.Zip(again).All(p => LandCaseCodec.Encode(p.First).AsSpan().SequenceEqual(LandCaseCodec.Encode(p.Second))));
    }
}
