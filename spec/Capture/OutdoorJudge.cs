using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// Judges open-land frames against the reference core (facts §3, §4) in the declared mode: the port's cell after the
/// frame against find_cell's containing cell (a none answer keeps the cell, as a walk threads it), and a reported
/// candidate list against find_cell's candidates in insertion order (as FIND-CELL-CONFORMANCE compares them).
/// </summary>
/// <remarks>
/// The query is the one the port asked: from the cell it held before the frame (its block frame, float32, as
/// <see cref="AcPhys.Contract.WalkThread"/> holds a position), with that cell as current. <b>Precision</b>: the log printed
/// each coordinate to some decimals, so the true position lies in a box of ± half a unit of the last digit per axis. The
/// answer is a function of which side of finitely many axis-aligned lines the centres lie (24 m cell lines for the pick,
/// facts §5.5; |centre − cell edge| = r per axis for the candidates, facts §3.2, strict), so it is constant on each
/// region those lines cut the box into. A fast test (the distance to the nearest such line, in double, against the half
/// unit plus <see cref="Slack"/>) clears almost every frame; only the rest pay the reference at one point of every region
/// (<see cref="Samples"/>: the four corners when one line crosses an axis, more when several spheres' lines do), and a
/// frame whose points do not all give the same answer is not judged, never a false alarm.
/// </remarks>
internal sealed class OutdoorJudge : ICaptureJudge
{
    /// <summary>Metres added to the half unit in the fast test: float32 framing and re-basing (ulps of 192 m are 15 µm) and the EPS snap band (0.2 mm, facts §0).</summary>
    public const double Slack = 1e-3;

    private const double MapMetres = LandDefs.LandLength * (double)LandDefs.CellLength;

    private static readonly BodySphere[] Point = [new(Vector3.Zero, 0f)];

    private readonly PickPolicy pick;
    private readonly OutdoorFidelity outdoor;
    private readonly CellArray array = new();
    private readonly CellArray corner = new();
    private Sphere[] spheres = new Sphere[1];
    private double[] xs = new double[4], ys = new double[4];

    /// <summary>Initializes a new instance of the <see cref="OutdoorJudge"/> class.</summary>
    /// <param name="pick">The declared pick policy.</param>
    /// <param name="outdoor">The declared outdoor fidelity.</param>
    public OutdoorJudge(PickPolicy pick, OutdoorFidelity outdoor)
    {
        this.pick = pick;
        this.outdoor = outdoor;
    }

    /// <inheritdoc/>
    public string Name => "outdoor";

    /// <summary>Gets how many frames needed the reference at the box's corners (the slow path), for the report and the benchmark.</summary>
    public long CornerChecks { get; private set; }

    /// <inheritdoc/>
    public bool Accepts(in CaptureQuery query) => !query.IsIndoor;

    /// <inheritdoc/>
    public FrameVerdict Judge(in CaptureQuery query)
    {
        var f = query.Frame;
        bool bodyKnown = query.Body.Length > 0;
        var body = bodyKnown ? query.Body : Point;
        bool judgeCells = f.HasCandidates && bodyKnown;
        if (f.Cell.IsNone && !judgeCells)
        {
            return FrameVerdict.Skip(NotJudgedReason.NothingToJudge);
        }

        double wx = query.WorldX, wy = query.WorldY;
        double cx = wx + body[0].Offset.X, cy = wy + body[0].Offset.Y;
        if (!(cx > LandDefs.CellLength && cx < MapMetres - LandDefs.CellLength && cy > LandDefs.CellLength && cy < MapMetres - LandDefs.CellLength))
        {
            return FrameVerdict.Skip(NotJudgedReason.OffMap);
        }

        var from = query.Before.IsLand ? query.Before : LandDefs.LcoordToGid((int)Math.Floor(cx / LandDefs.CellLength), (int)Math.Floor(cy / LandDefs.CellLength));
        double ox = LandDefs.BlockLength * (double)from.BlockX, oy = LandDefs.BlockLength * (double)from.BlockY;
        var position = new Vector3((float)(wx - ox), (float)(wy - oy), (float)f.Position.Z);
        var containing = Ask(array, from, position, body, query.Before);
        double hx = f.Position.HalfX + Slack, hy = f.Position.HalfY + Slack;
        if (!Clear(wx, wy, hx, hy, body, judgeCells))
        {
            CornerChecks++;
            int nx = Samples(ref xs, wx, f.Position.HalfX, body, judgeCells, static o => o.X);
            int ny = Samples(ref ys, wy, f.Position.HalfY, body, judgeCells, static o => o.Y);
            bool cellsDiffer = false;
            for (int i = 0; i < nx; i++)
            {
                for (int j = 0; j < ny; j++)
                {
                    var at = new Vector3((float)(wx + xs[i] - ox), (float)(wy + ys[j] - oy), position.Z);
                    if (Ask(corner, from, at, body, query.Before) != containing)
                    {
                        return FrameVerdict.Skip(NotJudgedReason.NearCellLine);
                    }

                    cellsDiffer |= judgeCells && !Same(array, corner);
                }
            }

            if (cellsDiffer)
            {
                return FrameVerdict.Skip(NotJudgedReason.NearSphereEdge);
            }
        }

        var after = containing.IsNone ? query.Before : containing; // none keeps the cell (WalkThread.Take)
        if (!f.Cell.IsNone && f.Cell != after)
        {
            return FrameVerdict.Diverge(after, DivergenceKind.Cell);
        }

        if (judgeCells && !Same(array, f.Candidates.Span))
        {
            var want = new CellId[array.Count];
            for (int i = 0; i < want.Length; i++)
            {
                want[i] = array[i].Id;
            }

            bool sameSet = want.Length == f.Candidates.Length && want.Order().SequenceEqual(f.Candidates.ToArray().Order());
            return FrameVerdict.Diverge(after, sameSet ? DivergenceKind.CandidateOrder : DivergenceKind.CandidateContent, want);
        }

        return FrameVerdict.Agree(after);
    }

