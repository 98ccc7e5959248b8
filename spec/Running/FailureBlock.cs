using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Values;
using AcPhys.Spec.Corpus;

namespace AcPhys.Spec.Running;

/// <summary>
/// A failed invariant as <c>acphys verify</c> prints it — heading, statement, shrunk case, message, the declaration
/// that would make it intended, the original case, seed, replay line, case file and its replay line — built once, so
/// the gate as xunit tests (AcPhys.Xunit) fails with the same text the tool prints.
/// </summary>
/// <param name="Heading">The first line, <c>FAIL ID on NAME</c>.</param>
/// <param name="Fields">The indented field lines that follow it.</param>
/// <param name="ReplayLine">The verify line that replays the failure.</param>
/// <param name="Confirmed">Whether re-running the line reproduced the same shrunk case.</param>
/// <param name="CaseFile">The shrunk case written as a corpus file, if it could be.</param>
/// <param name="CaseReplay">The replay line of that file.</param>
public sealed record FailureBlock(string Heading, IReadOnlyList<string> Fields, string ReplayLine, bool Confirmed, string? CaseFile, string? CaseReplay)
{
    /// <summary>The longest field value printed (the failure file keeps the whole text).</summary>
    public const int MaxFieldChars = 2000;

    /// <summary>Gets the block as plain text, one line per row.</summary>
    public string Text => string.Join(Environment.NewLine, new[] { Heading }.Concat(Fields));

    /// <summary>Builds the block of one failed invariant, writing its shrunk case as a corpus file.</summary>
    /// <param name="r">The failed result.</param>
    /// <param name="impl">The implementation it failed on.</param>
    /// <param name="implName">The implementation's name as printed (escaped).</param>
    /// <param name="replay">How the failure is replayed.</param>
    /// <param name="failureFolder">Where the case file goes.</param>
    /// <param name="finder">Who found it (<see cref="FinderNames"/>).</param>
    /// <returns>The block.</returns>
    public static FailureBlock Of(InvariantResult r, ICellPhysics impl, string implName, ReplayCommand replay, string failureFolder, string finder)
    {
        var fields = new List<string> { Field("statement", r.Invariant.Statement) };
        bool swept = r.Replay is null && r.ExhaustiveCases > 0;
        if (r.Violation is { } v)
        {
            fields.Add(Field(swept ? "case" : "shrunk", v.CaseText));
            fields.Add(Field("message", v.Message));
            switch (Judging.IntendedUnder.Explain(impl, r.Invariant.Id, [.. new[] { v.Case, r.Original?.Case }.OfType<AnyCase>().Distinct()]))
            {
                case { Declaration: string declaration }:
                    fields.Add(Field("intended", $"your answers are the reference's if you declare {declaration} in hello (.NET: ICellPhysics Indoor/Outdoor/Pick), on this case, the original and {Judging.IntendedUnder.FreshCases} fresh cases of its class: a documented deviation (docs/conformance.md, \"Declared modes\")"));
                    break;
                case { Differs: string differs }:
                    fields.Add(Field("intended", "no: " + differs));
                    break;
            }
        }

        if (swept)
        {
            fields.Add(Field("found by", $"the exhaustive sweep ({r.ExhaustiveCases.ToString("N0", System.Globalization.CultureInfo.InvariantCulture)} cases): first violation in sweep order, not shrunk"));
        }
        else if (r.Original is { } o && o != r.Violation)
        {
            fields.Add(Field("original", o.CaseText));
            if (o.Message != r.Violation?.Message)
            {
                fields.Add(Field(string.Empty, o.Message));
            }
        }

        var (line, confirmed) = replay.For(r, impl);
        fields.Add(Field("seed", r.Seed.ToString()));
        fields.Add(Field("replay", line));
        string? caseFile = null, caseReplay = null;
        if (r.Violation is { } shrunk)
        {
            try
            {
                caseFile = FailureFile.Write(shrunk, failureFolder, finder, r.Seed.ToString(), replay.Mode);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // A folder that cannot take the case file (a read-only checkout) loses the file, not the verdict.
                fields.Add(Field("case file", "not written: " + e.Message));
            }

            if (caseFile is not null)
            {
                caseReplay = replay.ReplayFile(caseFile);
                fields.Add(Field("case file", caseFile));
                fields.Add(Field("replay", caseReplay));
            }
        }

        if (!confirmed)
        {
            fields.Add(Field(string.Empty, "(note: re-running this line did not reproduce the same shrunk case)"));
        }

        return new FailureBlock($"FAIL {r.Invariant.Id} on {implName}", fields, line, confirmed, caseFile, caseReplay);
    }

    // An implementation's text is escaped where it enters; the line is also cut (the failure file keeps the whole text).
    private static string Field(string name, string value) =>
        $"  {name,-10} {InputQuote.Brief(InputQuote.Escape(value, keepLines: true), MaxFieldChars)}";
}
