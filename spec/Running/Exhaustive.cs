using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>The outcome of sweeping a finite domain.</summary>
/// <param name="Domain">What was swept.</param>
/// <param name="Cases">How many cases.</param>
/// <param name="FirstViolation">The first violation in sweep order, or null.</param>
/// <param name="Elapsed">Wall time.</param>
public sealed record SweepResult(string Domain, long Cases, Violation? FirstViolation, TimeSpan Elapsed);

/// <summary>
/// Exhaustive sweeps where the domain is finite: every lcoord of the 2040 × 2040 map, and every landblock id
/// (all 65,536, 0xFF bytes included) × every land low word 1..64. Checked, not sampled.
/// </summary>
public static class Exhaustive
{
    /// <summary>Sweeps every lcoord (x, y) ∈ [0, 2040)² through an invariant, as the case (id 0, 0, 0, (x, y)).</summary>
    /// <param name="invariant">An invariant over the lcoord part of a case.</param>
    /// <param name="impl">The implementation.</param>
    /// <returns>The sweep result.</returns>
    public static SweepResult AllLcoords(Invariant<LandCase> invariant, ICellPhysics impl) =>
        Sweep("every lcoord (2040²)", LandDefs.LandLength, LandDefs.LandLength, (x, y) => new LandCase(CellId.None, 0f, 0f, new Lcoord(x, y)), invariant, impl);

    /// <summary>Sweeps every landblock id × low words 1..64 through an invariant, as the case (id, 0, 0, (−1, −1)).</summary>
    /// <param name="invariant">An invariant over the cell part of a case.</param>
    /// <param name="impl">The implementation.</param>
    /// <returns>The sweep result.</returns>
    public static SweepResult AllLandCellIds(Invariant<LandCase> invariant, ICellPhysics impl) =>
        Sweep("every block × 64 land cells", 65536, 64, (block, cell) => new LandCase(new CellId(((uint)block << 16) | (uint)(cell + 1)), 0f, 0f, new Lcoord(-1, -1)), invariant, impl);

    /// <summary>Returns the sweep an invariant has, or null: LCOORD-ROUNDTRIP sweeps lcoords and land cell ids, LCOORD-BLOCK and MAP-EDGE land cell ids.</summary>
    /// <param name="invariant">The invariant.</param>
    /// <param name="impl">The implementation.</param>
    /// <returns>The combined sweep, or null when the invariant has no finite domain.</returns>
    public static SweepResult? For(Invariant<LandCase> invariant, ICellPhysics impl)
    {
        if (ReferenceEquals(invariant, LandInvariants.LcoordRoundTrip))
        {
            var a = AllLcoords(invariant, impl);
            var b = AllLandCellIds(invariant, impl);
            return new SweepResult(a.Domain + " + " + b.Domain, a.Cases + b.Cases, a.FirstViolation ?? b.FirstViolation, a.Elapsed + b.Elapsed);
        }

        if (ReferenceEquals(invariant, LandInvariants.LcoordBlock) || ReferenceEquals(invariant, LandInvariants.MapEdge))
        {
            return AllLandCellIds(invariant, impl);
        }

        return null;
    }

    private static SweepResult Sweep(string domain, int rows, int columns, Func<int, int, LandCase> make, Invariant<LandCase> invariant, ICellPhysics impl)
    {
        var stopwatch = Stopwatch.StartNew();
        var firstByRow = new Violation?[rows];
        Parallel.For(0, rows, row =>
        {
            for (int column = 0; column < columns; column++)
            {
                var c = make(row, column);
                var outcome = invariant.Check(impl, c);
                if (outcome.IsViolation)
                {
                    firstByRow[row] = new Violation(invariant.Id, outcome.Message ?? "violated", c.ToString()) { Case = c };
                    return;
                }
            }
        });
        stopwatch.Stop();
        return new SweepResult(domain, (long)rows * columns, firstByRow.FirstOrDefault(v => v is not null), stopwatch.Elapsed);
    }
}
