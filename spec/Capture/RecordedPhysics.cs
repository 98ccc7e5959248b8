using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Faults;

namespace AcPhys.Spec.Capture;

/// <summary>
/// A port as its capture recorded it (<c>acphys replay</c> of a walk file with <c>recorded</c> answers): the recorded walk
/// is answered with the port's recorded cells (and candidates, where recorded; else the reference's stand in, so only the
/// cell is judged), declared in the reference's mode; any other query is the reference's (nothing was recorded for it,
/// so it cannot fail). The ordinary walk invariants then judge the recorded answers.
/// </summary>
internal sealed class RecordedPhysics : ForwardingPhysics
{
    private readonly Walk walk;
    private readonly IReadOnlyList<RecordedAnswer> recorded;

    /// <summary>Initializes a new instance of the <see cref="RecordedPhysics"/> class.</summary>
    /// <param name="walk">The recorded walk.</param>
    /// <param name="recorded">One answer per query.</param>
    /// <param name="reference">The reference in the declared mode.</param>
    public RecordedPhysics(Walk walk, IReadOnlyList<RecordedAnswer> recorded, ICellPhysics reference)
        : base(reference)
    {
        if (recorded.Count != walk.Steps.Count + 1)
        {
            throw new ArgumentException($"{recorded.Count} recorded answers for a walk of {walk.Steps.Count + 1} queries", nameof(recorded));
        }

        this.walk = walk;
        this.recorded = recorded;
    }

    /// <inheritdoc/>
    public override string Name => "recorded answers";

    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest request)
    {
        if (!IsRecorded(request))
        {
            return Inner.FindCellWalk(request);
        }

        var answers = new List<FindCellResult>(request.Queries);
        var thread = new WalkThread(request);
        while (thread.MoveNext())
        {
            var r = recorded[thread.Index];
            var standIn = r.Cells is null ? thread.Ask(Inner) : null;
            answers.Add(new FindCellResult(r.Cells ?? standIn!.Cells, r.Cell) { Loaded = standIn?.Loaded });
            thread.Take(r.Cell);
        }

        return answers;
    }

    private bool IsRecorded(WalkRequest r) =>
        r.Scene is null && !r.LoadCells && r.Current.IsNone && r.StartCell == walk.StartCell && r.Start == walk.Start
        && r.Steps.SequenceEqual(walk.Steps) && r.Body.Count == walk.Body.Count
        && r.Body.Zip(walk.Body).All(p => p.First.Center == p.Second.Offset && p.First.Radius.Equals(p.Second.Radius));
}
