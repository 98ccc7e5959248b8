using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Dat;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Invariants of the parts variant in a scene (find_cell_parts_scene / find_cell_parts_transition; facts §3.4, §4
/// step 5, §5.2, §5.3), over the parts queries a scene walk stands for (<see cref="ScenePartsQueries"/>). Boxes are
/// judged with a 1 mm band: a cell a box robustly reaches must be listed, a cell no box comes within 1 mm of must not.
/// </summary>
internal static class PartsIndoorInvariants
{
    /// <summary>The band, metres.</summary>
    public const float Margin = 1e-3f;

    /// <summary>Either parts kind: an implementation offering one of them is tested on the parts indoors.</summary>
    public const Op Either = Op.FindCellPartsScene | Op.FindCellPartsTransition;

    /// <summary>PARTS-INDOOR-SOUNDNESS.</summary>
    public static readonly Invariant<SceneWalk> Soundness = new(
        "PARTS-INDOOR-SOUNDNESS",
        "In a scene, every loaded env cell the parts list names, other than the anchor's own, is reached by some part's box (within 1 mm, in that cell's frame); every land cell lies in the smallest cell rectangle holding the anchor's column and every part's box — an Always2D part's square ±r around its origin instead (§3.4) — (within 1 mm); every env id naming no loaded cell is the anchor or a load hint (the target of a portal of a cell the closure walked, under ACE's key when declared); none appears twice; after static placement from an indoor anchor every loaded cell is the anchor's or one it sees; and an anchor indoor by its low word (a block id too) that names no loaded env cell is listed alone, flagged not loaded, with HitsInteriorCell set when reported. Under a declared ace-keeps-stale-cells the cells of the walk's previous parts answer of the same kind are excused, and nothing else.",
        "facts §1.1, §3.4, §4 steps 1, 3–5, §5.2, §5.3, §5.9, §7 #6",
        Op.None,
        ScenePartsDomain.Instance,
        (impl, w) => Judge(impl, w, false, Sound),
        sceneForms: Either);

    /// <summary>PARTS-INDOOR-COVERAGE.</summary>
    public static readonly Invariant<SceneWalk> Coverage = new(
        "PARTS-INDOOR-COVERAGE",
        "In a scene, for every loaded env cell the parts list names and every portal of it that some part's box crosses by more than 1 mm on both sides with the part's centre within r − 1 mm of the plane: a loaded neighbour (retail: any loaded cell by full id) that such a part's box overlaps by more than 1 mm is listed, and an exit portal lists the land cell under the anchor (each unless static placement from an indoor anchor filters it out) — by any part, not only the first.",
        "facts §4 step 4a, §5.2, §5.4, §5.7, §7 #10, #12",
        Op.None,
        ScenePartsDomain.Instance,
        (impl, w) => Judge(impl, w, true, Covered),
        sceneForms: Either);

    /// <summary>PARTS-BUILDING-ENTRY.</summary>
    public static readonly Invariant<SceneWalk> BuildingEntry = new(
        "PARTS-BUILDING-ENTRY",
        "In a scene, for every loaded land cell the parts list names whose building has a portal into a loaded env cell: when some part's box crosses that door's plane by more than 1 mm on both sides (in the env cell's frame, block offset applied), its centre is within r − 1 mm of the plane and its box overlaps the cell by more than 1 mm, the cell is listed and HitsInteriorCell (when reported) is set — by any part, not only the anchor.",
        "facts §5.3 (parts check_building_transit, retail box-side pairing), §5.8",
        Op.None,
        ScenePartsBuildingDomain.Instance,
        (impl, w) => Judge(impl, w, true, Entered),
        sceneForms: Either);

    /// <summary>PARTS-INDOOR-CONFORMANCE.</summary>
    public static readonly Invariant<SceneWalk> Conformance = new(
        "PARTS-INDOOR-CONFORMANCE",
        "In a scene, the parts list equals the retail-faithful reference's in the declared mode, in each kind offered: the same cells in the same order, the same load-hint flags and HitsInteriorCell when reported, and no containing cell.",
        "facts §3.4, §4, §5.2, §5.3 (the retail-faithful reference in the declared mode)",
        Op.None,
        ScenePartsDomain.Instance,
        Conform,
        sceneForms: Either);

    /// <summary>Gets every invariant of the parts variant indoors.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; } = [Soundness, Coverage, BuildingEntry, Conformance];

    private delegate string? Check(ICellPhysics impl, CellScene scene, Query q, ref bool applied);

    private static Outcome Judge(ICellPhysics impl, SceneWalk w, bool preferTransition, Check check)
    {
        var built = SceneBuild.Build(w.Scene);
        bool loadCells = ScenePartsQueries.Kind(impl.Ops, preferTransition);
        bool applied = false;
        foreach (var (index, parts, answer, stale) in PartsSession.Ask(impl, w, loadCells))
        {
            var anchor = parts[0].Cell;
            var q = new Query(index, parts, answer, anchor.IsIndoorByLowWord ? built.GetEnvCell(anchor) : null, anchor.IsIndoorByLowWord && !(loadCells && !impl.Indoor.AceTransitionFilters), stale, w.Scene);
            if (check(impl, built, q, ref applied) is string why)
            {
                return Outcome.ViolatedAt(index, $"step {index} ({(loadCells ? "find_cell_parts_transition" : "find_cell_parts_scene")}, {parts.Length} part{(parts.Length == 1 ? string.Empty : "s")}, anchor {anchor}): {why}");
            }
        }

        return applied ? Outcome.Holds : Outcome.Vacuous;
    }

    private static string? Sound(ICellPhysics impl, CellScene scene, Query q, ref bool applied)
    {
        var cells = q.Answer.Cells;
        if (cells.Distinct().Count() != cells.Count)
        {
            return $"duplicate ids in [{string.Join(", ", cells)}]";
        }

        var anchor = q.Parts[0];
        if (MissingAnchor(scene, q) is string missing)
        {
            applied = true;
            return missing;
        }

        var range = LandRange(q.Parts);
        for (int k = 0; k < cells.Count; k++)
        {
            var id = cells[k];
            applied = true;
            if (AceBlindHint(impl, scene, q, k) || (q.Stale?.Contains(id) ?? false))
            {
                continue;
            }

            var env = id.IsEnv ? scene.GetEnvCell(id) : null;
            if (env is null && id.IsIndoorByLowWord && id != anchor.Cell && !LoadHint(impl, scene, q, id))
            {
                return $"{id} names no loaded env cell, and is neither the anchor nor a load hint (a portal target of a cell the closure walked: facts §4 step 3, §5.1)";
            }

            if (env is not null && id != anchor.Cell && !q.Parts.Any(p => Overlaps(p, env, Margin)))
            {
                return $"{id} is listed but no part's box comes within 1 mm of it";
            }

            if (id.IsLand && range is { } r && !r.Holds(id))
            {
                return $"{id} lies outside the cell rectangle of the anchor's column and the parts' boxes";
            }

            bool loaded = env is not null || (id.IsLand && scene.IsLoaded(id.Landblock));
            if (q.Filtered && loaded && id != anchor.Cell && !(env is not null && q.AnchorEnv is { } a && a.Sees(id)))
            {
                return $"static placement from {anchor.Cell}: {id} is listed but is neither the anchor's cell nor one it sees (facts §4 step 5)";
            }
        }

        return null;
    }

    private static string? Covered(ICellPhysics impl, CellScene scene, Query q, ref bool applied)
    {
        if (!Visible(scene, q.Parts[0].Cell))
        {
            return null;
        }

        var listed = q.Answer.Cells.ToHashSet();
        for (int k = 0; k < q.Answer.Cells.Count; k++)
        {
            var id = q.Answer.Cells[k];
            if (!id.IsEnv || scene.GetEnvCell(id) is not { } cell || AceBlindHint(impl, scene, q, k))
            {
                continue;
            }

            foreach (var portal in cell.Portals)
            {
                var reaching = q.Parts.Where(p => Crosses(p, cell, portal.Plane) && Gated(p, cell, portal.Plane)).ToArray();
                if (reaching.Length == 0)
                {
                    continue;
                }

                if (portal.LeadsOutside(impl.Indoor))
                {
                    if (!q.Filtered && LandUnder(q.Parts[0]) is { } land && scene.IsLoaded(land.Landblock))
                    {
                        applied = true;
                        if (!listed.Contains(land))
                        {
                            return $"a part's box crosses {cell.Id}'s exit portal but the land cell under the anchor, {land}, is missing from [{string.Join(", ", q.Answer.Cells)}]";
                        }
                    }

                    continue;
                }

                var otherId = cell.Id.WithLow(portal.OtherCellId);
                if (scene.GetEnvCell(otherId) is not { } other || (impl.Indoor.AceNeighbourViaVisibleCells && !cell.Sees(otherId)))
                {
                    continue;
                }

                if (reaching.Any(p => Overlaps(p, other, -Margin)) && Kept(q, otherId))
                {
                    applied = true;
                    if (!listed.Contains(otherId))
                    {
                        return $"part {Array.IndexOf(q.Parts, reaching.First(p => Overlaps(p, other, -Margin)))}'s box crosses {cell.Id}'s portal to {otherId} and overlaps it, but {otherId} is missing from [{string.Join(", ", q.Answer.Cells)}]";
                    }
                }
            }
        }

        return null;
    }

    private static string? Entered(ICellPhysics impl, CellScene scene, Query q, ref bool applied)
    {
        if (!Visible(scene, q.Parts[0].Cell))
        {
            return null;
        }

        var listed = q.Answer.Cells.ToHashSet();
        foreach (var land in q.Answer.Cells)
        {
            if (!land.IsLand || !scene.IsLoaded(land.Landblock) || scene.GetBuilding(land) is not { } building)
            {
                continue;
            }

            foreach (var door in building.Portals)
            {
                if (scene.GetEnvCell(land.WithLow(door.OtherCellId)) is not { } cell || door.OtherPortalId >= cell.Portals.Length)
                {
                    continue;
                }

                var plane = cell.Portals[door.OtherPortalId].Plane;
                int by = Array.FindIndex(q.Parts, p => Crosses(p, cell, plane) && Gated(p, cell, plane) && Overlaps(p, cell, -Margin));
                if (by < 0 || !Kept(q, cell.Id))
                {
                    continue;
                }

                applied = true;
                if (!listed.Contains(cell.Id))
                {
                    return $"part {by}'s box crosses the door of {land}'s building into {cell.Id} and overlaps it, but {cell.Id} is missing from [{string.Join(", ", q.Answer.Cells)}]";
                }

                if (q.Answer.HitsInteriorCell == false)
                {
                    return $"the parts entered {cell.Id} through a building door but HitsInteriorCell is false";
                }
            }
        }

        return null;
    }

    private static Outcome Conform(ICellPhysics impl, SceneWalk w)
    {
        var reference = Invariants.Conformance.ReferenceFor(impl);
        var queries = ScenePartsQueries.Of(w);
        var scene = Transports.ScenesAsRecords(impl) ? DatRoundTrip.Of(w.Scene) : w.Scene; // what the implementation was sent (docs/conformance.md)
        bool applied = false;
        foreach (bool loadCells in new[] { false, true })
        {
            if ((impl.Ops & (loadCells ? Op.FindCellPartsTransition : Op.FindCellPartsScene)) == 0)
            {
                continue;
            }

            string kind = loadCells ? "find_cell_parts_transition" : "find_cell_parts_scene";
            // The reference's walk in the same mode (stale cells: one array per walk and kind), on the scene the implementation was sent.
            var walk = impl.Indoor.AceKeepsStaleCells ? reference.FindCellPartsWalk(scene, [.. queries.Select(q => (IReadOnlyList<Part>)q.Parts)], loadCells) : null;
            int at = 0;
            foreach (var (index, parts, got, _) in PartsSession.Ask(impl, w, loadCells))
            {
                applied = true;
                int i = at++;
                var expected = walk is null ? reference.FindCellParts(scene, parts, loadCells) : walk[i];
                // A difference a tie probe's answer explains is the arithmetic's, not the port's (docs/conformance.md, "Scenes").
                if (Difference(got, expected) is string why && PartsProbes.Of(parts).All(p => Difference(got, Probe(reference, scene, queries, i, p, loadCells, walk is not null)) is not null))
                {
                    return Outcome.ViolatedAt(index, $"step {index} ({kind}): {why}");
                }

                if (!got.Containing.IsNone)
                {
                    return Outcome.ViolatedAt(index, $"step {index} ({kind}): containing {got.Containing}, but the parts list has no pick (null)");
                }
            }
        }

        return applied ? Outcome.Holds : Outcome.Vacuous;
    }

    // The reference's answer to query i with its parts moved to a probe: under stale cells the walk's earlier queries are
    // asked first in the same walk (only when the answers differ, so a conforming walk pays nothing).
    private static FindCellResult Probe(ICellPhysics reference, Scene scene, IReadOnlyList<(int Index, Part[] Parts)> queries, int i, Part[] probe, bool loadCells, bool stale) =>
        !stale ? reference.FindCellParts(scene, probe, loadCells)
            : reference.FindCellPartsWalk(scene, [.. queries.Take(i).Select(q => (IReadOnlyList<Part>)q.Parts), probe], loadCells)[i];

    // The cells in order, the load-hint flags and HitsInteriorCell when reported, against the reference's.
    private static string? Difference(FindCellResult got, FindCellResult expected)
    {
        if (!got.Cells.SequenceEqual(expected.Cells))
        {
            return $"cells [{string.Join(", ", got.Cells)}], reference [{string.Join(", ", expected.Cells)}]";
        }

        if (got.Loaded is { } loaded && expected.Loaded is { } want && !loaded.SequenceEqual(want))
        {
            return $"load-hint flags [{string.Join(", ", loaded)}], reference [{string.Join(", ", want)}] for [{string.Join(", ", expected.Cells)}]";
        }

        return got.HitsInteriorCell is bool hits && hits != expected.HitsInteriorCell ? $"HitsInteriorCell {hits}, reference {expected.HitsInteriorCell}" : null;
    }

    // An anchor indoor by its low word (an env id, or a block id 0xFFFF: facts §1.1) that names no loaded env cell is
    // added with its load flag false and sets HitsInteriorCell (§4 step 3); no closure runs from it (step 4) and the
    // filter keeps it (step 5: its own id), so the list is the anchor alone. Under a declared ace-keeps-stale-cells the
    // previous answer's cells stay too (§7 #6: no closure, no filter runs to remove them), and nothing else.
    private static string? MissingAnchor(CellScene scene, Query q)
    {
        var anchor = q.Parts[0].Cell;
        if (!anchor.IsIndoorByLowWord || scene.GetEnvCell(anchor) is not null)
        {
            return null;
        }

        var cells = q.Answer.Cells;
        int at = q.Stale is null ? (cells.Count == 1 ? 0 : -1) : Enumerable.Range(0, cells.Count).FirstOrDefault(i => cells[i] == anchor, -1);
        if (at < 0 || cells[at] != anchor || (q.Stale is { } stale && cells.Any(c => c != anchor && !stale.Contains(c))))
        {
            return q.Stale is null
                ? $"the anchor {anchor} names no loaded env cell, so the list is the anchor alone (facts §4 steps 3–4), but it is [{string.Join(", ", cells)}]"
                : $"the anchor {anchor} names no loaded env cell, so the list is the anchor and the previous answer's stale cells (facts §4 steps 3–4, §7 #6), but it is [{string.Join(", ", cells)}]";
        }

        if (q.Answer.Loaded is { } loaded && loaded.Count > at && loaded[at])
        {
            return $"the anchor {anchor} names no loaded env cell, but its load flag is true";
        }

        return q.Answer.HitsInteriorCell == false ? $"the anchor {anchor} is indoor by its low word (facts §1.1, §4 step 3), but HitsInteriorCell is false" : null;
    }

    // The closure runs only from a loaded anchor (facts §4 step 4: visible).
    private static bool Visible(CellScene scene, CellId anchor) =>
        anchor.IsIndoorByLowWord ? scene.GetEnvCell(anchor) is not null : anchor.IsLand && scene.IsLoaded(anchor.Landblock);

    // Under a declared ace-neighbour-via-visible-cells a portal neighbour the listed cell does not see is not resolved but
    // added as a load hint under its id (facts §7 #10, §5.1; not walked, no box test) and the filter keeps hints (§4
    // step 5): a listed id that a listed loaded env cell leads to by a portal without seeing it, not reported as loaded.
    // The sphere invariants excuse the same (IndoorInvariants.AceBlindHint).
    private static bool AceBlindHint(ICellPhysics impl, CellScene scene, Query q, int k)
    {
        var id = q.Answer.Cells[k];
        if (!impl.Indoor.AceNeighbourViaVisibleCells || !id.IsEnv || q.Answer.Loaded is { } loaded && k < loaded.Count && loaded[k])
        {
            return false;
        }

        foreach (var c in q.Answer.Cells)
        {
            if (c != id && scene.GetEnvCell(c) is { } e && !e.Sees(id) && LeadsTo(impl, e, id))
            {
                return true;
            }
        }

        // Static placement: the filter may have dropped the cell whose portal added the hint, and keeps the hint (facts
        // §4 step 5: ACE never removes null entries) — so a loaded cell of the scene, listed or not, must lead to the
        // id by a portal without seeing it.
        return q.Filtered && q.Declared.Cells.Any(c => scene.GetEnvCell(c.Id) is { } e && e.Id != id && !e.Sees(id) && LeadsTo(impl, e, id));
    }

    // An env id no loaded cell answers to, other than the anchor, is a load hint (facts §4 step 3, §5.1): the target of
    // a portal of a loaded env cell the closure walked, under ACE's bare 16-bit key when ace-load-hint-low-key is
    // declared (§7 #11). Walked cells are the listed ones; after static placement the filter may have dropped the
    // walker and keeps the hint (§4 step 5), so then any loaded cell of the scene.
    private static bool LoadHint(ICellPhysics impl, CellScene scene, Query q, CellId id)
    {
        var walkers = q.Filtered ? q.Declared.Cells.Select(c => c.Id) : q.Answer.Cells.Where(c => c.IsEnv);
        foreach (var w in walkers)
        {
            if (scene.GetEnvCell(w) is not { } cell)
            {
                continue;
            }

            foreach (var p in cell.Portals)
            {
                var target = w.WithLow(p.OtherCellId);
                var key = impl.Indoor.AceLoadHintLowKey ? new CellId(p.OtherCellId) : target;
                if (key == id && !p.LeadsOutside(impl.Indoor) && (scene.GetEnvCell(target) is null || (impl.Indoor.AceNeighbourViaVisibleCells && !cell.Sees(target))))
                {
                    return true;
                }
            }
        }

        return false;
    }

    // Whether an env cell has a portal (not an exit) whose neighbour is the id.
    private static bool LeadsTo(ICellPhysics impl, EnvCell cell, CellId id)
    {
        foreach (var p in cell.Portals)
        {
            if (!p.LeadsOutside(impl.Indoor) && cell.Id.WithLow(p.OtherCellId) == id)
            {
                return true;
            }
        }

        return false;
    }

    // Static placement from an indoor anchor keeps only the anchor's cell and the loaded cells it sees.
    private static bool Kept(Query q, CellId id) => !q.Filtered || id == q.Parts[0].Cell || (q.AnchorEnv?.Sees(id) ?? false);

    // The part's box (its axis-aligned hull in the cell's frame, as retail computes it) reaches both sides of the plane by more than the band.
    private static bool Crosses(Part part, EnvCell cell, CellPlane plane)
    {
        var box = BoxSide.InFrame(part, cell.Id, cell.Frame);
        float lo = float.PositiveInfinity, hi = float.NegativeInfinity;
        for (int c = 0; c < 8; c++)
        {
            float d = plane.Distance(box.Corner(c));
            lo = MathF.Min(lo, d);
            hi = MathF.Max(hi, d);
        }

        return lo < -Margin && hi > Margin;
    }

    // The part's sphere gate passes on either side: its centre within r − band of the plane (facts §5.2, §5.3: R = r + EPS).
    private static bool Gated(Part part, EnvCell cell, CellPlane plane)
    {
        var c = cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell));
        return MathF.Abs(plane.Distance(c)) < part.Radius - Margin;
    }

    // The part's box in the cell's frame, grown (grow > 0) or shrunk (grow < 0) by |grow| on every side, intersects the cell.
    private static bool Overlaps(Part part, EnvCell cell, float grow)
    {
        var box = BoxSide.InFrame(part, cell.Id, cell.Frame);
        var g = new Vector3(grow);
        var min = box.Min - g;
        var max = box.Max + g;
        return min.X <= max.X && min.Y <= max.Y && min.Z <= max.Z && cell.Volume.BoxIntersects(new Box(min, max));
    }

    // The land cell under the anchor's origin, as the parts add_all_outside_cells seats it (AdjustToOutside).
    private static CellId? LandUnder(Part anchor)
    {
        var column = Oracle.Column(anchor.Cell.WithLow(1), Oracle.Snap(anchor.Frame.Origin.X), Oracle.Snap(anchor.Frame.Origin.Y));
        return column.Ok ? Oracle.CellOf(column.X, column.Y) : null;
    }

    private static LandRect? LandRange(Part[] parts)
    {
        var anchor = parts[0];
        var column = Oracle.Column(anchor.Cell.WithLow(1), Oracle.Snap(anchor.Frame.Origin.X), Oracle.Snap(anchor.Frame.Origin.Y));
        if (!column.Ok)
        {
            return null;
        }

        double lox = 24.0 * column.X, loy = 24.0 * column.Y, hix = lox + 24, hiy = loy + 24;
        var identity = new Frame(Vector3.Zero, Quaternion.Identity);
        foreach (var p in parts)
        {
            // An Always2D part covers the square ±r around its raw origin, not its box (facts §3.4).
            var box = p.Always2D ? Square(p) : BoxSide.InFrame(p, p.Cell, identity);
            double bx = 192.0 * p.Cell.BlockX, by = 192.0 * p.Cell.BlockY;
            lox = Math.Min(lox, bx + box.Min.X);
            loy = Math.Min(loy, by + box.Min.Y);
            hix = Math.Max(hix, bx + box.Max.X);
            hiy = Math.Max(hiy, by + box.Max.Y);
        }

        return new LandRect(lox - Margin, loy - Margin, hix + Margin, hiy + Margin);
    }

    // An Always2D part's square [x − r, x + r] × [y − r, y + r] in its own block frame (z unused).
    private static Box Square(Part p)
    {
        var o = p.Frame.Origin;
        return new Box(new Vector3(o.X - p.Radius, o.Y - p.Radius, o.Z), new Vector3(o.X + p.Radius, o.Y + p.Radius, o.Z));
    }

    private sealed record Query(int Index, Part[] Parts, FindCellResult Answer, EnvCell? AnchorEnv, bool Filtered, IReadOnlySet<CellId>? Stale, Scene Declared);

    private readonly record struct LandRect(double LoX, double LoY, double HiX, double HiY)
    {
        public bool Holds(CellId id)
        {
            if (!Oracle.IsLandCellOnMap(id))
            {
                return false;
            }

            var (gx, gy) = Oracle.LcoordOf(id);
            return !(24.0 * (gx + 1) < LoX || 24.0 * gx > HiX || 24.0 * (gy + 1) < LoY || 24.0 * gy > HiY);
        }
    }
}
