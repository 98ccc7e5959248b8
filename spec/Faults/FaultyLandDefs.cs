using AcPhys.Core;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A model of the LandDefs math that reproduces one historical defect. It re-states the retail steps of facts §2
/// with the defect in place, so the reference core itself stays free of fault switches.
/// </summary>
internal sealed class FaultyLandDefs : ICellPhysics
{
    private readonly PlantedFault fault;

    public FaultyLandDefs(PlantedFault fault) => this.fault = fault;

    public string Name => "reference+" + fault.Id;

    public Op Ops => Op.LandDefs;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        if (id.IsNone)
        {
            return false;
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

    private bool Is(PlantedFault f) => ReferenceEquals(fault, f);

    private int BlockY(CellId id) => Is(PlantedFaults.SignExtendBlockY) ? (sbyte)id.BlockY : id.BlockY;

    private bool InBounds(int x, int y) => Is(PlantedFaults.MapEdge2040)
        ? x >= 0 && y >= 0 && x <= LandDefs.LandLength && y <= LandDefs.LandLength
        : LandDefs.InBounds(x, y);

    private float Rebase(float v) => Is(PlantedFaults.DropBlockLength)
        ? (float)(v - Math.Floor(v / 192.0))
        : (float)(v - (192.0 * Math.Floor(v / 192.0)));
}
