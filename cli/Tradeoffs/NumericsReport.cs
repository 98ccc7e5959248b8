using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Studies.Numerics;
using static AcPhys.Cli.Tradeoffs.Markdown;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>The tables of docs/numerics.md §7–§8: the extreme sweeps and the measured float32 tie bands.</summary>
internal static class NumericsReport
{
    /// <summary>Runs every measurement and prints the tables.</summary>
    /// <returns>0 when the double mode never disagreed and every float32 disagreement was explained, else 1.</returns>
    public static int Run()
    {
        Terminal.Line($"<!-- acphys tradeoffs numerics; {Machine.Describe()} at start -->");
        Terminal.Line("**Extreme sweeps** (whole point sets; outdoor queries at radii " + string.Join(", ", ExtremePoints.Radii.Select(F)) + "):");
        Terminal.Line();
        var sweeps = new[]
        {
            NumericSweep.Run("x = 24k lines ±4 ULP, every block frame", ExtremePoints.Lines(alongX: true), ReferenceAdapter.Instance, ReferenceAdapter.Double),
            NumericSweep.Run("y = 24k lines ±4 ULP, every block frame", ExtremePoints.Lines(alongX: false), ReferenceAdapter.Instance, ReferenceAdapter.Double),
            NumericSweep.Run("disc edges 24k ± r, ±4 ULP", ExtremePoints.DiscEdges(), ReferenceAdapter.Instance, ReferenceAdapter.Double),
            NumericSweep.Run("block corners ±4 ULP", ExtremePoints.Corners(), ReferenceAdapter.Instance, ReferenceAdapter.Double),
            NumericSweep.Run("special values × edge / 0xFF blocks", ExtremePoints.SpecialValues(), ReferenceAdapter.Instance, ReferenceAdapter.Double),
        };
        Table(
            ["point set", "points", "LandDefs checks", "outdoor queries", "float32 ≠ exact", "by rounding", "double ≠ exact", "failures", "ms"],
            sweeps.Select(s => (IReadOnlyList<string>)
            [
                s.Domain, N(s.Points), N(s.LandChecks), N(s.OutdoorQueries),
                $"{N(s.Float32Disagreements.Values.Sum())} ({Pct(s.Float32Disagreements.Values.Sum(), s.OutdoorQueries)})",
                string.Join(", ", s.Float32Disagreements.OrderBy(k => k.Key).Select(k => $"{k.Key} {N(k.Value)}")),
                N(s.DoubleDisagreements), N(s.Failures.Count), N((long)s.Elapsed.TotalMilliseconds),
            ]));
        foreach (var s in sweeps)
        {
            foreach (var (reason, text) in s.Example.OrderBy(k => k.Key))
            {
                Terminal.Line($"- {s.Domain}, {reason}: `{text}`");
            }
        }

        Terminal.Line();
        Terminal.Line("**Re-base v − 192·⌊v/192⌋ in float32, every negative float32 of each binade** (|v| ≥ EPS):");
        Terminal.Line();
        var binades = TieBands.RebaseByBinade();
        Table(
            ["v", "floats", "re-base inexact", "rounds onto a line (tie)"],
            binades.Where(b => b.Negative).Select(b => (IReadOnlyList<string>)
            [
                $"−[{R(b.Low)}, {R(b.High)})", N(b.Floats), $"{N(b.Inexact)} ({Pct(b.Inexact, b.Floats)})", $"{N(b.OntoLine)} ({Pct(b.OntoLine, b.Floats)})",
            ]));
        var positive = binades.Where(b => !b.Negative).ToList();
        Terminal.Line($"Positive v, same binades: {N(positive.Sum(b => b.Floats))} floats, {N(positive.Sum(b => b.Inexact))} inexact, {N(positive.Sum(b => b.OntoLine))} ties.");
        Terminal.Line();

        Terminal.Line("**Tie band below each line, seen from the east/north neighbour's frame** (consecutive floats below `line − 192` whose re-base rounds onto the line):");
        Terminal.Line();
        Table(
            ["line in target block (m)", "coordinate in neighbour frame", "band (ULPs of v)", "band (m)"],
            TieBands.BelowLines().Select(b => (IReadOnlyList<string>)[F(b.Line), F(b.Frame), N(b.Ulps), R(b.Metres)]));

        Terminal.Line("**Retail's float32 24 − r (maxRad, facts §3.2)** per radius:");
        Terminal.Line();
        Table(
            ["r", "float32 24 − r", "error (m)", "can flip a neighbour test"],
            TieBands.MaxRad([0f, float.Epsilon, 0.1f, 0.3f, 0.5f, 1f / 3f, 12f, MathF.BitIncrement(12f), 23.9f, 24f, 30f]).Select(m => (IReadOnlyList<string>)
                [F(m.Radius), F(m.Float32), R(m.ErrorMetres), m.Flips ? "yes (rounds up)" : "no"]));
        var (radii, up, max) = TieBands.MaxRadOverAllRadii();
        Terminal.Line($"Over every float32 radius in [2^-10, 24): {N(radii)} radii, 24 − r rounds up for {N(up)} ({Pct(up, radii)}), largest error {R(max)} m.");
        Terminal.Line();
        float reframe = TieBands.ReframeBand();
        Terminal.Line($"**EPS snap band**: |v| < {F(LandDefs.Epsilon)} snaps; largest snapped {F(MathF.BitDecrement(LandDefs.Epsilon))}, smallest kept {F(LandDefs.Epsilon)} "
            + $"({N(2L * BitConverter.SingleToInt32Bits(MathF.BitDecrement(LandDefs.Epsilon)) + 2)} float32 values snap, ±0 included).");
        Terminal.Line();
        Terminal.Line($"**Pick re-framing band**: a centre 0 < v ≤ {F(reframe)} m ({R(reframe)}) east/north of a block line re-expressed in the west/south neighbour's frame rounds to exactly 192, onto that cell's closed square.");
        Terminal.Line();
        Terminal.Line($"<!-- {Machine.Describe()} at end -->");
        bool clean = sweeps.All(s => s.DoubleDisagreements == 0 && s.Failures.Count == 0);
        foreach (var failure in sweeps.SelectMany(s => s.Failures))
        {
            Terminal.Error("tradeoffs numerics", failure);
        }

        return clean ? ExitCodes.Ok : ExitCodes.Violated;
    }
}
