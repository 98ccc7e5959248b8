using System.CommandLine;
using AcPhys.Cli.Tradeoffs;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>tradeoffs</c> verb: the measurements behind docs/numerics.md and docs/tradeoffs.md, each printed as markdown tables.</summary>
internal static class TradeoffsCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var numerics = new Command("numerics", "Sweep the float32 extremes against the exact oracle and measure the tie bands (docs/numerics.md §7).");
        numerics.SetAction(_ => Guard.Run("tradeoffs numerics", NumericsReport.Run));

        var seed = new Option<int>("--seed") { Description = "Seed of the generated cases.", DefaultValueFactory = _ => 8, HelpName = "N" };
        var cases = new Option<int>("--cases") { Description = "Queries per source (walks: a quarter as many walks; indoor: a fiftieth as many generated scenes).", DefaultValueFactory = _ => 20_000, HelpName = "N" };
        var accuracy = new Command("accuracy", "Disagreement rate of the float32 and double modes against the exact oracle, and of AABB against BSP cells indoors, by boundary class (docs/tradeoffs.md).") { seed, cases };
        accuracy.SetAction(parse => Guard.Run("tradeoffs accuracy", () => AccuracyTable.Run(parse.GetValue(seed), Positive(parse.GetValue(cases), "--cases"))));

        var seeds = new Option<int>("--seeds") { Description = "Independent seeds per fault.", DefaultValueFactory = _ => 20, HelpName = "N" };
        var maxCases = new Option<int>("--max-cases") { Description = "Cap on generated cases per invariant.", DefaultValueFactory = _ => 20_000, HelpName = "N" };
        var outDir = new Option<string>("--out") { Description = "Directory for budget-samples.csv and budget-curve.csv.", HelpName = "DIR" };
        var fuzz = new Option<string>("--fuzz") { Description = "CSV of AFL++ time-to-first-crash per fault (docs/tradeoffs/fuzz-first-crash.csv).", HelpName = "FILE" };
        var budget = new Command("budget", "Detection probability of every known-bug catalogue entry against the budget (cases and seconds), pr and fresh seeds (docs/tradeoffs.md).") { seeds, maxCases, outDir, fuzz };
        budget.SetAction(parse => Guard.Run("tradeoffs budget", () => BudgetReport.Run(
            Positive(parse.GetValue(seeds), "--seeds"), Positive(parse.GetValue(maxCases), "--max-cases"), parse.GetValue(outDir), parse.GetValue(fuzz))));

        return new Command("tradeoffs", "Measure the speed / accuracy / budget trade-offs (docs/tradeoffs.md).") { numerics, accuracy, budget };
    }

    /// <summary>Validates a positive count.</summary>
    /// <param name="value">The value.</param>
    /// <param name="name">The option.</param>
    /// <returns>The value.</returns>
    /// <exception cref="UsageException">Not positive.</exception>
    public static int Positive(int value, string name) => value > 0 ? value : throw new UsageException($"{name} must be positive, got {value}");
}
