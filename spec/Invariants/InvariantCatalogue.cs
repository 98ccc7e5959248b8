using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Judging;

namespace AcPhys.Spec.Invariants;

/// <summary>The complete list of invariants: the only thing runners enumerate.</summary>
public static class InvariantCatalogue
{
    /// <summary>Gets every invariant, in catalogue order.</summary>
    public static IReadOnlyList<Invariant> All { get; } = [.. LandInvariants.All, .. OutdoorInvariants.All, .. WalkInvariants.All, .. PartsInvariants.All, .. IndoorInvariants.All, .. IndoorExactInvariants.All, .. IndoorTieInvariants.All, .. PartsIndoorInvariants.All, .. ConformanceInvariants.All];

    /// <summary>Gets the scene invariants (over <see cref="SceneWalk"/>), conformance aside.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> SceneInvariants { get; } = [.. IndoorInvariants.All, .. IndoorExactInvariants.All, .. IndoorTieInvariants.All, .. PartsIndoorInvariants.All];

    /// <summary>Gets the invariants over <see cref="LandCase"/>.</summary>
    public static IReadOnlyList<Invariant<LandCase>> Land => LandInvariants.All;

    /// <summary>Finds an invariant by ID (case-insensitive).</summary>
    /// <param name="id">The ID.</param>
    /// <returns>The invariant, or null.</returns>
    public static Invariant? Find(string id) => All.FirstOrDefault(i => string.Equals(i.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>Checks one case against every testable LandDefs invariant, conformance included (<see cref="Judges"/>).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The first violation in judge order, or null when all hold.</returns>
    public static Violation? CheckLandCase(ICellPhysics impl, LandCase c) => Judges.First(impl, c);

    /// <summary>
    /// Checks a walk: every testable walk invariant on the walk, then every testable outdoor invariant on the query
    /// of each step (as the reference answers them, so the queries are the ones a correct client would ask), then
    /// FIND-CELL-CONFORMANCE (<see cref="Judges"/>).
    /// </summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckWalk(ICellPhysics impl, Walk walk) => Judges.First(impl, walk);

    /// <summary>Checks a corpus entry of any kind (<see cref="Judges"/>).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="entry">The entry.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckEntry(ICellPhysics impl, CorpusEntry entry) => Judges.First(impl, entry.Item);

    /// <summary>Checks a parts query against every testable parts invariant (PARTS-COVERAGE, PARTS-SOUNDNESS).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The query.</param>
    /// <returns>The first violation in catalogue order, or null.</returns>
    public static Violation? CheckParts(ICellPhysics impl, PartsCase c) => Judges.First(impl, c);

    /// <summary>Checks a scene walk against every testable scene invariant, then FIND-CELL-CONFORMANCE (<see cref="Judges"/>).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="sw">The scene walk.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckSceneWalk(ICellPhysics impl, SceneWalk sw) => Judges.First(impl, sw);
}
