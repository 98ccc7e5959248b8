using AcPhys.Core;

namespace AcPhys.Spec.Adapters;

/// <summary>The bundled reference core (AcPhys.Core) behind the adapter contract.</summary>
public sealed class ReferenceAdapter : ICellPhysics
{
    /// <summary>Gets the shared instance (the adapter is stateless).</summary>
    public static ReferenceAdapter Instance { get; } = new();

    /// <inheritdoc/>
    public string Name => "reference";

    /// <inheritdoc/>
    public Op Ops => Op.LandDefs;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => LandDefs.BlockIdToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => LandDefs.GidToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => LandDefs.LcoordToGid(x, y);

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => LandDefs.InboundValidCellId(id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => LandDefs.GetOutsideLcoord(id, x, y, out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y)
    {
        bool ok = LandDefs.AdjustToOutside(ref id, ref x, ref y);
        return new AdjustResult(ok, id, x, y);
    }
}
