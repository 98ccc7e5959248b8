using System.Globalization;
using System.Text;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Verify;
using AcPhys.Contract;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Invariants;
using Spectre.Console;

namespace AcPhys.Cli.Diff;

/// <summary>
/// Prints and writes what <c>acphys diff</c> found: per check, every divergence class with its count and its
/// minimal input side by side on both implementations; a replayable case file and a <c>.diff.md</c> per class; and
/// <c>summary.md</c>, every class of every check in one table.
/// </summary>
/// <param name="impl">The implementation.</param>
/// <param name="reference">The reference.</param>
/// <param name="choice">How the implementation was chosen (its words go into replay lines).</param>
/// <param name="cases">Inputs per check (goes into replay lines).</param>
/// <param name="folder">Where files go.</param>
internal sealed class DiffReport(ICellPhysics impl, ICellPhysics reference, ImplementationChoice choice, int cases, string folder)
{
    /// <summary>Gets the overview table: one row per check.</summary>
    /// <param name="results">The results.</param>
    /// <returns>The table.</returns>
    public static Table Overview(IEnumerable<DiffResult> results)
    {
        var table = new Table().AddColumn("Check").AddColumn(new TableColumn("Inputs").RightAligned()).AddColumn(new TableColumn("Differ").RightAligned())
            .AddColumn(new TableColumn("Classes").RightAligned()).AddColumn("Verdict").AddColumn(new TableColumn("Time").RightAligned());
        foreach (var r in results)
        {
            if (r.NotComparedReason is string why)
            {
                table.AddRow(r.Check.Id, "-", "-", "-", Markup.Escape($"not compared ({why})"), Fmt.Seconds(r.Elapsed));
                continue;
            }

            table.AddRow(r.Check.Id, Fmt.Count(r.Cases), Fmt.Count(r.Divergent), Fmt.Count(r.Classes.Count), r.Differs ? "[red]DIFFERS[/]" : "same", Fmt.Seconds(r.Elapsed));
        }

        return table;
    }

    /// <summary>Prints one diverging check's classes and writes their files.</summary>
    /// <param name="r">The result.</param>
    /// <returns>One summary row per class: (check, class number, class, input class, count, case file).</returns>
    public IReadOnlyList<(string Check, int N, DivergenceClass Class, string? CaseFile)> Write(DiffResult r)
    {
        string replay = ReplayLineFor(r);
        Terminal.Line();
        Terminal.Out.MarkupLine($"[red bold]DIFFERS[/] [bold]{Markup.Escape(r.Check.Id)}[/]: {Markup.Escape($"{Fmt.Count(r.Divergent)} of {Fmt.Count(r.Cases)} inputs differ ({Fmt.Percent(r.Divergent, r.Cases)}) in {r.Classes.Count} class{(r.Classes.Count == 1 ? string.Empty : "es")}; {impl.Name} vs {reference.Name}")}");
        var rows = new List<(string, int, DivergenceClass, string?)>();
        int n = 0;
        foreach (var c in r.Classes)
        {
            n++;
            Terminal.Line($"  D{n}  {Fmt.Count(c.Count)} input{(c.Count == 1 ? string.Empty : "s")}  {c.What}");
            Terminal.Line($"      inputs  {Spread(c)}");
            Terminal.Line($"      {(c.Shrunk ? "shrunk" : "first ")}  {Brief(CaseText(c.Example))}");
            Terminal.Line($"      answers {Brief(c.Message)}");
            var side = SideBySide.Rows(c.Example, impl, reference);
            if (c.Shrunk && side.Count <= 12)
            {
                var table = new Table().AddColumn("Query").AddColumn(impl.Name).AddColumn(reference.Name).AddColumn(string.Empty);
                foreach (var (query, mine, theirs) in side)
                {
                    table.AddRow(new Text(query), new Text(mine), new Text(theirs), new Markup(mine == theirs ? string.Empty : "[red]differs[/]"));
                }

                Terminal.Out.Write(table);
            }

            string? caseFile = WriteFiles(r, n, c, side, replay);
            rows.Add((r.Check.Id, n, c, caseFile));
        }

        Terminal.Line($"  seed    {r.Seed}");
        Terminal.Line($"  replay  {replay}");
        return rows;
    }

