using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Coverage;

/// <summary>
/// The pr gate pins both sides of every bound of cell_in_range (facts §1.1: land 0x0001..0x0040, env 0x0100..0xFFFD,
/// block 0xFFFF) for every port: a port's <c>low &gt; 0x100</c> where retail says <c>low &gt;= 0x100</c> survived the
/// whole gate until the generators drew the bounds themselves (docs/ports.md §12).
/// </summary>
public sealed class LowWordBoundsTests
{
    public static TheoryData<string> CellCaseInvariants() =>
        [.. InvariantCatalogue.All.Where(i => i.CaseType == typeof(LandCase) || i.CaseType == typeof(OutdoorCase)).Select(i => i.Id)];

    [Theory(DisplayName = "LOW-WORD-BOUNDS: every LandDefs and outdoor-query invariant's pr cases put each bound of the low-word ranges on an on-map block")]
    [MemberData(nameof(CellCaseInvariants))]
    public void EveryBoundIsAmongThePrCases(string id)
    {
        var invariant = InvariantCatalogue.Find(id)!;
        var seed = Seed.Derive(Profile.Pr.BaseSeed!.Value, id);
        var seen = new Dictionary<ushort, int>();
        void Count(CellId cell)
        {
            if (cell.BlockX != 0xFF && cell.BlockY != 0xFF && LandGens.LowWordBounds.Contains(cell.Low))
            {
                seen[cell.Low] = seen.GetValueOrDefault(cell.Low) + 1;
            }
        }

        if (invariant is Invariant<LandCase> land)
        {
            CaseSweep.Each(land.Domain, Profile.Pr.CasesPerInvariant, seed, c => { Count(c.Cell); return true; });
        }
        else
        {
            CaseSweep.Each(((Invariant<OutdoorCase>)invariant).Domain, Profile.Pr.CasesPerInvariant, seed, c => { Count(c.Cell); return true; });
        }

        var missing = LandGens.LowWordBounds.Where(b => !seen.ContainsKey(b)).Select(b => $"0x{b:X4}").ToList();
        Assert.True(missing.Count == 0, $"{id}: no pr case (seed {seed}) has the low word {string.Join(", ", missing)} on an on-map block; seen {string.Join(", ", seen.OrderBy(p => p.Key).Select(p => $"0x{p.Key:X4}×{p.Value}"))}");
    }

    [Fact(DisplayName = "LANDDEFS-CONFORMANCE: a port that takes 0x0100, the first env cell, for an invalid low word fails the pr gate")]
    public void FirstEnvCellAsInvalidFails()
    {
        var result = CatalogueRunner.RunInvariant(ConformanceInvariants.LandDefs, new FirstEnvCellInvalid(), Profile.Pr, Profile.Pr.BaseSeed!.Value);
        Assert.Equal(ResultStatus.Failed, result.Status);
        Assert.Contains("0100", result.Violation!.CaseText, StringComparison.Ordinal); // the shrunk case keeps the bound
    }

    [Fact(DisplayName = "FIND-CELL-QUERY-CONFORMANCE: a port whose find_cell takes the position 0x0100 for open land fails the pr gate")]
    public void FirstEnvCellAsLandFails()
    {
        var result = CatalogueRunner.RunInvariant(ConformanceInvariants.FindCellQuery, new FirstEnvCellIsLand(), Profile.Pr, Profile.Pr.BaseSeed!.Value);
        Assert.Equal(ResultStatus.Failed, result.Status);
    }

    // The reference, except that the low word 0x0100 is not in range (the mutant `low > 0x100` of a port's cell_in_range).
    private sealed class FirstEnvCellInvalid() : Forwarding(ReferenceAdapter.Instance)
    {
        public override bool InboundValidCellId(CellId id) => id.Low != 0x100 && Inner.InboundValidCellId(id);

        public override bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord)
        {
            lcoord = default;
            return id.Low != 0x100 && Inner.GetOutsideLcoord(id, x, y, out lcoord);
        }

        public override AdjustResult AdjustToOutside(CellId id, float x, float y) =>
            id.Low == 0x100 ? new AdjustResult(false, CellId.None, x, y) : Inner.AdjustToOutside(id, x, y);
    }

    // The reference, except that a query from 0x0100 is answered as one from the block's first land cell.
    private sealed class FirstEnvCellIsLand() : Forwarding(ReferenceAdapter.Instance)
    {
        public override FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
            Inner.FindCell(cell.Low == 0x100 ? new CellId(cell.BlockX, cell.BlockY, 1) : cell, origin, spheres, current);
    }
}
