using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Faults;

/// <summary>How a port with a frame fault of <see cref="PartsFrameFaults"/> or <see cref="PartsObjectFaults"/> reads the parts it is asked about.</summary>
internal static class PartsMisread
{
    /// <summary>Returns the parts as the faulty port reads them.</summary>
    /// <param name="parts">The parts as asked.</param>
    /// <param name="fault">The fault.</param>
    /// <returns>The parts read.</returns>
    public static Part[] Read(IReadOnlyList<Part> parts, PlantedFault fault)
    {
        var read = new Part[parts.Count];
        for (int k = 0; k < read.Length; k++)
        {
            var p = parts[k];
            read[k] = fault == PartsFrameFaults.RotationInverted ? p with { Frame = p.Frame with { Rotation = Quaternion.Conjugate(p.Frame.Rotation) } }
                : fault == PartsFrameFaults.YawOnly ? p with { Frame = p.Frame with { Rotation = PartShapes.Heading(p.Frame.Rotation) } }
                : fault == PartsFrameFaults.BoxCentred ? p with { Bounds = PartShapes.Centred(p.Bounds) }
                : fault == PartsFrameFaults.AnchorFrame ? p with { Cell = parts[0].Cell }
                : PartsObjectFaults.Misread(parts, p, fault);
        }

        return read;
    }
}
