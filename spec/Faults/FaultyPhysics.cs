using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A model of the cell math that reproduces one historical defect. It re-states the retail steps of facts §2–§4
/// with the defect in place, so the reference core itself stays free of fault switches. With a defect that does
/// not touch a step, the step behaves as the reference (a differential test checks the model against core).
/// </summary>
internal sealed class FaultyPhysics : ICellPhysics
{
    private readonly PlantedFault[] faults;
    private readonly List<CellId> stale = [];
    private int inherited;

    public FaultyPhysics(params PlantedFault[] faults) => this.faults = faults;

    public string Name => "reference+" + string.Join("+", faults.Select(f => f.Id));

    public Op Ops => Op.OpenLand;

    // no-hysteresis declares the current-first policy but implements the retail rule.
    public PickPolicy Pick => Is(PlantedFaults.NoHysteresis) ? PickPolicy.CurrentFirst : PickPolicy.Retail;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        if (id.IsNone)
        {
            return Is(PlantedFaults.BlockIdZeroOk); // ACE: (0, 0) ok (facts §7 #16); lcoord is (0, 0) already
        }

        int x = id.BlockX * 8, y = BlockY(id) * 8;
        if (x >= LandDefs.LandLength || y >= LandDefs.LandLength)
        {
            return false;
        }

