using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Studies.Invariants;
using AcPhys.Studies.Numerics;
using Xunit.Abstractions;

namespace AcPhys.Props.Numerics;

/// <summary>The double-precision mode and the exact oracle: the mode is exact, the oracle is exact, float32 departs only where it rounds.</summary>
public sealed class PrecisionModes(ITestOutputHelper output)
{
    [Fact(DisplayName = "NUMERICS: over generated queries, fine floats and walk steps the double mode equals the exact oracle and float32 departs only where it rounds")]
    public void DoubleModeIsExact()
    {
        var report = AccuracyRun.Run(seed: 8, cases: 2_000);
        foreach (var row in report.Rows.Where(r => r.Queries > 0))
        {
            output.WriteLine($"{row.Source,-17} {row.Class,-11} {row.Queries,6}  float32 != exact {row.Float32Any,4}  double != exact {row.DoubleAny}  {string.Join(", ", row.Reasons.Select(k => $"{k.Key} {k.Value}"))}");
        }

        Assert.All(report.Rows, r => Assert.Equal(0, r.DoubleAny));
        Assert.All(report.Rows, r => Assert.False(r.Reasons.ContainsKey("unexplained"), $"{r.Source}/{r.Class}: unexplained float32 disagreement"));
        Assert.All(AccuracyClass.All, cls => Assert.Contains(report.Rows, r => r.Class == cls && r.Queries > 0));
        Assert.True(report.Rows.Sum(r => r.Float32Any) > 0, "float32 never departed from the exact oracle: the cases do not reach a rounding");
    }

    [Fact(DisplayName = "NUMERICS: the tie-band example of docs/numerics.md §1 differs in float32 and not in double")]
    public void TieBandExample()
    {
        var query = new AcPhys.Formats.Cases.OutdoorCase(new CellId(0x01000001), [new Sphere(new System.Numerics.Vector3(-48.000008f, 100.5f, 0.5f), float.Epsilon)]);
        var f = PrecisionCheck.Compare(ReferenceAdapter.Instance, query)!;
        var d = PrecisionCheck.Compare(ReferenceAdapter.Double, query)!;
        output.WriteLine(f.Detail);
        Assert.True(f.CellsDiffer);
        Assert.Equal(Rounding.Rebase, f.Reason);
        Assert.True(d.Agrees);
    }

    [Fact(DisplayName = "NUMERICS: Dyadic holds every float32 exactly and floors toward -inf")]
    public void DyadicIsExact()
    {
        var random = new Random(8);
        for (int i = 0; i < 20_000; i++)
        {
            float v = BitConverter.Int32BitsToSingle(random.Next(int.MinValue, int.MaxValue));
            if (!float.IsFinite(v) || Math.Abs(v) > 1e30)
            {
                continue;
            }

            Assert.Equal((double)v, Dyadic.Of(v).ToDouble());
            if (Math.Abs(v) < 1e6)
            {
                Assert.Equal(Math.Floor(v / 24.0), (double)Dyadic.Of(v).FloorDiv(24));
            }
        }

        Assert.Equal(-1, (int)Dyadic.Of(-float.Epsilon).FloorDiv(24));
        Assert.Equal(0, (int)Dyadic.Of(float.Epsilon).FloorDiv(24));
        Assert.True(Dyadic.Of(24) - Dyadic.Of(float.Epsilon) < Dyadic.Of(24));
    }

    [Fact(DisplayName = "NUMERICS: the double mode keeps retail's rules: EPS snap, last-wins pick on exact lines, map edge")]
    public void DoubleModeKeepsTheRules()
    {
        foreach (var centre in new[] { new System.Numerics.Vector3(-0.0001f, 100f, 0.5f), new System.Numerics.Vector3(24f, 96f, 0.5f), new System.Numerics.Vector3(0f, 0f, 0.5f) })
        {
            var spheres = new[] { new Sphere(centre, 0.5f) };
            var array = new CellArray();
            var pick = CellQuery.FindCellListOutdoor(array, new CellId(0x10100001), spheres, CellId.None, PickPolicy.Retail, OpenLand.Instance, OutdoorFidelity.Double);
            var retail = new CellArray();
            var retailPick = CellQuery.FindCellListOutdoor(retail, new CellId(0x10100001), spheres, CellId.None, PickPolicy.Retail, OpenLand.Instance);
            output.WriteLine($"{centre}: [{string.Join(", ", array.ToIdArray())}] pick {pick}");
            Assert.Equal(retail.ToIdArray(), array.ToIdArray());
            Assert.Equal(retailPick, pick);
        }

        double x = -0.0001, y = 0;
        var id = new CellId(0x00000001);
        Assert.True(LandDefs.AdjustToOutsideInDouble(ref id, ref x, ref y)); // snapped into block 0, not off the map
        Assert.Equal(new CellId(0x00000001), id);
        x = -0.001;
        Assert.False(LandDefs.AdjustToOutsideInDouble(ref id, ref x, ref y));
    }
}
