using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Pipeline;

namespace AcPhys.Protocol.Client;

/// <summary>
/// An implementation in another process, in any language, behind <see cref="ICellPhysics"/>: protocol v1 over the
/// child's stdin/stdout (docs/protocol.md). A crash, a hang past the timeout or an answer that is not protocol v1 is an
/// <see cref="AdapterFailureException"/> (exit 2); <c>{"error": ...}</c> to an announced op is a finding.
/// </summary>
/// <remarks>Calls are serialised (one request in flight), so the adapter is safe to share between threads.</remarks>
public sealed partial class ProcessAdapter : ICellPhysics, ITransport, IDisposable
{
    private readonly LineProcess child;
    private readonly TimeSpan timeout;
    private const int KeptScenes = 8;
    private readonly Lock gate = new();
    private readonly List<(Scene Scene, string Id)> loaded = [];
    private readonly Lazy<ICellPhysics> guesser;
    private readonly ReportedFields[] reported = [new(), new()]; // [0] open land, [1] scenes
    private PipelineSession? session;
    private readonly ReaderThread reader = new("acphys pipeline reader");
    private int chosenIds;
    private bool probing;
    private readonly List<string> differences = [];

    private ProcessAdapter(LineProcess child, TimeSpan timeout, string name, Op ops, Capability capabilities, PickPolicy pick, IReadOnlyList<string> unknownOps)
    {
        this.child = child;
        this.timeout = timeout;
        Name = name;
        Ops = ops;
        Capabilities = capabilities;
        Pick = pick;
        UnknownOps = unknownOps;
        guesser = new(() => new ReferenceAdapter(Pick, outdoor: Outdoor) { Indoor = Indoor });
    }

    /// <inheritdoc/>
    public string Name { get; }

    /// <inheritdoc/>
    public Op Ops { get; }

    /// <summary>Gets what the handshake negotiated beside the operations: how scenes and walks travel, whether requests stream.</summary>
    public Capability Capabilities { get; }

    /// <inheritdoc/>
    public PickPolicy Pick { get; }

    /// <inheritdoc/>
    public IndoorFidelity Indoor { get; private init; }

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor { get; private init; }

    /// <summary>Gets a value indicating whether the implementation declared <c>"frame": "world"</c>: points travel in world coordinates (<see cref="WorldFrame"/>).</summary>
    public bool InWorldFrame { get; private init; }

    /// <summary>Gets names the implementation announced in <c>ops</c> that protocol v1 knows neither as an operation nor as a capability (ignored).</summary>
    public IReadOnlyList<string> UnknownOps { get; }

    /// <summary>Gets a value indicating whether the implementation announced <c>pipeline</c>: <see cref="Pipelined{T}"/> then speculates and streams.</summary>
    /// <remarks>A world-frame child too: a point it cannot be sent (UnposableQueryException) is refused before the
    /// pipeline counts the query (<see cref="RefuseUnposable"/>), in every pass alike.</remarks>
    public bool Pipelines => (Capabilities & Capability.Pipeline) != 0;

    /// <summary>Gets how many runs went through <see cref="Pipelined{T}"/> with the pipeline, and how many of them had to be replayed (an answer differed from its guess).</summary>
    public (int Runs, int Replays) PipelineCounts { get; private set; }

    /// <summary>Gets, for the first few replayed runs, the answer that differed from its guess (why the run was replayed).</summary>
    public IReadOnlyList<string> PipelineDifferences => differences;

    /// <summary>Gets the last lines the implementation wrote to stderr.</summary>
    public IReadOnlyList<string> StderrTail => child.StderrTail;

    /// <inheritdoc/>
    IReadOnlyList<string> ITransport.Negotiated => CapabilityNames.Names(Capabilities);

    /// <inheritdoc/>
    bool ITransport.ScenesAsRecords => (Capabilities & Capability.DatRecords) != 0;

    /// <inheritdoc/>
    bool ITransport.Streams => Pipelines;

