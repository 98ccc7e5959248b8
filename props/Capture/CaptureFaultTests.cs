using AcPhys.Contract;
using AcPhys.Spec.Faults;
using Xunit.Abstractions;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-FAULTS: a capture recorded from each planted outdoor fault, on a walk designed to exercise it, diverges; the
/// same walk recorded from the reference in the fault's declared mode does not (no false alarm). Faults a capture of
/// cells cannot show are listed with the reason, and the list is checked to be the rest of the outdoor model's faults.
/// </summary>
public sealed class CaptureFaultTests(ITestOutputHelper output)
{
    private const uint A9B40031 = 0xA9B40031; // (144-168, 0-24) of block A9B4: the seed's cell (facts §8)

    private static readonly (float, float, float, float)[] Player = [(0, 0, 0, 0.48f)];

    /// <summary>Gets each fault and the walk that exercises it.</summary>
    public static TheoryData<string> Shown => [.. Walks.Keys];

    /// <summary>The outdoor model's faults a capture of cells cannot show, and why.</summary>
    internal static IReadOnlyDictionary<string, string> NotShown { get; } = new Dictionary<string, string>
    {
        ["nan-as-zero"] = "needs a NaN coordinate: a capture's coordinates are finite (NaN is refused, exit 2)",
        ["checked-cast"] = "throws only on NaN, infinities or coordinates far off the map, which a capture refuses or does not judge",
        ["map-edge-2040"] = "shows only within a cell of the map's east or north edge, where frames are not judged (MAP-EDGE's business)",
        ["inbound-x-only"] = "inbound_valid_cellid differs only for block y 0xFF, off the map: no capture frame is there",
        ["blockid-zero-ok"] = "a LandDefs answer for id 0; find_cell never asks it from a land position",
        ["no-sphere-no-cell"] = "needs a query with no spheres; a capture's body always has sphere 0",
        ["no-sphere-origin-ignored"] = "needs a query with no spheres; a capture's body always has sphere 0",
        ["env-position-contains"] = "an env-cell position on open land: an indoor frame, not judged outdoors",
    };

    private static Dictionary<string, CaptureWriter.Plan> Walks { get; } = new()
    {
        // South across the A9B4/A9B3 line at x = 150 (the seed's geometry), then on into A9B3.
        ["clamp-106"] = South(),
        ["trunc-floor"] = South(1.95f), // the crossing frame at y = -0.05, well outside the EPS snap band
        ["drop-block-length"] = South(1.95f),
        ["sign-extend-by"] = South(), // block y 0xB4 ≥ 0x80 is negative as a signed byte
        ["no-reset"] = new(A9B40031, 150, 12, 1.5f, 0, 20, Player), // east through several cells: the array keeps old cells
        ["in-cell-neighbours"] = new(A9B40031, 150, 1.0f, 0, -0.1f, 8, Player), // north of the line, the sphere reaching over it
        ["sphere-guard-inverted"] = new(A9B40031, 150, 1.0f, 0, -0.1f, 8, Player),
        ["else-diagonal"] = new(A9B40031, 156, 12, 0.5f, 0, 8, [(0, 0, 0, 13f)]), // r > 12: both x sides must be added
        // Sphere 0 a metre south of the position: the frame it crosses the block line is asked from A9B4, sphere 0 in A9B3.
        ["sphere-leak"] = new(A9B40031, 150, 1.25f, 0, -0.1f, 8, [(0, -1, 0, 0.48f), (0, 0, 0, 0.48f)]),

        // 0.1 mm south of the block line, asked from A9B4, printed to 7 decimals: inside the EPS snap band (facts §2.1, §6.4).
        ["no-eps-snap"] = new(A9B40031, 150, 0.00015f, 0, -0.00025f, 3, Player, 7),

        // Exactly onto the cell line y = 24 inside the block (float32 exact, printed to 9 decimals): the pick's ties.
        ["no-hysteresis"] = OntoLine(),
        ["sticky-pick"] = OntoLine(),
        ["first-hit-outdoor-pick"] = OntoLine(),

        // Exactly touching: the sphere's south edge on y = 24 (pt_y = r = 0.5), strict in retail (facts §3.2).
        ["touch-inclusive"] = new(A9B40031 + 1, 150, 25.5f, 0, -0.25f, 5, [(0, 0, 0, 0.5f)], 9),
    };

    [Theory(DisplayName = "CAPTURE-FAULTS: a capture from the planted fault diverges on a walk that exercises it; the reference's capture of that walk does not")]
    [MemberData(nameof(Shown))]
    public void FaultCaptureDiverges(string id)
    {
        var plan = Walks[id];
        var port = PlantedFaults.Create(id);
        string capture = CaptureWriter.Native(port, plan);
        var faulty = CaptureRunner.Check(capture, port.Pick);
        var reference = CaptureRunner.Check(CaptureWriter.Native(new ReferenceAdapter(port.Pick), plan), port.Pick);
        output.WriteLine($"{id}: {faulty.Divergent} of {faulty.Judged} judged frames diverge, first at {faulty.FirstDivergence}, causes {string.Join(", ", faulty.Findings.Select(f => f.Cause))}; reference {reference.Divergent} of {reference.Judged}, not judged {reference.NotJudgedTotal}");
        Assert.True(faulty.Divergent > 0, $"{id}: the fault's capture was not found ({faulty.Judged} judged, {faulty.NotJudgedTotal} not judged):\n{capture}");
        Assert.Equal(0, reference.Divergent);
        Assert.True(reference.Judged > 0);
    }

    [Fact(DisplayName = "CAPTURE-FAULTS: every fault of the outdoor model is shown by a capture or listed with the reason it cannot be")]
    public void EveryOutdoorFaultIsAccountedFor()
    {
        var model = PlantedFaults.All.Where(f => f.Id != "none" && !f.Id.StartsWith("ace-", StringComparison.Ordinal) && IsOutdoorModel(f.Id)).Select(f => f.Id).ToHashSet();
        var accounted = Walks.Keys.Concat(NotShown.Keys).ToHashSet();
        Assert.Empty(model.Except(accounted));
        Assert.Empty(accounted.Except(model));
        Assert.Empty(Walks.Keys.Intersect(NotShown.Keys));
    }

    private static bool IsOutdoorModel(string id)
    {
        try
        {
            _ = PlantedFaults.Combine(id);
            return true;
        }
        catch (ArgumentException)
        {
            return false;
        }
    }

    private static CaptureWriter.Plan South(float y = 2) => new(A9B40031, 150, y, 0, -0.1f, 40, Player);

    private static CaptureWriter.Plan OntoLine() => new(A9B40031 + 1, 150, 25, 0, -0.5f, 5, Player, 9);
}
