using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// Checks a capture frame by frame (docs/ports.md, "Your own sessions"): each frame is asked of the first judge that
/// accepts it, threaded as a walk is — the query of a frame is asked from the cell <b>the port</b> held before it (its
/// recorded cell, or its answer when re-asked), never from the reference's previous answer, so one wrong frame does not
/// cascade into a wrong span of the reference and a minimised walk stays short. Streamed: one frame at a time, in
/// constant memory (spans past <see cref="CaptureReport.MaxSpans"/> are only counted).
/// </summary>
internal sealed class CaptureChecker
{
    private readonly IReadOnlyList<ICaptureJudge> judges;
    private readonly ICellPhysics? port;
    private BodySphere[] radiusBody = [new(Vector3.Zero, 0f)];

    /// <summary>Initializes a new instance of the <see cref="CaptureChecker"/> class.</summary>
    /// <param name="judges">The judges, in order (the first that accepts a frame judges it).</param>
    /// <param name="port">An implementation to ask again at every frame (its answers replace the recorded ones), or null to judge the log.</param>
    public CaptureChecker(IReadOnlyList<ICaptureJudge> judges, ICellPhysics? port = null)
    {
        this.judges = judges;
        this.port = port;
    }

    /// <summary>Returns the judges for a declared mode with no dat files: the outdoor judge, and indoor frames not judged.</summary>
    /// <param name="pick">The declared pick.</param>
    /// <param name="outdoor">The declared outdoor fidelity.</param>
    /// <returns>The judges.</returns>
    public static IReadOnlyList<ICaptureJudge> OutdoorOnly(PickPolicy pick, OutdoorFidelity outdoor) =>
        [new OutdoorJudge(pick, outdoor), IndoorPlaceholderJudge.Instance];

    /// <summary>Returns the judges for a declared mode over the user's dat files: frames indoors and by a building in the scene
    /// the dats give (<see cref="SceneJudge"/>, first: it takes the outdoor frames by a building too), the rest on open land.</summary>
    /// <param name="scenes">The dat world's scenes.</param>
    /// <param name="pick">The declared pick.</param>
    /// <param name="indoor">The declared indoor fidelity.</param>
    /// <param name="outdoor">The declared outdoor fidelity.</param>
    /// <returns>The judges.</returns>
    public static IReadOnlyList<ICaptureJudge> WithDats(DatScenes scenes, PickPolicy pick, IndoorFidelity indoor, OutdoorFidelity outdoor) =>
        [new SceneJudge(scenes, pick, indoor, outdoor), new OutdoorJudge(pick, outdoor), IndoorPlaceholderJudge.Instance];

    /// <summary>Checks a capture.</summary>
    /// <param name="reader">The capture.</param>
    /// <param name="progress">Called every 65,536 frames with the bytes read, or null.</param>
    /// <param name="observe">Called with every frame's query (as judged: re-asked when a port is given) and verdict, or null (acphys render draws the path from it).</param>
    /// <returns>The report.</returns>
    /// <exception cref="AcPhys.Formats.InputFormatException">A malformed line.</exception>
    public CaptureReport Check(ICaptureReader reader, Action<long>? progress = null, Action<CaptureQuery, FrameVerdict>? observe = null)
    {
        var report = new CaptureReport();
        var headerBody = reader.Header.Body.ToArray();
        var before = CellId.None;
        var lastAgreed = new AgreedFrame();
        DivergentSpan? open = null;
        long spanStart = 0;
        var windows = new Dictionary<string, int>(StringComparer.Ordinal);
        while (reader.Read(out var frame))
        {
            report.Read++;
            if ((report.Read & 0xFFFF) == 0)
            {
                progress?.Invoke(reader.Position);
            }

            var prior = frame.Before.IsNone ? before : frame.Before;
            var query = new CaptureQuery(frame, prior, reader.Header.Frame, Body(headerBody, frame.Radius));
            if (port is not null)
            {
                query = Reask(query);
            }

            var verdict = Judge(query);
            observe?.Invoke(query, verdict);
            if (!query.Frame.Cell.IsNone)
            {
                before = query.Frame.Cell;
            }

            switch (verdict.Kind)
            {
                case VerdictKind.NotJudged:
                    report.Skip(verdict.Reason!);
                    break;
                case VerdictKind.Agrees:
                    report.Judged++;
                    open = null;
                    lastAgreed.Set(query);
                    break;
                default:
                    report.Judged++;
                    report.Divergent++;
                    string cause = CaptureCauses.Of(query, verdict);
                    if (open is not null && open.Cause == cause)
                    {
                        open.Extend(frame.Number, report.Read - spanStart + 1, query.WorldX, query.WorldY, verdict.Reference);
                        if (open.Window.Count > 0 && open.Window.Count < CaptureReport.MaxWindow)
                        {
                            open.Window.Add(KeptFrame.Of(query, VerdictKind.Diverges));
                        }

                        break;
                    }

                    var first = KeptFrame.Of(query, VerdictKind.Diverges);
                    open = new DivergentSpan(cause, first, verdict);
                    spanStart = report.Read;
                    int kept = windows.GetValueOrDefault(cause);
                    if (kept < CaptureReport.MinimisedSpans && report.Spans.Count < CaptureReport.MaxSpans)
                    {
                        windows[cause] = kept + 1;
                        if (lastAgreed.Any)
                        {
                            open.Window.Add(lastAgreed.Keep());
                        }

                        open.Window.Add(first); // the first spans of a cause are minimised (CaptureReport.MinimisedSpans)
                    }

                    if (report.Spans.Count < CaptureReport.MaxSpans)
                    {
                        report.Spans.Add(open);
                    }
                    else
                    {
                        report.SpansNotKept++;
                    }

                    break;
            }
        }

        report.Ignored = reader.Ignored;
        report.CornerChecks = judges.OfType<OutdoorJudge>().Sum(j => j.CornerChecks);
        return report;
    }

