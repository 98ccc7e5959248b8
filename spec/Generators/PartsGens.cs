using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>Generators for parts queries: 1–4 parts near cell and block lines, arbitrary rotations, boxes from 5 cm to 30 m, some Always2D.</summary>
public static class PartsGens
{
    private static Gen<float> Half => Gen.Frequency((3, Gen.Choose(50, 3000).Select(i => i / 1000f)), (1, Gen.Choose(3000, 15000).Select(i => i / 1000f)));

    private static Gen<Quaternion> Rotations => Gen.Frequency(
        (1, Gen.Constant(Quaternion.Identity)),
        (1, Gen.Choose(0, 359).Select(d => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, d * MathF.PI / 180f))),
        (2, Gen.Zip(Gen.Zip(Gen.Choose(-1000, 1000), Gen.Choose(-1000, 1000)), Gen.Zip(Gen.Choose(-1000, 1000), Gen.Choose(1, 1000)))
            .Select(t => Quaternion.Normalize(new Quaternion(t.Item1.Item1, t.Item1.Item2, t.Item2.Item1, t.Item2.Item2)))));

    private static Gen<Part> PartsIn(CellId cell) =>
        Gen.Zip(Gen.Zip(OutdoorGens.Coordinates, OutdoorGens.Coordinates), Gen.Zip(Rotations, Gen.Zip(Gen.Zip(Half, Half), Gen.Zip(Half, Gen.Choose(0, 4)))))
            .Select(t => new Part(
                cell,
                new Frame(new Vector3(t.Item1.Item1, t.Item1.Item2, 0.5f), t.Item2.Item1),
                new Box(new Vector3(-t.Item2.Item2.Item1.Item1, -t.Item2.Item2.Item1.Item2, -t.Item2.Item2.Item2.Item1), new Vector3(t.Item2.Item2.Item1.Item1, t.Item2.Item2.Item1.Item2, t.Item2.Item2.Item2.Item1)),
                t.Item2.Item2.Item1.Item1,
                t.Item2.Item2.Item2.Item2 == 0));

    /// <summary>Gets parts queries (all parts in one block frame).</summary>
    public static Gen<PartsCase> Cases { get; } =
        Gen.Zip(OutdoorGens.Cells, Gen.Choose(1, 4)).SelectMany(t => Gen.ArrayOf(PartsIn(t.Item1), t.Item2).Select(p => new PartsCase(p)));

    /// <summary>Gets the arbitrary: drop parts, then simplify each part's rotation, origin, box and radius.</summary>
    public static Arbitrary<PartsCase> Arbitrary { get; } = Arb.From(Cases, Shrink);

    /// <summary>Returns simpler queries: each part but the anchor dropped, then per part no rotation, simpler x, y, box corners and radius.</summary>
    /// <param name="c">The query.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<PartsCase> Shrink(PartsCase c)
    {
        for (int i = c.Parts.Count - 1; i >= 1; i--)
        {
            yield return new PartsCase([.. c.Parts.Take(i), .. c.Parts.Skip(i + 1)]);
        }

        for (int i = 0; i < c.Parts.Count; i++)
        {
            var p = c.Parts[i];
            if (p.Frame.Rotation != Quaternion.Identity)
            {
                yield return With(c, i, p with { Frame = p.Frame with { Rotation = Quaternion.Identity } });
            }

            foreach (var x in Snap.Simpler(p.Frame.Origin.X))
            {
                yield return With(c, i, p with { Frame = p.Frame with { Origin = p.Frame.Origin with { X = x } } });
            }

            foreach (var y in Snap.Simpler(p.Frame.Origin.Y))
            {
                yield return With(c, i, p with { Frame = p.Frame with { Origin = p.Frame.Origin with { Y = y } } });
            }

            foreach (var box in SimplerBoxes(p.Bounds))
            {
                yield return With(c, i, p with { Bounds = box });
            }

            foreach (var r in Snap.Simpler(p.Radius).Where(r => r >= 0))
            {
                yield return With(c, i, p with { Radius = r });
            }
        }
    }

    // Each box corner component made simpler while min ≤ max holds (z first: it only matters through a rotation).
    private static IEnumerable<Box> SimplerBoxes(Box b)
    {
        for (int axis = 2; axis >= 0; axis--)
        {
            foreach (var v in Snap.Simpler(b.Min[axis]).Where(v => v <= b.Max[axis]))
            {
                yield return b with { Min = WithComponent(b.Min, axis, v) };
            }

            foreach (var v in Snap.Simpler(b.Max[axis]).Where(v => v >= b.Min[axis]))
            {
                yield return b with { Max = WithComponent(b.Max, axis, v) };
            }
        }
    }

    private static Vector3 WithComponent(Vector3 v, int axis, float value) => axis switch
    {
        0 => v with { X = value },
        1 => v with { Y = value },
        _ => v with { Z = value },
    };

    private static PartsCase With(PartsCase c, int i, Part p)
    {
        var parts = c.Parts.ToArray();
        parts[i] = p;
        return new PartsCase(parts);
    }
}
