using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>
/// The rule a walk is threaded by, as a client threads it (the contract of <c>find_cell_walk</c>, docs/protocol.md):
/// query i (i = 0 the start) is asked from the frame cell with the position and the body's spheres at it; after an
/// answer whose containing cell is not none, the position is re-framed into that cell's block (GetBlockOffset,
/// float32 subtraction) and the cell becomes the frame and the current cell; with none, both are kept (a freeze).
/// </summary>
/// <remarks>
/// The tool's walk runners and <see cref="ICellPhysics.FindCellWalk"/>'s default both step through this one type, so a
/// walk answered whole and a walk asked query by query are the same queries by construction.
/// </remarks>
public sealed class WalkThread
{
    private readonly WalkRequest walk;
    private int index = -1;
    private bool answered = true;

    /// <summary>Initializes a new instance of the <see cref="WalkThread"/> class, before the start query.</summary>
    /// <param name="walk">The walk.</param>
    public WalkThread(WalkRequest walk)
    {
        this.walk = walk;
        Frame = walk.StartCell;
        Position = walk.Start;
        Current = walk.Current;
    }

    /// <summary>Gets the query's index: 0 for the start, then 1..n.</summary>
    public int Index => index;

    /// <summary>Gets the cell whose block frame <see cref="Position"/> is in: the cell the query is asked from.</summary>
    public CellId Frame { get; private set; }

    /// <summary>Gets the position in <see cref="Frame"/>'s block frame.</summary>
    public Vector3 Position { get; private set; }

    /// <summary>Gets the current cell the query passes (after <see cref="Take"/>: the current cell after the step).</summary>
    public CellId Current { get; private set; }

    /// <summary>Moves to the next query: the start first, then each step's move added to the position (float32).</summary>
    /// <returns>False when every query has been made.</returns>
    /// <exception cref="InvalidOperationException">The previous query was not answered (<see cref="Take"/>).</exception>
    public bool MoveNext()
    {
        if (!answered)
        {
            throw new InvalidOperationException("walk query " + index + " was not answered");
        }

        if (index + 1 >= walk.Queries)
        {
            return false;
        }

        index++;
        if (index > 0)
        {
            var d = walk.Steps[index - 1];
            Position += new Vector3(d.X, d.Y, 0); // z + 0 as well: -0 becomes +0, as the client's own add does
        }

        answered = false;
        return true;
    }

    /// <summary>Returns the body's spheres at <see cref="Position"/> (centres position + offset, float32), in <see cref="Frame"/>'s block frame.</summary>
    /// <returns>The spheres of this query.</returns>
    public Sphere[] Spheres()
    {
        var spheres = new Sphere[walk.Body.Count];
        for (int i = 0; i < spheres.Length; i++)
        {
            spheres[i] = new Sphere(Position + walk.Body[i].Center, walk.Body[i].Radius);
        }

        return spheres;
    }

    /// <summary>Takes the query's answer: a containing cell re-frames the position and becomes frame and current cell.</summary>
    /// <param name="containing">The containing cell answered (<see cref="CellId.None"/>: none, the client keeps its cell and frame).</param>
    public void Take(CellId containing)
    {
        answered = true;
        if (!containing.IsNone)
        {
            Position -= LandDefs.GetBlockOffset(Frame, containing);
            Frame = containing;
            Current = containing;
        }
    }

    /// <summary>Asks one query of the walk through the single-query operations (what <see cref="ICellPhysics.FindCellWalk"/> does by default).</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The answer.</returns>
    public FindCellResult Ask(ICellPhysics impl) =>
        walk.Scene is null && !walk.LoadCells
            ? impl.FindCell(Frame, Position, Spheres(), Current)
            : impl.FindCell(walk.Scene, Frame, Spheres(), Current, walk.LoadCells);

    /// <summary>Answers a whole walk query by query through the single-query operations, threading by this rule.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>One answer per query.</returns>
    public static IReadOnlyList<FindCellResult> AskEach(ICellPhysics impl, WalkRequest walk)
    {
        var answers = new List<FindCellResult>(walk.Queries);
        var thread = new WalkThread(walk);
        while (thread.MoveNext())
        {
            var answer = thread.Ask(impl);
            answers.Add(answer);
            thread.Take(answer.Containing);
        }

        return answers;
    }
}
