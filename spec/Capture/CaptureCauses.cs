namespace AcPhys.Spec.Capture;

/// <summary>
/// The root-cause key of a divergent frame, so that spans of one bug are one finding (as verify groups failures by
/// class): which part of the answer differs, and how.
/// </summary>
internal static class CaptureCauses
{
    /// <summary>Gets the sentence for each key, for the report.</summary>
    public static IReadOnlyDictionary<string, string> Text { get; } = new Dictionary<string, string>(StringComparer.Ordinal)
    {
        ["cell-held-across-block-line"] = "the port kept its cell while the centre crossed a landblock line (the #106 freeze class, facts §6.1)",
        ["cell-held"] = "the port kept its cell while the centre crossed a cell line (facts §4)",
        ["cell-other"] = "the port moved to another cell than the reference's (facts §4)",
        ["cell-none"] = "the port reported no cell where the reference has one (facts §4)",
        ["candidates-missing"] = "candidates missing from the port's list (facts §3.2, §3.3)",
        ["candidates-extra"] = "candidates the reference does not add (facts §3.2, §3.3)",
        ["candidates-content"] = "other candidates than the reference's (facts §3.2, §3.3)",
        ["candidates-order"] = "the reference's candidates in another order (insertion order, facts §3.3)",
    };

    /// <summary>Returns the key of a divergent frame.</summary>
    /// <param name="q">The frame.</param>
    /// <param name="v">Its divergent verdict.</param>
    /// <returns>The key.</returns>
    public static string Of(in CaptureQuery q, in FrameVerdict v)
    {
        if (v.Divergence == DivergenceKind.Cell)
        {
            var port = q.Frame.Cell;
            if (port == q.Before && !port.IsNone)
            {
                return v.Reference.Landblock != port.Landblock ? "cell-held-across-block-line" : "cell-held";
            }

            return port.IsNone ? "cell-none" : "cell-other";
        }

        if (v.Divergence == DivergenceKind.CandidateOrder)
        {
            return "candidates-order";
        }

        var want = v.ReferenceCells ?? [];
        var got = q.Frame.Candidates.ToArray();
        bool allGotInWant = got.All(want.Contains);
        bool allWantInGot = want.All(got.Contains);
        return allGotInWant ? "candidates-missing" : allWantInGot ? "candidates-extra" : "candidates-content";
    }
}
