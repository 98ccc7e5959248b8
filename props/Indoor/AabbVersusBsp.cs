using System.Numerics;
using AcPhys.Core;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// Fidelity: the ACME editor's AABB cells against retail's positive-chain BSP (facts §5.7), by room shape. Points are
/// drawn in each room's box grown by 0.5 m, in a random frame; points within 1 cm of a piece plane (the two modes'
/// tolerances, EPS and 0.01) are not counted. The disagreement rate is reported; it is 0 for box rooms.
/// </summary>
public sealed class AabbVersusBsp(ITestOutputHelper output)
{
    private const int Samples = 20_000;

    public static TheoryData<string> Shapes => new(["box", "l-shape", "stairs"]);

    [Theory(DisplayName = "AABB vs BSP: point_in_cell disagreement rate by room shape (0 for boxes)")]
    [MemberData(nameof(Shapes))]
    public void DisagreementByShape(string shape)
    {
        var random = new Random(0xACE + shape.Length);
        int counted = 0, differ = 0, bspMissesUnion = 0, aabbOverUnion = 0;
        for (int room = 0; room < 50; room++)
        {
            float w = 3 + (6 * random.NextSingle()), d = 3 + (6 * random.NextSingle());
            var pieces = Pieces(shape, w, d);
            var bsp = new CellBsp(pieces);
            var aabb = new CellAabb(pieces);
            var rotation = Quaternion.Normalize(new Quaternion(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
            var frame = new Frame(new Vector3(100 * random.NextSingle(), 100 * random.NextSingle(), 0), rotation);
            var lo = bsp.Bounds.Min - new Vector3(0.5f);
            var hi = bsp.Bounds.Max + new Vector3(0.5f);
            for (int i = 0; i < Samples / 50; i++)
            {
                var local = lo + ((hi - lo) * new Vector3(random.NextSingle(), random.NextSingle(), random.NextSingle()));
                var p = frame.GlobalToLocal(frame.LocalToGlobal(local)); // the round trip a query does
                if (pieces.Any(piece => piece.Planes.Any(pl => MathF.Abs(pl.Distance(p)) < 0.01f)))
                {
                    continue;
                }

                counted++;
                bool inBsp = bsp.PointInside(p), inAabb = aabb.PointInside(p), inUnion = pieces.Any(piece => piece.Contains(p));
                differ += inBsp != inAabb ? 1 : 0;
                bspMissesUnion += inUnion && !inBsp ? 1 : 0;
                aabbOverUnion += !inUnion && inAabb ? 1 : 0;
            }
        }

        double rate = (double)differ / counted;
        output.WriteLine($"{shape}: {counted} points, AABB≠BSP {differ} ({rate:P2}); BSP misses the union {bspMissesUnion}; AABB covers beyond the union {aabbOverUnion}");
        if (shape == "box")
        {
            Assert.Equal(0, differ);
        }
        else
        {
            Assert.True(differ > 0, $"{shape}: the modes should disagree somewhere (the union is not a box)");
        }
    }

    private static ConvexPiece[] Pieces(string shape, float w, float d) => shape switch
    {
        "box" => [ConvexPiece.FromBox(Vector3.Zero, new Vector3(w, d, 3))],
        "l-shape" => [ConvexPiece.FromBox(Vector3.Zero, new Vector3(w, d / 2, 3)), ConvexPiece.FromBox(Vector3.Zero, new Vector3(w / 2, d, 3))],
        _ =>
        [
            ConvexPiece.FromBox(Vector3.Zero, new Vector3(w, d, 1)),
            ConvexPiece.FromBox(new Vector3(w / 3, 0, 0), new Vector3(w, d, 2)),
            ConvexPiece.FromBox(new Vector3(2 * w / 3, 0, 0), new Vector3(w, d, 3)),
        ],
    };
}
