using System.Numerics;

namespace AcPhys.Core;

/// <summary>A frame: origin (metres, in a block frame) and a unit rotation (facts §5.8).</summary>
/// <param name="Origin">The origin.</param>
/// <param name="Rotation">A unit quaternion (W, X, Y, Z as stored in the dat files).</param>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly record struct Frame(Vector3 Origin, Quaternion Rotation)
{
    /// <summary>Gets the identity frame at the origin.</summary>
    public static Frame Identity => new(Vector3.Zero, Quaternion.Identity);

    /// <summary>Maps a frame-local point to the enclosing frame: origin + R·p (AFrame.LocalToGlobal).</summary>
    /// <param name="p">A local point.</param>
    /// <returns>The point in the enclosing frame.</returns>
    public Vector3 LocalToGlobal(Vector3 p) => Origin + Vector3.Transform(p, Rotation);

    /// <summary>Maps an enclosing-frame point to this frame: Rᵀ·(p − origin) (AFrame.GlobalToLocal).</summary>
    /// <param name="p">A point in the enclosing frame.</param>
    /// <returns>The local point.</returns>
    public Vector3 GlobalToLocal(Vector3 p) => Vector3.Transform(p - Origin, Quaternion.Conjugate(Rotation));
}
