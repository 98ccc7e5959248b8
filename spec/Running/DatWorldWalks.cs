using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Running;

/// <summary>One walk through a real scene: the cell it starts in, the portal it heads for, and the walk.</summary>
/// <param name="Cell">The env cell the walk starts in.</param>
/// <param name="Portal">The index of the portal it walks through.</param>
/// <param name="Walk">The walk.</param>
public sealed record DatWorldWalk(CellId Cell, int Portal, Walk Walk)
{
    /// <summary>Names the walk in findings.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"from {Cell} through portal {Portal}";
}

/// <summary>
/// Walks through a scene read from a dat world (docs/dat-container.md "The gate over a dat world"): from the centre of
/// every kept env cell's first piece, on its floor, straight through each portal whose plane is not horizontal, to
/// <see cref="Beyond"/> metres past it, in steps of a quarter metre; a body of two spheres of radius 0.5. Deterministic.
/// </summary>
public static class DatWorldWalks
{
    /// <summary>How far past the portal plane a walk ends, metres.</summary>
    public const float Beyond = 2f;

    /// <summary>The step length, metres.</summary>
    public const float Step = 0.25f;

    /// <summary>The most steps of one walk.</summary>
    public const int MaxSteps = 128;

    private static readonly BodySphere[] Body = [new(new Vector3(0, 0, 0.6f), 0.5f), new(new Vector3(0, 0, 1.3f), 0.5f)];

    /// <summary>Builds the walks of a scene.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The walks, cells in scene order, portals in order.</returns>
    public static IEnumerable<DatWorldWalk> Of(Scene scene)
    {
        foreach (var cell in scene.Cells)
        {
            var piece = cell.Pieces[0].ToConvex();
            var centre = piece.Vertices.Aggregate(Vector3.Zero, (a, v) => a + v) / piece.Vertices.Count;
            float floor = piece.Vertices.Min(v => v.Z);
            for (int i = 0; i < cell.Portals.Count; i++)
            {
                var plane = cell.Portals[i].Plane;
                float side = Vector3.Dot(plane.Normal, centre) + plane.D;
                var through = Vector3.Transform(plane.Normal * -MathF.Sign(side), cell.Rotation); // from the centre towards the plane, block frame
                var flat = new Vector2(through.X, through.Y);
                if (side == 0 || flat.Length() < 0.5f)
                {
                    continue; // a floor or ceiling portal, or a centre on the plane: no horizontal walk through it
                }

                var start = cell.Origin + Vector3.Transform(centre with { Z = floor }, cell.Rotation);
                float distance = (MathF.Abs(side) / flat.Length()) + Beyond;
                int n = Math.Min(MaxSteps, (int)MathF.Ceiling(distance / Step));
                var step = Vector2.Normalize(flat) * Step;
                yield return new DatWorldWalk(cell.Id, i, new Walk(cell.Id, start, Body, [.. Enumerable.Repeat(step, n)]));
            }
        }
    }
}
