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
        ["cell-held-outside"] = "the port kept its land cell while the centre entered a building's cell (interior wins: facts §4 step 4b, §5.3)",
        ["cell-held-indoors"] = "the port kept its env cell while the centre left it through an exit portal (facts §5.1)",
        ["cell-held-portal"] = "the port kept its env cell while the centre crossed a portal into another env cell (facts §5.1, §5.5)",
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
                return (port.IsIndoorByLowWord, v.Reference.IsIndoorByLowWord) switch
                {
                    (false, true) => "cell-held-outside",
                    (true, false) => "cell-held-indoors",
                    (true, true) => "cell-held-portal",
                    _ => v.Reference.Landblock != port.Landblock ? "cell-held-across-block-line" : "cell-held",
                };
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
