using AcPhys.Core;

namespace AcPhys.Formats.Cases;

/// <summary>One parts / bounding-box query (facts §3.4): the object's parts, the first being the anchor.</summary>
/// <param name="Parts">The parts.</param>
public sealed record PartsCase(IReadOnlyList<Part> Parts)
{
    /// <summary>Formats the query on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => "parts [" + string.Join("; ", Parts.Select(p =>
        $"{p.Cell} o=({FloatText.Format(p.Frame.Origin.X)}, {FloatText.Format(p.Frame.Origin.Y)}, {FloatText.Format(p.Frame.Origin.Z)}) " +
        $"q=({FloatText.Format(p.Frame.Rotation.W)}, {FloatText.Format(p.Frame.Rotation.X)}, {FloatText.Format(p.Frame.Rotation.Y)}, {FloatText.Format(p.Frame.Rotation.Z)}) " +
        $"box=({FloatText.Format(p.Bounds.Min.X)}, {FloatText.Format(p.Bounds.Min.Y)}, {FloatText.Format(p.Bounds.Min.Z)})..({FloatText.Format(p.Bounds.Max.X)}, {FloatText.Format(p.Bounds.Max.Y)}, {FloatText.Format(p.Bounds.Max.Z)})" +
        (p.Always2D ? $" always2d r={FloatText.Format(p.Radius)}" : string.Empty))) + "]";
}