    /// <inheritdoc/>
    T ITransport.Streamed<T>(Func<T> run) => Pipelined(run);

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(MessageTable.BlockIdToLcoord, id, out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(MessageTable.GidToLcoord, id, out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => Ask(MessageTable.LcoordToGid, (x, y));

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => Ask(MessageTable.InboundValidCellId, id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => LcoordAnswer(MessageTable.GetOutsideLcoord, (id, x, y), out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y) => Ask(MessageTable.AdjustToOutside, (id, x, y));

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, System.Numerics.Vector3.Zero, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) => Ask(MessageTable.OutsideCells, (cell, origin, spheres));

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, System.Numerics.Vector3.Zero, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
        Call(Op.FindCell, "find_cell", Answers.FindCell, w =>
        {
            FindCellFields(w, null, cell, spheres, current);
            Wire.WriteOrigin(w, origin, spheres);
        }, a => Learn(Answers.FindCell.Read(a), false), r => Project(r.FindCell(cell, origin, spheres, current), false));

    /// <summary>
    /// <c>find_cell</c> with a scene: the scene travels as its compact JSON (docs/protocol.md, "Scenes") and is
    /// served only by an implementation that announced <c>find_cell_scene</c>; a null scene is open land.
    /// </summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <returns>The candidates and the containing cell.</returns>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) =>
        scene is null
            ? FindCell(cell, spheres, current)
            : Call(Op.FindCellScene, "find_cell", Answers.FindCell, w => FindCellFields(w, scene, cell, spheres, current), a => Learn(Answers.FindCell.Read(a), true), r => Project(r.FindCell(scene, cell, spheres, current), true));

    /// <summary><c>find_cell</c> with <c>"load_cells": true</c> (a movement transition, no visibility filter), for an implementation that announced <c>find_cell_transition</c>.</summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <param name="loadCells">True for a transition query.</param>
    /// <returns>The candidates and the containing cell.</returns>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        !loadCells
            ? FindCell(scene, cell, spheres, current)
            : Call(Op.FindCellTransition, "find_cell", Answers.FindCell, w =>
            {
                FindCellFields(w, scene, cell, spheres, current);
                w.WriteBoolean("load_cells", true);
            }, a => Learn(Answers.FindCell.Read(a), scene is not null), r => Project(r.FindCell(scene, cell, spheres, current, true), scene is not null));

    /// <summary>
    /// <c>find_cell_walk</c>: the whole walk in one round trip when the implementation announced it (docs/protocol.md,
    /// "Whole walks"); otherwise, or for a walk longer than <see cref="WalkWire.MaxSteps"/>, query by query as before.
    /// </summary>
    /// <param name="walk">The walk.</param>
    /// <returns>One answer per query.</returns>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk)
    {
        if ((Capabilities & Capability.FindCellWalk) == 0 || walk.Steps.Count > WalkWire.MaxSteps || InWorldFrame) // a world-frame port is asked query by query
        {
            return WalkThread.AskEach(this, walk);
        }

        // The op a step-by-step walk would need: a missing one is NotSupportedException, as it is there.
        var needs = walk.LoadCells ? Op.FindCellTransition : walk.Scene is null ? Op.FindCell : Op.FindCellScene;
        var shape = Answers.Walk(walk.Queries);
        return Call(
            needs,
            "find_cell_walk",
            shape,
            w =>
            {
                SceneField(w, walk.Scene);
                WalkWire.WriteFields(w, walk);
            },
            a => LearnAll(shape.Read(a), walk.Scene is not null),
            r => ProjectAll(r.FindCellWalk(walk), walk.Scene is not null) is var g && g.Count == walk.Queries
                ? g
                : throw new InvalidOperationException("the reference answered the walk with another number of queries")); // no guess: asked and read as the child answers
    }

    /// <inheritdoc/>
    /// <exception cref="UnposableQueryException">A part protocol v1 cannot carry (more than a block from the first part, or out of the wire's bounds): the case is not judged, as a correct child must refuse it (PartBounds).</exception>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts)
    {
        ArgumentNullException.ThrowIfNull(parts);

        // Refused before it is asked or counted (as RefuseUnposable): a pipelined pass must not pair answers with it.
        for (int i = 0; i < parts.Count; i++)
        {
            if (PartBounds.Problem(parts[i], parts[0]) is var (field, problem))
            {
                throw new UnposableQueryException($"parts[{i}].{field}: {problem}: protocol v1 cannot carry this query (docs/protocol.md); case not judged");
            }
        }

        return Ask(MessageTable.OutsideCellsParts, parts);
    }

    /// <summary>
    /// <c>find_cell_parts_scene</c> or <c>find_cell_parts_transition</c>: the scene as <c>find_cell</c> sends it, the
    /// parts as <c>outside_cells_parts</c> does (docs/protocol.md, "Parts indoors").
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="parts">The parts; the first is the anchor.</param>
    /// <param name="loadCells">True for the transition kind.</param>
    /// <returns>The cells, their loaded flags and HitsInteriorCell as reported; no containing cell.</returns>
    /// <exception cref="UnposableQueryException">A part protocol v1 cannot carry (as <see cref="OutsideCellsParts"/>).</exception>
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(parts);
        for (int i = 0; i < parts.Count; i++)
        {
            if (PartBounds.Problem(parts[i], parts[0]) is var (field, problem))
            {
                throw new UnposableQueryException($"parts[{i}].{field}: {problem}: protocol v1 cannot carry this query (docs/protocol.md); case not judged");
            }
        }

        var row = loadCells ? MessageTable.FindCellPartsTransition : MessageTable.FindCellPartsScene;
        var query = new PartsInScene(scene, parts);
        return Call(
            row.Op,
            row.Name,
            row.Answer,
            w =>
            {
                SceneField(w, scene);
                row.WriteRequest(w, query);
            },
            a => Learn(row.Answer.Read(a), true),
            r => Project(row.Ask(r, query), true));
    }

    /// <summary>
    /// <c>find_cell_parts_walk</c>: one walk's parts queries of one kind in one round trip when the implementation announced
    /// it (docs/protocol.md, "Whole parts walks"); otherwise, or for more than <see cref="WalkWire.MaxSteps"/> queries or
    /// in the world frame, query by query through <see cref="FindCellParts"/>.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="queries">The parts queries, in order.</param>
    /// <param name="loadCells">True for the transition kind.</param>
    /// <returns>One answer per query.</returns>
    /// <exception cref="UnposableQueryException">A part protocol v1 cannot carry (as <see cref="OutsideCellsParts"/>).</exception>
    public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(queries);
        if ((Capabilities & Capability.FindCellPartsWalk) == 0 || queries.Count > WalkWire.MaxSteps || InWorldFrame)
        {
            return [.. queries.Select(q => FindCellParts(scene, q, loadCells))];
        }

        foreach (var parts in queries)
        {
            for (int i = 0; i < parts.Count; i++)
            {
                if (PartBounds.Problem(parts[i], parts[0]) is var (field, problem))
                {
                    throw new UnposableQueryException($"parts[{i}].{field}: {problem}: protocol v1 cannot carry this query (docs/protocol.md); case not judged");
                }
            }
        }

        var row = loadCells ? MessageTable.FindCellPartsTransition : MessageTable.FindCellPartsScene;
        var shape = Answers.Walk(queries.Count);
        return Call(
            row.Op,
            "find_cell_parts_walk",
            shape,
            w =>
            {
                SceneField(w, scene);
                PartsWalkWire.WriteFields(w, queries, loadCells);
            },
            a => LearnAll(shape.Read(a), true),
            r => ProjectAll(r.FindCellPartsWalk(scene, queries, loadCells), true));
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        child.Dispose();
        reader.Dispose();
    }
}
