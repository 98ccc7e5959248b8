using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

// A cell's portals with the cell's own side read from the geometry, not from PortalSide.
internal static partial class IndoorInvariants
{
    // A cell's portals with their planes normalised and the cell's own side read from the geometry (piece 0's box
    // centre), not from PortalSide, so a fault in PortalSide cannot hide itself from the invariants that use this.
    private static IEnumerable<OutwardPortal> Outward(SceneCell cell)
    {
        var frame = new Frame(cell.Origin, cell.Rotation);
        var bounds = cell.Pieces[0].ToConvex().Bounds;
        var middle = (bounds.Min + bounds.Max) / 2;
        foreach (var portal in cell.Portals)
        {
            var plane = new CellPlane(Vector3.Normalize(portal.Plane.Normal), portal.Plane.D / portal.Plane.Normal.Length());
            yield return new OutwardPortal(portal, plane, Math.Sign(plane.Distance(middle)), frame);
        }
    }

    private readonly record struct OutwardPortal(ScenePortal Portal, CellPlane Plane, double OwnSide, Frame Frame)
    {
        // How far a global point lies past the portal's plane, away from the cell (negative: on the cell's side).
        public double Past(Vector3 global) => -OwnSide * Plane.Distance(Frame.GlobalToLocal(global));
    }
}
