using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Capture;

/// <summary>
/// Judges indoor frames (an env cell before or after the frame) and outdoor frames by a building against the reference in
/// the scene the user's dat files give (docs/ports.md, "Your own sessions"): the query a scene walk asks (find_cell_scene,
/// facts §4) from the cell the port held before the frame, in that cell's block frame, with the body's spheres, current
/// cell that cell, in the declared pick and fidelity (the indoor switches included). The port's cell after the frame is
/// judged against the containing cell (none keeps the cell, as a walk threads it); a reported candidate list against the
/// static placement's and the movement transition's (facts §4 step 5: the filter is the one difference; the log does not
/// say which the port asked, so either agrees).
/// </summary>
/// <remarks>
/// Not judged, with the reason: no body (the closure depends on the radius), no previous cell, a cell or block not in the
/// dats, a refused scene, ace-keeps-stale-cells declared (the answer is the session's, facts §7 #6), and any frame whose
/// printed precision reaches a threshold the answer depends on (<see cref="ScenePrecision"/>).
/// </remarks>
internal sealed class SceneJudge : ICaptureJudge
{
    private const double MapMetres = LandDefs.LandLength * (double)LandDefs.CellLength;

    private readonly DatScenes scenes;
    private readonly IndoorFidelity indoor;
    private readonly ReferenceAdapter reference;

    /// <summary>Initializes a new instance of the <see cref="SceneJudge"/> class.</summary>
    /// <param name="scenes">The user's dat world.</param>
    /// <param name="pick">The declared pick.</param>
    /// <param name="indoor">The declared indoor fidelity.</param>
    /// <param name="outdoor">The declared outdoor fidelity.</param>
    public SceneJudge(DatScenes scenes, PickPolicy pick, IndoorFidelity indoor, OutdoorFidelity outdoor)
    {
        this.scenes = scenes;
        this.indoor = indoor;
        reference = new ReferenceAdapter(pick, outdoor: outdoor) { Indoor = indoor };
    }

    /// <inheritdoc/>
    public string Name => "indoor (dat files)";

    /// <summary>Gets how many frames the judge took.</summary>
    public long Taken { get; private set; }

    /// <inheritdoc/>
    /// <remarks>Every indoor frame; an outdoor frame when it names a body and a sphere comes within r + 1 m of a land cell
    /// a building of the dats is attached to: there the reference may enter the building (facts §5.3), which open land
    /// (<see cref="OutdoorJudge"/>) has none of. Elsewhere the two agree (every block loaded in the user's world).</remarks>
    public bool Accepts(in CaptureQuery query)
    {
        if (query.IsIndoor)
        {
            return true;
        }

        if (query.Body.Length == 0)
        {
            return false;
        }

        foreach (var s in query.Body)
        {
            // The land cells a sphere can add (within r of its centre, facts §3.2), with a metre to spare.
            double cx = query.WorldX + s.Offset.X, cy = query.WorldY + s.Offset.Y, reach = s.Radius + 1.0;
            int x0 = Cell(cx - reach), x1 = Cell(cx + reach), y0 = Cell(cy - reach), y1 = Cell(cy + reach);
            for (int x = x0; x <= x1; x++)
            {
                for (int y = y0; y <= y1; y++)
                {
                    if (LandDefs.LcoordToGid(x, y) is { IsNone: false } land && scenes.MayOwnBuilding(land))
                    {
                        return true;
                    }
                }
            }
        }

        return false;
    }