        lcoord = new Lcoord(x, y);
        return true;
    }

    public bool InboundValidCellId(CellId id) =>
        LandDefs.CellInRange(id.Low)
        && id.BlockX * 8 < LandDefs.LandLength
        && (Is(PlantedFaults.InboundXOnly) || BlockY(id) * 8 < LandDefs.LandLength);

    public bool GidToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        if (!InboundValidCellId(id) || id.Low >= LandDefs.FirstEnvCellId)
        {
            return false;
        }

        int x = (id.BlockX * 8) + ((id.Low - 1) >> 3), y = (BlockY(id) * 8) + ((id.Low - 1) & 7);
        if (!InBounds(x, y))
        {
            return false;
        }

        lcoord = new Lcoord(x, y);
        return true;
    }

    public CellId LcoordToGid(int x, int y) =>
        InBounds(x, y) ? new CellId((uint)(((x >> 3) << 24) | ((y >> 3) << 16) | (1 + ((x & 7) << 3) + (y & 7)))) : CellId.None;

    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord)
    {
        lcoord = default;
        if (!LandDefs.CellInRange(id.Low) || !BlockIdToLcoord(id, out var block))
        {
            return false;
        }

        double cx = Is(PlantedFaults.TruncFloor) ? Math.Truncate(x / 24.0) : Math.Floor(x / 24.0);
        double cy = Is(PlantedFaults.TruncFloor) ? Math.Truncate(y / 24.0) : Math.Floor(y / 24.0);
        if (Is(PlantedFaults.CheckedCast))
        {
            int gx = checked(block.X + (int)cx), gy = checked(block.Y + (int)cy); // the defect: NaN, ±∞, huge throw
            if (!InBounds(gx, gy))
            {
                return false;
            }

            lcoord = new Lcoord(gx, gy);
            return true;
        }

        if (Is(PlantedFaults.NanAsZero))
        {
            int gx = (int)(block.X + cx), gy = (int)(block.Y + cy); // NaN → 0 on .NET 9+: the defect
            if (!InBounds(gx, gy))
            {
                return false;
            }

            lcoord = new Lcoord(gx, gy);
            return true;
        }

        double dx = block.X + cx, dy = block.Y + cy;
        if (!(dx >= 0 && dy >= 0 && dx <= int.MaxValue && dy <= int.MaxValue) || !InBounds((int)dx, (int)dy))
        {
            return false;
        }

        lcoord = new Lcoord((int)dx, (int)dy);
        return true;
    }

    public AdjustResult AdjustToOutside(CellId id, float x, float y)
    {
        if (!LandDefs.CellInRange(id.Low))
        {
            return new AdjustResult(false, CellId.None, x, y);
        }

        if (!Is(PlantedFaults.NoEpsSnap))
        {
            x = Math.Abs(x) < LandDefs.Epsilon ? 0f : x;
            y = Math.Abs(y) < LandDefs.Epsilon ? 0f : y;
        }

        if (!GetOutsideLcoord(id, x, y, out var lc))
        {
            return new AdjustResult(false, CellId.None, x, y);
        }

        return new AdjustResult(true, LcoordToGid(lc.X, lc.Y), Rebase(x), Rebase(y));
    }

    private bool Is(PlantedFault f) => Array.IndexOf(faults, f) >= 0;

    private int BlockY(CellId id) => Is(PlantedFaults.SignExtendBlockY) ? (sbyte)id.BlockY : id.BlockY;

    private bool InBounds(int x, int y) => Is(PlantedFaults.MapEdge2040)
        ? x >= 0 && y >= 0 && x <= LandDefs.LandLength && y <= LandDefs.LandLength
        : LandDefs.InBounds(x, y);

    private float Rebase(float v) => Is(PlantedFaults.DropBlockLength)
        ? (float)(v - Math.Floor(v / 192.0))
        : (float)(v - (192.0 * Math.Floor(v / 192.0)));

    // The parts variant has no planted defect of its own here: it answers as core (ace-same-block-guard is core's ACE option).
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => ReferenceAdapter.Instance.OutsideCellsParts(parts);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, System.Numerics.Vector3.Zero, spheres);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        var cells = NewArray();
        AddAllOutsideCells(cells, cell, origin, spheres);
        return cells;
    }

    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, System.Numerics.Vector3.Zero, spheres, current);

    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current)
    {
        if (!cell.IsLand)
        {
            // An env, block-id or id-0 position is seeded as itself and has no pick on open land (facts §4 step 3);
            // env-position-contains answers it as its own containing cell with no candidates.
            return Is(PlantedFaults.EnvPositionContains)
                ? new FindCellResult([], cell)
                : new ReferenceAdapter(Pick).FindCell(cell, origin, spheres, current);
        }

        var cells = NewArray();
        AddAllOutsideCells(cells, cell, origin, spheres);
        var containing = CellId.None;
        if (spheres.Count > 0 && Is(PlantedFaults.StickyPick) && current.IsLand && cells.Contains(current)
            && ContainingCell.LandCellContains(current, spheres[0].Center - LandDefs.GetBlockOffset(cell, current)))
        {
            return new FindCellResult(cells, current); // sticky-pick: current-first behaviour behind a retail declaration
        }

        if (spheres.Count > 0)
        {
            foreach (var id in cells)
            {
                if (Is(PlantedFaults.Clamp106) && (id.Value >> 16) != (cell.Value >> 16))
                {
                    continue; // #106: the pick, too, only looked at the current block's 8 × 8 grid
                }

                if (id.IsLand && ContainingCell.LandCellContains(id, spheres[0].Center - LandDefs.GetBlockOffset(cell, id)))
                {
                    containing = id;
                    if (Is(PlantedFaults.FirstHitOutdoorPick))
                    {
                        break; // the defect: retail's outdoor hits do not stop the scan (facts §4 step 4b)
                    }
                }
            }
        }

        return new FindCellResult(cells, containing);
    }

    // no-reset: the array keeps the previous query's cells (ACE's find_cell_list, facts §7 #6). Only the previous
    // query's own cells are carried, as within one short ACE transition, so the model stays bounded.
    private List<CellId> NewArray()
    {
        inherited = Is(PlantedFaults.NoReset) ? stale.Count : 0;
        return Is(PlantedFaults.NoReset) ? [.. stale] : [];
    }

    private void AddAllOutsideCells(List<CellId> cells, CellId position, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        if (Is(PlantedFaults.SphereGuardInverted) ? spheres.Count != 0 : spheres.Count == 0)
        {
            if (Is(PlantedFaults.NoSphereNoCell))
            {
                return; // the defect: the sphere loop ran zero times and nothing else was added
            }

            var only = Is(PlantedFaults.NoSphereOriginIgnored) ? AdjustToOutside(position, 0f, 0f) : AdjustToOutside(position, origin.X, origin.Y);
            if (only.Ok && GidToLcoord(only.Cell, out var lc))
            {
                AddOutsideCell(cells, position, lc.X, lc.Y);
            }

            Remember(cells);
            return;
        }

        var carried = position;
        foreach (var sphere in spheres)
        {
            var start = Is(PlantedFaults.SphereLeak) ? carried : position;
            var r = AdjustToOutside(start, sphere.Center.X, sphere.Center.Y);
            if (!r.Ok)
            {
                break;
            }

            carried = r.Cell;
            float ptX = (float)(r.X - (24.0 * Math.Floor(r.X / 24.0)));
            float ptY = (float)(r.Y - (24.0 * Math.Floor(r.Y / 24.0)));
            GidToLcoord(r.Cell, out var lc);
            AddOutsideCell(cells, position, lc.X, lc.Y);
            CheckAddCellBoundary(cells, position, r.Cell, ptX, ptY, lc, sphere.Radius, 24f - sphere.Radius);
        }

        Remember(cells);
    }

    private void Remember(List<CellId> cells)
    {
        if (Is(PlantedFaults.NoReset))
        {
            var fresh = cells.Skip(inherited).ToList();
            stale.Clear();
            stale.AddRange(fresh);
        }
    }

    private void CheckAddCellBoundary(List<CellId> cells, CellId position, CellId cell, float ptX, float ptY, Lcoord lc, float minRad, float maxRad)
    {
        if (Is(PlantedFaults.TouchInclusive))
        {
            // The defect: >= / <= for retail's strict tests (facts §3.2). Moving the limits by one ulp inward makes
            // every strict test below inclusive for the float32 values it sees.
            minRad = MathF.BitIncrement(minRad);
            maxRad = MathF.BitDecrement(maxRad);
        }

        void Add(int dx, int dy)
        {
            if (Is(PlantedFaults.InCellNeighbours))
            {
                // Early ACE: neighbours from the in-block cell index, so nothing across a block line.
                int cx = ((cell.Low - 1) >> 3) + dx, cy = ((cell.Low - 1) & 7) + dy;
                if (cx is < 0 or > 7 || cy is < 0 or > 7)
                {
                    return;
                }
            }

            AddOutsideCell(cells, position, lc.X + dx, lc.Y + dy);
        }

        if (ptX > maxRad)
        {
            Add(1, 0);
            if (ptY > maxRad)
            {
                Add(1, 1);
            }

            if (ptY < minRad)
            {
                Add(1, -1);
            }
        }

        // else-diagonal: an early ACE revision made this an else branch, so with r > 12 only one side is added.
        if (ptX < minRad && !(Is(PlantedFaults.ElseDiagonal) && ptX > maxRad))
        {
            Add(-1, 0);
            if (ptY > maxRad)
            {
                Add(-1, 1);
            }

            if (ptY < minRad)
            {
                Add(-1, -1);
            }
        }

        if (ptY > maxRad)
        {
            Add(0, 1);
        }

        if (ptY < minRad)
        {
            Add(0, -1);
        }
    }

    private void AddOutsideCell(List<CellId> cells, CellId position, int x, int y)
    {
        if (!InBounds(x, y))
        {
            return;
        }

        var id = LcoordToGid(x, y);
        if (Is(PlantedFaults.Clamp106) && (id.Value >> 16) != (position.Value >> 16))
        {
            return; // #106: candidates clamped to the current landblock
        }

        if (!cells.Contains(id))
        {
            cells.Add(id);
        }
    }
}
