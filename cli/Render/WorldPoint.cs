namespace AcPhys.Cli.Render;

/// <summary>A point on the world map: metres east and north of the map's south-west corner (192 m per landblock).</summary>
/// <param name="X">Metres east.</param>
/// <param name="Y">Metres north.</param>
internal readonly record struct WorldPoint(double X, double Y)
{
    /// <summary>Gets the distance to another point.</summary>
    /// <param name="other">The other point.</param>
    /// <returns>Metres.</returns>
    public double DistanceTo(WorldPoint other) => Math.Sqrt(((X - other.X) * (X - other.X)) + ((Y - other.Y) * (Y - other.Y)));
}
