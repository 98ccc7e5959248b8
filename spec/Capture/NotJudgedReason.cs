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

    /// <summary>An indoor frame (or one by a building) without a body: which cells the transit closure reaches, so the pick, depends on the radius (facts §4 step 4a, §5.1).</summary>
    public static readonly NotJudgedReason IndoorNoBody = new("indoor-no-body", "indoor, no body named (# radius / # body / --radius): the cells the pick walks depend on the radius");

    /// <summary>The first frame of a capture is indoors: the query is asked from the port's previous cell, and there is none.</summary>
    public static readonly NotJudgedReason IndoorNoPrevious = new("indoor-no-previous-cell", "indoor, no previous cell to ask the query from (the capture's first frame)");

    /// <summary>The port's cell before or after the frame (or the landblock the query is asked in) is not in the user's dat files.</summary>
    public static readonly NotJudgedReason NotInDats = new("not-in-dats", "a cell or landblock of the frame is not in the dat files (--cell-dat)");

    /// <summary>A land cell the reference's answer depends on lies in a landblock the dat files do not hold (loaded in the game, unloaded in the scene).</summary>
    public static readonly NotJudgedReason BlockNotInDats = new("block-not-in-dats", "a land cell of the answer lies in a landblock the dat files do not hold");

    /// <summary>The record reader refused the landblock's scene (docs/dat-container.md, "Limits for a retail file").</summary>
    public static readonly NotJudgedReason SceneRefused = new("scene-refused", "the landblock's scene could not be read from the dat files (the record reader refused a record)");

    /// <summary>ace-keeps-stale-cells declared: the reference's array is the whole session's, not one frame's (facts §7 #6).</summary>
    public static readonly NotJudgedReason IndoorStaleCells = new("indoor-stale-cells", "indoor under ace-keeps-stale-cells: the answer depends on every earlier query of the session (facts §7 #6)");

    /// <summary>A sphere (or sphere 0's centre) within the printed precision of a portal plane's threshold (|d| against r + EPS, facts §5.1).</summary>
    public static readonly NotJudgedReason NearPortalPlane = new("near-portal-plane", "within the printed precision of a portal plane (|d| against r + EPS: the transit depends on unprinted digits)");

    /// <summary>A sphere (or sphere 0's centre) within the printed precision of a cell BSP face's threshold (d against ±(r + 0.01) or −EPS, facts §5.5, §5.7).</summary>
    public static readonly NotJudgedReason NearCellFace = new("near-cell-face", "within the printed precision of a cell's BSP face (d against ±(r + 0.01) or −EPS: containment depends on unprinted digits)");
}