    // Every boundary the verdict depends on is farther than the box (plus slack): per axis, sphere 0's centre from the
    // 24 m lines (the pick), and each sphere's centre from its cell's edges and from r and 24 − r in its cell (the candidates).
    internal static bool Clear(double wx, double wy, double hx, double hy, BodySphere[] body, bool judgeCells)
    {
        int n = judgeCells ? body.Length : 1;
        for (int i = 0; i < n; i++)
        {
            float r = judgeCells ? body[i].Radius : -1f;
            if (!AxisClear(wx + body[i].Offset.X, hx, r) || !AxisClear(wy + body[i].Offset.Y, hy, r))
            {
                return false;
            }
        }

        return true;
    }

    private static bool AxisClear(double v, double h, float r)
    {
        double inCell = v - (LandDefs.CellLength * Math.Floor(v / LandDefs.CellLength));
        if (inCell <= h || LandDefs.CellLength - inCell <= h)
        {
            return false;
        }

        return r < 0 || (Math.Abs(inCell - r) > h && Math.Abs(LandDefs.CellLength - r - inCell) > h);
    }

    private static bool Same(CellArray a, CellArray b)
    {
        if (a.Count != b.Count)
        {
            return false;
        }

        for (int i = 0; i < a.Count; i++)
        {
            if (a[i].Id != b[i].Id)
            {
                return false;
            }
        }

        return true;
    }

    private static bool Same(CellArray a, ReadOnlySpan<CellId> b)
    {
        if (a.Count != b.Length)
        {
            return false;
        }

        for (int i = 0; i < b.Length; i++)
        {
            if (a[i].Id != b[i])
            {
                return false;
            }
        }

        return true;
    }

    // One offset per region of the precision interval [−h, +h] along one axis: its two ends and a point between each pair
    // of neighbouring boundaries inside it (24 m lines for every sphere judged, and r and 24 − r into the cell for the
    // candidates). The answer is constant on each region, so these points see every answer the box holds — the four
    // corners alone miss the middle strip when two boundaries fall inside one interval (several spheres, r below the
    // printed precision, r near 12 m).
    internal static int Samples(ref double[] into, double v, double h, BodySphere[] body, bool judgeCells, Func<Vector3, float> axis)
    {
        Span<double> cuts = stackalloc double[6 * Math.Max(1, body.Length)];
        int n = 0;
        int spheresJudged = judgeCells ? body.Length : 1;
        for (int i = 0; i < spheresJudged; i++)
        {
            double u = v + axis(body[i].Offset);
            double line = LandDefs.CellLength * Math.Floor(u / LandDefs.CellLength);
            n = Cut(cuts, n, u, h, line);
            n = Cut(cuts, n, u, h, line + LandDefs.CellLength);
            if (judgeCells)
            {
                float r = body[i].Radius;
                foreach (double edge in (ReadOnlySpan<double>)[line, line + LandDefs.CellLength])
                {
                    n = Cut(cuts, n, u, h, edge - r);
                    n = Cut(cuts, n, u, h, edge + r);
                }
            }
        }

        cuts = cuts[..n];
        cuts.Sort();
        int count = n + 1;
        if (into.Length < count + 1)
        {
            Array.Resize(ref into, count + 1); // the caller's buffer grows once for a many-sphere body
        }

        into[0] = -h;
        for (int k = 1; k < n; k++)
        {
            into[k] = (cuts[k - 1] + cuts[k]) / 2;
        }

        into[n < 1 ? 1 : n] = h;
        return n < 1 ? 2 : n + 1;
    }

    private static int Cut(Span<double> cuts, int n, double u, double h, double boundary)
    {
        double d = boundary - u;
        if (d > -h && d < h && n < cuts.Length)
        {
            cuts[n++] = d;
        }

        return n;
    }

    private CellId Ask(CellArray into, CellId from, Vector3 position, BodySphere[] body, CellId current)
    {
        if (spheres.Length != body.Length)
        {
            spheres = new Sphere[body.Length];
        }

        for (int i = 0; i < body.Length; i++)
        {
            spheres[i] = new Sphere(position + body[i].Offset, body[i].Radius);
        }

        return CellQuery.FindCellListOutdoor(into, from, position, spheres, current, pick, OpenLand.Instance, outdoor);
    }
}
