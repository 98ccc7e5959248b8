namespace AcPhys.Spec.Capture;

/// <summary>Why a frame was not judged: a stable id (for counts and tests) and the sentence the report prints.</summary>
/// <param name="Id">The id, e.g. <c>indoor-no-dats</c>.</param>
/// <param name="Text">The sentence.</param>
internal sealed record NotJudgedReason(string Id, string Text)
{
    /// <summary>An env-cell frame without the user's dat files (the indoor judge needs the scene: <c>--cell-dat/--portal-dat</c>).</summary>
    public static readonly NotJudgedReason IndoorNoDats = new("indoor-no-dats", "indoor (an env cell), no dat files given (--cell-dat/--portal-dat)");

    /// <summary>Sphere 0's centre within the printed precision of a 24 m cell line: the containing cell depends on digits the log did not print.</summary>
    public static readonly NotJudgedReason NearCellLine = new("near-cell-line", "within the printed precision of a cell line (the containing cell depends on unprinted digits)");

    /// <summary>A sphere within the printed precision of a candidate boundary (|distance to a cell edge − r|): the candidate list depends on unprinted digits.</summary>
    public static readonly NotJudgedReason NearSphereEdge = new("near-sphere-edge", "within the printed precision of a candidate boundary (a sphere just touching a cell edge)");

    /// <summary>Sphere 0's centre off the map or within a cell of its edge (MAP-EDGE's business, not a walk's).</summary>
    public static readonly NotJudgedReason OffMap = new("off-map", "off the map or at its edge");

    /// <summary>The port reported neither a cell nor candidates the judge could compare (e.g. an acdream cellset frame without a radius).</summary>
    public static readonly NotJudgedReason NothingToJudge = new("nothing-to-judge", "nothing to compare (no cell after the frame, and no candidates or no radius)");

    /// <summary>A capture from an implementation re-asked with --impl / --impl-cmd that could not pose an indoor frame.</summary>
    public static readonly NotJudgedReason IndoorNotAsked = new("indoor-not-asked", "indoor, not re-asked of the implementation (no scene)");
}
