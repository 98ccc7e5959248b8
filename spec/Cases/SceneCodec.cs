using System.Buffers.Binary;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Turns any bytes into a bounded <see cref="SceneRecipe"/> (and so a valid scene and walk), so that every fuzzer input
/// reaches the indoor physics, never a parser. Total: any byte string (empty included) decodes, never throws; the
/// recipe stays inside <see cref="SceneGens"/>' domain (cottages of 1–4 rooms or dungeon chains of 2–5 cells, at most
/// <see cref="MaxSteps"/> steps), widened only in where a cottage may stand inside its block.
/// </summary>
/// <remarks>
/// <para>Layout, <see cref="Length"/> bytes (missing bytes read as zero, extra bytes are ignored):
/// <c>shape rooms|cells width|length depth|unloaded yawMode yaw:u16 flips flags place p1 p2 p3 p4 route target radius body take</c>.</para>
/// <para><c>shape % 7</c> below 5 is a cottage, else a dungeon. Cottage: <c>1 + rooms % 4</c> rooms of
/// <c>(16 + b % 17) / 4</c> m; <c>yawMode % 6</c>: 0–2 no yaw, 3 a quarter turn <c>yaw % 4</c>, 4–5 one of 1024 angles
/// (<c>yaw % 1024</c>); flags bit 0 back door, bit 1 storey, bit 2 the eight neighbour blocks unloaded; route
/// <c>route % 6</c> (<see cref="SceneRoute"/> Enter … Storey; Through forces the back door, Storey the storey);
/// target <c>target % rooms</c>. Dungeon: <c>2 + cells % 4</c> cells of <c>(16 + b % 25) / 4</c> m,
/// <c>unloaded % (min(2, cells − 1) + 1)</c> unloaded tail cells, route run or run-and-back (<c>route % 2</c>).</para>
/// <para>Placement, <c>place % 8</c>: 0–2 anywhere (block bytes <c>1 + p % 253</c>, whole metres 0–191 in the block,
/// so a building may cross any of the block's lines), 3–6 straddling a block line (3–4 the north one, 5–6 the east
/// one: <c>1 + p3 % max(2, extent)</c> m short of it, <c>16 + p4 % 145</c> m along it), 7 at the map edge
/// (<c>p1</c> bit 0 east, else west; <c>3 + p3 % 10</c> m from it). Body: radius <c>(12 + radius % 21) / 32</c> m,
/// <c>body</c> bit 0 a second sphere, <c>(body &gt;&gt; 1) % 3</c> the step as ¼, ½ or 1 radius,
/// <c>(body &gt;&gt; 3) % 3</c> the jitter (<see cref="SceneGens.Jitters"/>). <c>take</c> 0 keeps the first <see cref="MaxSteps"/>
/// steps, else the first <c>min(take, MaxSteps)</c>.</para>
/// </remarks>
public static class SceneCodec
{
    /// <summary>Length of one encoded recipe.</summary>
    public const int Length = 19;

    /// <summary>Most steps a decoded walk has.</summary>
    public const int MaxSteps = 128;

    private static readonly float[] StepFractions = [0.25f, 0.5f, 1f];

    /// <summary>Decodes bytes into a recipe.</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The recipe (its <see cref="SceneRecipe.Build"/> gives the scene walk).</returns>
    public static SceneRecipe Decode(ReadOnlySpan<byte> data)
    {
        Span<byte> b = stackalloc byte[Length];
        b.Clear();
        data[..Math.Min(data.Length, Length)].CopyTo(b);

        bool cottage = b[0] % 7 < 5;
        float radius = (12 + (b[16] % 21)) / 32f;
        bool two = (b[17] & 1) != 0;
        float step = radius * StepFractions[(b[17] >> 1) % 3];
        float jitter = SceneGens.Jitters[(b[17] >> 3) % 3];
        int take = b[18] == 0 ? MaxSteps : Math.Min((int)b[18], MaxSteps);
        int flips = b[7];

        if (cottage)
        {
            int rooms = 1 + (b[1] % 4);
            float width = (16 + (b[2] % 17)) / 4f, depth = (16 + (b[3] % 17)) / 4f;
            ushort yaw = BinaryPrimitives.ReadUInt16LittleEndian(b[5..]);
            float angle = (b[4] % 6) switch
            {
                < 3 => 0f,
                3 => (yaw % 4) * MathF.PI / 2,
                _ => (yaw % 1024) * 2 * MathF.PI / 1024,
            };
            var route = (SceneRoute)(b[14] % 6);
            var (x, y) = Place(b[9..14], rooms * width);
            var plan = new CottagePlan(
                x, y, angle, rooms, width, depth, flips,
                BackDoor: (b[8] & 1) != 0 || route == SceneRoute.Through,
                Storey: (b[8] & 2) != 0 || route == SceneRoute.Storey,
                LoadNeighbours: (b[8] & 4) == 0);
            return new SceneRecipe(plan, null, route, b[15] % rooms, radius, two, step, jitter, take);
        }

        int cells = 2 + (b[1] % 4);
        float length = (16 + (b[2] % 25)) / 4f;
        int unloaded = b[3] % (Math.Min(2, cells - 1) + 1);
        var (dx, dy) = Place(b[9..14], cells * length);
        var dungeon = new DungeonPlan(dx, dy, cells, length, unloaded, flips);
        var run = b[14] % 2 == 0 ? SceneRoute.DungeonRun : SceneRoute.DungeonRunAndBack;
        return new SceneRecipe(null, dungeon, run, 0, radius, two, step, jitter, take);
    }

    /// <summary>Decodes bytes and builds the scene walk.</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The scene walk, carrying its recipe (so the scene shrinker applies).</returns>
    public static SceneWalk DecodeWalk(ReadOnlySpan<byte> data) => Decode(data).Build();

    // World origin (metres) from place p1 p2 p3 p4; extent is the building's length along its x.
    private static (double X, double Y) Place(ReadOnlySpan<byte> p, float extent)
    {
        int xb = 1 + (p[1] % 0xFD), yb = 1 + (p[2] % 0xFD);
        switch (p[0] % 8)
        {
            case < 3:
                return ((192.0 * xb) + (p[3] % 192), (192.0 * yb) + (p[4] % 192));
            case < 7:
                int back = 1 + (p[3] % Math.Max(2, (int)extent)), along = 16 + (p[4] % 145);
                return p[0] % 8 < 5 ? ((192.0 * xb) + along, (192.0 * (yb + 1)) - back) : ((192.0 * (xb + 1)) - back, (192.0 * yb) + along);
            default:
                int x = 3 + (p[3] % 10), y = 16 + (p[4] % 145);
                return ((p[1] & 1) != 0 ? (192.0 * 0xFF) - x - extent : x, (192.0 * yb) + y);
        }
    }
}
