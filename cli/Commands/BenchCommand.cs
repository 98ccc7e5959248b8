using System.CommandLine;
using System.Globalization;
using AcPhys.Cli.Bench;
using AcPhys.Cli.Tradeoffs;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>bench</c> verb: a short in-process benchmark of the hot paths, float32 vs double, as a table of ns/op and B/op.</summary>
internal static class BenchCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var roundMs = new Option<int>("--round-ms") { Description = "Length of one timed round per operation, ms.", DefaultValueFactory = _ => 100, HelpName = "MS" };
        var rounds = new Option<int>("--rounds") { Description = "Timed rounds per operation (the median is reported).", DefaultValueFactory = _ => 7, HelpName = "N" };
        var filter = new Option<string>("--filter") { Description = "Only operations whose group, name or mode contains this text.", HelpName = "TEXT" };
        var command = new Command("bench", "Time the hot paths in-process (ns/op, B/op; float32 vs double mode); exit 1 if a hot path allocates. BenchmarkDotNet: bench/.")
        {
            roundMs, rounds, filter,
        };
        command.SetAction(parse => Guard.Run("bench", () => Run(
            TradeoffsCommand.Positive(parse.GetValue(roundMs), "--round-ms"),
            TradeoffsCommand.Positive(parse.GetValue(rounds), "--rounds"),
            parse.GetValue(filter))));
        return command;
    }

    private static int Run(int roundMs, int rounds, string? filter)
    {
        var ops = BenchOps.All.Where(o => filter is null
            || $"{o.Group} {o.Name} {o.Mode}".Contains(filter, StringComparison.OrdinalIgnoreCase)).ToList();
        if (ops.Count == 0)
        {
            throw new UsageException($"--filter '{filter}' matches no operation");
        }

        Terminal.Line($"<!-- acphys bench --round-ms {roundMs} --rounds {rounds}; {Machine.Describe()} at start; .NET {Environment.Version} -->");
        var rows = new List<BenchRow>();
        ProgressBars.Run("bench", ops.Count, advance =>
        {
            foreach (var op in ops)
            {
                rows.Add(MicroBench.Measure(op, roundMs, rounds));
                advance($"{op.Group} / {op.Name} / {op.Mode}");
            }
        });

        Markdown.Table(
            ["group", "op", "mode", "ns/op (median)", "ns/op (min)", "B/op"],
            rows.Select(r => (IReadOnlyList<string>)
            [
                r.Op.Group, r.Op.Name, r.Op.Mode, Ns(r.NsPerOp), Ns(r.MinNsPerOp), r.BytesPerOp.ToString("0.##", CultureInfo.InvariantCulture),
            ]));
        Terminal.Line($"<!-- {Machine.Describe()} at end -->");
        var allocating = rows.Where(r => r.Op.Hot && r.BytesPerOp > 0).ToList();
        foreach (var r in allocating)
        {
            Terminal.Error("bench", $"hot path allocates: {r.Op.Group} / {r.Op.Name} / {r.Op.Mode}: {r.BytesPerOp:0.##} B/op");
        }

        return allocating.Count == 0 ? ExitCodes.Ok : ExitCodes.Violated;
    }

    private static string Ns(double ns) => ns.ToString(ns < 10 ? "0.00" : "0.0", CultureInfo.InvariantCulture);
}
