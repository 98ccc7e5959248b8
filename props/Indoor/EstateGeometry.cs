using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>The geometry of generated estates fits together: shared walls, partner portals, building portals, ids, pieces.</summary>
public sealed class EstateGeometry(ITestOutputHelper output)
{
    private const int Count = 400;

    private static readonly IReadOnlyList<SceneWalk> Walks =
        [.. Gen.Sample(EstateGens.Recipes, Count, new Rnd(0x5EED_E57A7EUL, 0x9E3779B97F4A7C15UL), 20).Select(r => r.Build())];

    [Fact(DisplayName = "A portal's plane in its owner's frame and its partner's plane in the partner's frame are one world plane (within 1e-4)")]
    public void PortalPlanesMeet()
    {
        foreach (var w in Walks)
        {
            foreach (var cell in w.Scene.Cells)
            {
                foreach (var p in cell.Portals.Where(p => !p.IsExit))
                {
                    if (w.Scene.Cells.FirstOrDefault(c => c.Id == cell.Id.WithLow(p.Other)) is not { } other)
                    {
                        continue; // an unloaded neighbour
                    }

                    // A point of the owner's plane near the owner, in the block; its distance to the partner's plane
                    // in the partner's frame (float32 block coordinates: compare where the cells are, not at the origin).
                    var n = Vector3.Normalize(p.Plane.Normal);
                    var centre = cell.Pieces[0].ToConvex().Bounds is var b ? (b.Min + b.Max) / 2 : default;
                    var onPlane = centre - (n * (Vector3.Dot(p.Plane.Normal, centre) + p.Plane.D) / p.Plane.Normal.Length());
                    var world = new Frame(cell.Origin, cell.Rotation).LocalToGlobal(onPlane);
                    var q = other.Portals[p.OtherPortal].Plane;
                    var otherFrame = new Frame(other.Origin, other.Rotation);
                    double d = q.Distance(otherFrame.GlobalToLocal(world)) / q.Normal.Length();
                    var n1 = Vector3.Transform(n, cell.Rotation);
                    var n2 = Vector3.Transform(Vector3.Normalize(q.Normal), other.Rotation);
                    Assert.True(Math.Abs(d) < 1e-4 && Math.Abs(Math.Abs(Vector3.Dot(n1, n2)) - 1) < 1e-4, $"{cell.Id} portal → {other.Id}: {d} off, normals {n1} {n2} in {w.Recipe}");
                }
            }
        }
    }

    [Fact(DisplayName = "Partner portal indices point back: the other cell's portal names this cell and this portal")]
    public void PartnersPointBack()
    {
        foreach (var w in Walks)
        {
            foreach (var cell in w.Scene.Cells)
            {
                for (int i = 0; i < cell.Portals.Count; i++)
                {
                    var p = cell.Portals[i];
                    if (!p.IsExit && w.Scene.Cells.FirstOrDefault(c => c.Id == cell.Id.WithLow(p.Other)) is { } other)
                    {
                        var back = other.Portals[p.OtherPortal];
                        Assert.Equal(cell.Id.Low, back.Other);
                        Assert.Equal(i, back.OtherPortal);
                    }
                }
            }
        }
    }

    [Fact(DisplayName = "A building portal names a cell of the building's block and, unless invalid, one of that cell's exits")]
    public void BuildingPortalsNameExits()
    {
        foreach (var w in Walks)
        {
            foreach (var b in w.Scene.Buildings)
            {
                foreach (var bp in b.Portals)
                {
                    var id = b.Block.BlockCell.WithLow(bp.Cell);
                    var cell = w.Scene.Cells.FirstOrDefault(c => c.Id == id);
                    Assert.NotNull(cell);
                    Assert.True(bp.Portal == 0xFFFF || cell.Portals[bp.Portal].IsExit, $"{id} portal {bp.Portal}");
                }

                Assert.Contains(b.Portals, bp => bp.Portal != 0xFFFF); // a valid way in
            }
        }
    }

    [Fact(DisplayName = "Env ids are unique in a scene and every building's cells sit in its own block")]
    public void IdsAreUnique()
    {
        foreach (var w in Walks)
        {
            var ids = w.Scene.Cells.Select(c => c.Id).Concat(w.Scene.UnloadedCells).ToList();
            Assert.Equal(ids.Count, ids.Distinct().Count());
            Assert.All(ids, id => Assert.True(id.IsEnv));
        }
    }

    [Fact(DisplayName = "The pieces of a multi-piece cell touch: each further piece shares a face or volume with piece 0")]
    public void PiecesTouch()
    {
        int multi = 0;
        foreach (var cell in Walks.SelectMany(w => w.Scene.Cells).Where(c => c.Pieces.Count > 1))
        {
            multi++;
            var a = cell.Pieces[0].Box!.Value;
            foreach (var piece in cell.Pieces.Skip(1))
            {
                var b = piece.Box!.Value;
                var lo = Vector3.Max(a.Min, b.Min);
                var hi = Vector3.Min(a.Max, b.Max);
                Assert.True(lo.X <= hi.X + 1e-4f && lo.Y <= hi.Y + 1e-4f && lo.Z <= hi.Z + 1e-4f, $"{cell.Id}: {a} and {b} are apart");
            }
        }

        Assert.True(multi > 0);
    }

    [Fact(DisplayName = "Estate walks hit every estate class (the distribution is printed)")]
    public void ClassesAreHit()
    {
        var counts = EstateClasses.All.ToDictionary(t => t, _ => 0);
        foreach (var w in Walks)
        {
            foreach (var tag in SceneDomain.Instance.Classes(w).Where(counts.ContainsKey))
            {
                counts[tag]++;
            }
        }

        foreach (var (tag, n) in counts)
        {
            output.WriteLine($"{tag,-28} {n,5} of {Count}");
        }

        Assert.All(counts, kv => Assert.True(kv.Value > 0, $"{kv.Key} never hit"));
    }
}