    /// <inheritdoc/>
    public FrameVerdict Judge(in CaptureQuery query)
    {
        Taken++;
        var f = query.Frame;
        if (query.Body.Length == 0)
        {
            return FrameVerdict.Skip(NotJudgedReason.IndoorNoBody);
        }

        if (indoor.AceKeepsStaleCells)
        {
            return FrameVerdict.Skip(NotJudgedReason.IndoorStaleCells);
        }

        double wx = query.WorldX, wy = query.WorldY;
        var from = query.Before;
        if (from.IsNone)
        {
            if (query.IsIndoor)
            {
                return FrameVerdict.Skip(NotJudgedReason.IndoorNoPrevious);
            }

            double cx = wx + query.Body[0].Offset.X, cy = wy + query.Body[0].Offset.Y;
            if (!(cx > LandDefs.CellLength && cx < MapMetres - LandDefs.CellLength && cy > LandDefs.CellLength && cy < MapMetres - LandDefs.CellLength))
            {
                return FrameVerdict.Skip(NotJudgedReason.OffMap);
            }

            from = LandDefs.LcoordToGid((int)Math.Floor(cx / LandDefs.CellLength), (int)Math.Floor(cy / LandDefs.CellLength));
        }

        if (!(from.IsLand || from.IsEnv) || scenes.Of(from.Landblock) is not { } scene)
        {
            return FrameVerdict.Skip(from.IsLand || from.IsEnv ? (scenes.Refused.ContainsKey(from.Landblock) ? NotJudgedReason.SceneRefused : NotJudgedReason.NotInDats) : NotJudgedReason.NotInDats);
        }

        if ((from.IsEnv && scene.Built.GetEnvCell(from) is null) || (f.Cell.IsIndoorByLowWord && scene.Built.GetEnvCell(f.Cell) is null))
        {
            return FrameVerdict.Skip(NotJudgedReason.NotInDats);
        }

        var position = new Vector3((float)(wx - (LandDefs.BlockLength * (double)from.BlockX)), (float)(wy - (LandDefs.BlockLength * (double)from.BlockY)), (float)f.Position.Z);
        var spheres = new Sphere[query.Body.Length];
        for (int i = 0; i < spheres.Length; i++)
        {
            spheres[i] = new Sphere(position + query.Body[i].Offset, query.Body[i].Radius);
        }

        var placement = reference.FindCell(scene.Scene, from, spheres, query.Before, false);
        var transition = reference.FindCell(scene.Scene, from, spheres, query.Before, true);
        var all = placement.Cells.Concat(transition.Cells).Distinct().ToArray();
        if (all.Any(c => c.IsLand && !scene.Built.IsLoaded(c.Landblock)))
        {
            return FrameVerdict.Skip(NotJudgedReason.BlockNotInDats);
        }

        var half = new Vector3((float)f.Position.HalfX, (float)f.Position.HalfY, (float)AcPhys.Formats.Capture.PrintedPoint.Half(f.Position.DecimalsZ));
        if (ScenePrecision.Near(scene, indoor, from, spheres, half, (wx, wy), query.Body, all) is { } near)
        {
            return FrameVerdict.Skip(near);
        }

        // The filter runs after the pick (facts §4 step 5): both kinds name one containing cell.
        var containing = placement.Containing;
        var after = containing.IsNone ? query.Before : containing;
        if (after.IsNone)
        {
            return FrameVerdict.Skip(NotJudgedReason.NothingToJudge);
        }

        if (!f.Cell.IsNone && f.Cell != after)
        {
            return FrameVerdict.Diverge(after, DivergenceKind.Cell);
        }

        if (f.HasCandidates)
        {
            var got = f.Candidates.Span;
            if (!got.SequenceEqual([.. placement.Cells]) && !got.SequenceEqual([.. transition.Cells]))
            {
                var want = placement.Cells.ToArray();
                bool sameSet = want.Length == got.Length && want.Order().SequenceEqual(got.ToArray().Order());
                return FrameVerdict.Diverge(after, sameSet ? DivergenceKind.CandidateOrder : DivergenceKind.CandidateContent, want);
            }
        }

        return FrameVerdict.Agree(after);
    }

    private static int Cell(double metres) => (int)Math.Max(-1, Math.Min(LandDefs.LandLength, Math.Floor(metres / LandDefs.CellLength)));
}
