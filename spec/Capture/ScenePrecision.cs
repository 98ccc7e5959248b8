using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// The printed-precision test of an indoor frame (docs/ports.md, "Your own sessions"): whether every test the reference's
/// answer is made of keeps its outcome over the box of positions the printed digits allow (± half a unit per axis, plus
/// <see cref="OutdoorJudge.Slack"/>). A plane's signed distance d over a box ranges over d₀ ± Σ|nᵢ|·hᵢ (n the plane's normal
/// in the block frame), so a test "d against T" is constant on the box unless |d₀ − T| is within that reach.
/// </summary>
/// <remarks>
/// The tests are those the closure and the pick make from the candidates at the printed position (facts §4): for every
/// env cell among them, its portals (exit and load hint: |d| against r + EPS, §5.1) and each resolvable neighbour's BSP
/// faces (sphere: d against ±(r + 0.01), §5.7); for every land cell among them, its building's cells' faces (§5.3) and the
/// outdoor lines (§3.2, as <see cref="OutdoorJudge"/> tests them); and sphere 0's centre against each candidate env cell's
/// faces (point_in_cell: d against −EPS, §5.5; ±EPS tested). If none is within reach, every test along the breadth-first
/// closure has the same outcome at every point of the box, so (by induction over the closure) the candidates and the pick
/// are the same there: the verdict does not depend on unprinted digits. Otherwise the frame is not judged.
/// </remarks>
internal static class ScenePrecision
{
    private const float SpherePadding = 0.01f; // BN:222, facts §5.7

    /// <summary>Returns why the frame cannot be judged at its printed precision, or null when every test is clear.</summary>
    /// <param name="scene">The block's scene.</param>
    /// <param name="fidelity">The declared indoor fidelity (which portals lead outside, re-framed transit).</param>
    /// <param name="position">The cell the query is asked from (its block frame is the spheres').</param>
    /// <param name="spheres">The spheres at the printed position.</param>
    /// <param name="half">Half a unit of the last printed digit per axis.</param>
    /// <param name="world">The position in world metres (the outdoor lines are tested at it plus each sphere's offset).</param>
    /// <param name="body">The body (offsets and radii).</param>
    /// <param name="candidates">The reference's candidates at the printed position (static and transition answers together).</param>
    /// <returns>The reason, or null.</returns>
    public static NotJudgedReason? Near(BlockScene scene, IndoorFidelity fidelity, CellId position, ReadOnlySpan<Sphere> spheres, Vector3 half, (double X, double Y) world, BodySphere[] body, IEnumerable<CellId> candidates)
    {
        bool outdoor = false;
        foreach (var id in candidates)
        {
            if (id.IsLand)
            {
                outdoor = true;
                if (scene.Built.GetBuilding(id) is { } building)
                {
                    foreach (var bp in building.Portals)
                    {
                        if (bp.OtherPortalId != BldPortal.None && scene.Built.GetEnvCell(id.WithLow(bp.OtherCellId)) is { } entered
                            && SpheresNear(scene, entered, fidelity, position, spheres, half))
                        {
                            return NotJudgedReason.NearCellFace;
                        }
                    }
                }

                continue;
            }

            if (scene.Built.GetEnvCell(id) is not { } env)
            {
                continue; // a load hint: its test is the owning cell's portal plane, below
            }

            // The pick: sphere 0's centre in the candidate's block frame (always re-framed, facts §4 step 4b).
            var centre = spheres[0].Center - LandDefs.GetBlockOffset(position, id);
            if (FacesNear(scene.Faces[id], env.Frame, centre, half, -LandDefs.Epsilon, LandDefs.Epsilon))
            {
                return NotJudgedReason.NearCellFace;
            }

            var shift = fidelity.ReframeTransit ? LandDefs.GetBlockOffset(position, id) : Vector3.Zero;
            foreach (var portal in env.Portals)
            {
                foreach (var s in spheres)
                {
                    float r = s.Radius + LandDefs.Epsilon;
                    if (PlaneNear(portal.Plane, env.Frame, s.Center - shift, half, -r, r))
                    {
                        return NotJudgedReason.NearPortalPlane;
                    }
                }

                if (!portal.LeadsOutside(fidelity) && scene.Built.GetEnvCell(id.WithLow(portal.OtherCellId)) is { } other
                    && SpheresNear(scene, other, fidelity, position, spheres, half))
                {
                    return NotJudgedReason.NearCellFace;
                }
            }
        }

        if (outdoor && !OutdoorJudge.Clear(world.X, world.Y, half.X + OutdoorJudge.Slack, half.Y + OutdoorJudge.Slack, body, judgeCells: true))
        {
            return NotJudgedReason.NearCellLine; // add_all_outside_cells ran: its lines and r-bands (facts §3.2), and the land pick's 24 m lines
        }

        return null;
    }

    // sphere_intersects_cell against a cell's faces for every sphere (its own frame; the BSP pads r by 0.01).
    private static bool SpheresNear(BlockScene scene, EnvCell cell, IndoorFidelity fidelity, CellId position, ReadOnlySpan<Sphere> spheres, Vector3 half)
    {
        var shift = fidelity.ReframeTransit ? LandDefs.GetBlockOffset(position, cell.Id) : Vector3.Zero;
        foreach (var s in spheres)
        {
            float r = s.Radius + SpherePadding;
            if (FacesNear(scene.Faces[cell.Id], cell.Frame, s.Center - shift, half, -r, r))
            {
                return true;
            }
        }

        return false;
    }

    private static bool FacesNear(IReadOnlyList<CellPlane> faces, Frame frame, Vector3 point, Vector3 half, float low, float high)
    {
        for (int i = 0; i < faces.Count; i++)
        {
            if (PlaneNear(faces[i], frame, point, half, low, high))
            {
                return true;
            }
        }

        return false;
    }

    // Whether d = N·local(p) + D can reach a threshold over the box p ± half (plus slack): d is linear in p, its reach
    // Σ|(R·N)ᵢ|·halfᵢ, R the cell frame's rotation; double arithmetic, the slack covering float32's framing error.
    private static bool PlaneNear(CellPlane plane, Frame frame, Vector3 point, Vector3 half, float low, float high)
    {
        var local = frame.GlobalToLocal(point);
        double d = ((double)plane.Normal.X * local.X) + ((double)plane.Normal.Y * local.Y) + ((double)plane.Normal.Z * local.Z) + plane.D;
        var n = Vector3.Transform(plane.Normal, frame.Rotation);
        double reach = (Math.Abs((double)n.X) * half.X) + (Math.Abs((double)n.Y) * half.Y) + (Math.Abs((double)n.Z) * half.Z)
            + (OutdoorJudge.Slack * plane.Normal.Length());
        return Math.Abs(d - low) <= reach || Math.Abs(d - high) <= reach;
    }
}
