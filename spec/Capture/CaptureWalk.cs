using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// Frames as an ordinary walk (docs/corpus-format.md) that keeps the port's answers: the start is the first frame's
/// position in the land cell under sphere 0's centre; each step moves the float32 position the walk's threading holds
/// (re-framed by the port's recorded cells, <see cref="AcPhys.Contract.WalkThread"/>) to the next frame's position.
/// </summary>
internal static class CaptureWalk
{
    /// <summary>Builds the walk and its recorded answers.</summary>
    /// <param name="frames">The frames (each with the port's cell).</param>
    /// <param name="body">The body (empty: a point, radius 0).</param>
    /// <returns>The walk and one recorded answer per query.</returns>
    public static (Walk Walk, RecordedAnswer[] Recorded) Of(IReadOnlyList<KeptFrame> frames, BodySphere[] body)
    {
        BodySphere[] b = body.Length > 0 ? body : [new BodySphere(Vector3.Zero, 0f)];
        var f0 = frames[0];
        double cx = f0.WorldX + b[0].Offset.X, cy = f0.WorldY + b[0].Offset.Y;
        var start = LandDefs.LcoordToGid((int)Math.Floor(cx / LandDefs.CellLength), (int)Math.Floor(cy / LandDefs.CellLength));
        var position = Local(f0, start, (float)f0.World.Z);
        var origin = position;
        var frame = start;
        var steps = new List<Vector2>(frames.Count - 1);
        var recorded = new RecordedAnswer[frames.Count];
        for (int i = 0; i < frames.Count; i++)
        {
            if (i > 0)
            {
                var target = Local(frames[i], frame, position.Z);
                var step = new Vector2(target.X - position.X, target.Y - position.Y);
                steps.Add(step);
                position += new Vector3(step.X, step.Y, 0);
            }

            var cell = frames[i].Cell;
            recorded[i] = new RecordedAnswer(cell, frames[i].Candidates);
            if (!cell.IsNone)
            {
                position -= LandDefs.GetBlockOffset(frame, cell);
                frame = cell;
            }
        }

        return (new Walk(start, origin, b, steps), recorded);
    }

    private static Vector3 Local(KeptFrame f, CellId frame, float z) =>
        new((float)(f.WorldX - (LandDefs.BlockLength * (double)frame.BlockX)), (float)(f.WorldY - (LandDefs.BlockLength * (double)frame.BlockY)), z);
}
