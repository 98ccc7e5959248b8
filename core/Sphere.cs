using System.Numerics;

namespace AcPhys.Core;

/// <summary>A sphere: centre (metres, in some block frame) and radius (metres).</summary>
/// <param name="Center">Centre, in the block frame of the position it belongs to (facts §0).</param>
/// <param name="Radius">Radius, metres, ≥ 0.</param>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly record struct Sphere(Vector3 Center, float Radius);