    private FrameVerdict Judge(in CaptureQuery query)
    {
        for (int i = 0; i < judges.Count; i++)
        {
            if (judges[i].Accepts(query))
            {
                return judges[i].Judge(query);
            }
        }

        return FrameVerdict.Skip(NotJudgedReason.IndoorNoDats);
    }

    // The body of this frame: the header's, with sphere 0's radius from the line when it gives one.
    private BodySphere[] Body(BodySphere[] header, float radius)
    {
        if (float.IsNaN(radius))
        {
            return header;
        }

        if (radiusBody.Length != Math.Max(header.Length, 1))
        {
            radiusBody = header.Length == 0 ? [new(Vector3.Zero, 0f)] : [.. header];
        }

        radiusBody[0] = radiusBody[0] with { Radius = radius };
        return radiusBody;
    }

    // The port asked again with the query the threading poses (its own previous answer as the cell before): its answer
    // replaces the recorded cell and candidates. An indoor frame has no scene to pose, so its record stands.
    private CaptureQuery Reask(CaptureQuery q)
    {
        if (q.IsIndoor)
        {
            return q;
        }

        var body = q.Body.Length > 0 ? q.Body : [new BodySphere(Vector3.Zero, 0f)];
        double wx = q.WorldX, wy = q.WorldY;
        double cx = wx + body[0].Offset.X, cy = wy + body[0].Offset.Y;
        var from = q.Before.IsLand ? q.Before : LandDefs.LcoordToGid((int)Math.Floor(cx / LandDefs.CellLength), (int)Math.Floor(cy / LandDefs.CellLength));
        if (from.IsNone)
        {
            return q; // off the map: the judge does not judge it
        }

        var position = new Vector3((float)(wx - (LandDefs.BlockLength * (double)from.BlockX)), (float)(wy - (LandDefs.BlockLength * (double)from.BlockY)), (float)q.Frame.Position.Z);
        var spheres = body.Select(b => new Sphere(position + b.Offset, b.Radius)).ToArray();
        var answer = port!.FindCell(from, position, spheres, q.Before);
        var after = answer.Containing.IsNone ? q.Before : answer.Containing;

        // The position is re-expressed in the world frame, so that the new cell frames nothing differently.
        var frame = q.Frame with
        {
            Cell = after,
            Position = q.Kind == CaptureFrameKind.World ? q.Frame.Position : q.Frame.Position.Offset(LandDefs.BlockLength * ((double)q.Frame.Cell.BlockX - after.BlockX), LandDefs.BlockLength * ((double)q.Frame.Cell.BlockY - after.BlockY)),
            HasCandidates = q.Body.Length > 0,
            Candidates = answer.Cells.ToArray(),
        };
        return q with { Frame = frame };
    }
}