    /// <summary>Writes <c>summary.md</c>: every class of every check with its count.</summary>
    /// <param name="results">The results.</param>
    /// <param name="rows">The class rows <see cref="Write"/> returned.</param>
    /// <returns>The path written.</returns>
    public string WriteSummary(IReadOnlyList<DiffResult> results, IEnumerable<(string Check, int N, DivergenceClass Class, string? CaseFile)> rows)
    {
        var md = new StringBuilder();
        md.Append($"# acphys diff: {impl.Name} vs {reference.Name}\n\n");
        md.Append("| check | inputs | differ | classes | seed |\n|---|---:|---:|---:|---|\n");
        foreach (var r in results)
        {
            md.Append(r.NotComparedReason is string why
                ? $"| `{r.Check.Id}` | - | - | - | not compared: {why} |\n"
                : $"| `{r.Check.Id}` | {r.Cases} | {r.Divergent} | {r.Classes.Count} | `{r.Seed}` |\n");
        }

        md.Append("\n## Divergence classes\n\n| check | # | inputs | what differs | input classes | minimal case |\n|---|---:|---:|---|---|---|\n");
        foreach (var (check, n, c, file) in rows)
        {
            md.Append($"| `{check}` | D{n} | {c.Count} | {Cell(c.What)} | {Cell(Spread(c))} | {(file is null ? Cell(CaseText(c.Example)) : $"`{Path.GetFileName(file)}`")} |\n");
        }

        string path = Path.Combine(folder, "summary.md");
        AtomicFile.WriteAllText(path, md.ToString());
        return path;
    }

    private string? WriteFiles(DiffResult r, int n, DivergenceClass c, IReadOnlyList<(string Query, string Implementation, string Reference)> side, string replay)
    {
        var violation = new Violation(r.Check.Id, $"D{n} {c.What}: {c.Message}", CaseText(c.Example)) { Case = AcPhys.Formats.Cases.AnyCase.Of(c.Example) };
        string? caseFile = FailureFile.Write(violation, folder, FinderNames.Diff, r.Seed.ToString());
        string name = caseFile is null ? $"{r.Check.Id}-D{n}" : Path.GetFileNameWithoutExtension(caseFile);
        string sideFile = Path.Combine(folder, name + ".diff.md");
        var md = new StringBuilder();
        md.Append($"# {r.Check.Id} D{n}: {impl.Name} vs {reference.Name}\n\n{r.Check.Statement}\n\n");
        md.Append($"Class: {c.What}; {c.Count} of {r.Cases} inputs ({Spread(c)}).\n\n");
        md.Append($"{(c.Shrunk ? "Shrunk" : "First")} input: `{CaseText(c.Example)}`\n\nAnswers: {c.Message}\n\n");
        md.Append(SideBySide.Markdown(side, impl.Name));
        md.Append($"\nSeed `{r.Seed}`; replay the check (every class, same counts): `{replay}`\n\n");
        if (caseFile is not null)
        {
            string words = choice.Words().Count > 0 ? " " + string.Join(' ', choice.Words().Select(ReplayLine.Quote)) : string.Empty;
            md.Append($"Replay this input against either side: `{ReplayLine.Program} replay {caseFile}{words}`\n");
            Terminal.Line($"      case file  {caseFile}");
        }

        AtomicFile.WriteAllText(sideFile, md.ToString());
        Terminal.Line($"      side by side {sideFile}");
        return caseFile;
    }

    private string ReplayLineFor(DiffResult r)
    {
        var words = new List<string> { ReplayLine.Program, "diff", "--only", r.Check.Id, "--cases", cases.ToString(CultureInfo.InvariantCulture), "--seed", r.Seed.ToString() };
        words.AddRange(choice.Words());
        return string.Join(' ', words.Select(ReplayLine.Quote));
    }

    // The input classes the class was met on, most first: one root cause on many kinds of input.
    private static string Spread(DivergenceClass c) =>
        string.Join(", ", c.Inputs.Take(4).Select(i => $"{i.Input} {i.Count}")) + (c.Inputs.Count > 4 ? $", {c.Inputs.Count - 4} more" : string.Empty);

    private static string CaseText(object example) => example.ToString() ?? string.Empty;

    private static string Cell(string text) => text.ReplaceLineEndings(" ").Replace("|", "\\|", StringComparison.Ordinal);

    private static string Brief(string text)
    {
        string one = text.ReplaceLineEndings(" ");
        return one.Length <= 240 ? one : one[..239] + "…";
    }
}
