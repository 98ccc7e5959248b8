using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;

namespace AcPhys.Fuzz.Targets;

/// <summary>Valid corpus entries the parser targets start from: land, walk and parts kinds, every optional field, every float special.</summary>
internal static class ParserSeeds
{
    /// <summary>Gets the entries, by seed name.</summary>
    public static IReadOnlyDictionary<string, CorpusEntry> Entries { get; } = new Dictionary<string, CorpusEntry>
    {
        ["land-nan"] = new CorpusEntry
        {
            Title = "NaN never becomes lcoord 0",
            Invariant = "NONFINITE-REJECTED",
            FoundBy = "hand",
            Catches = ["nan-as-zero"],
            Case = new LandCase(new CellId(0x7F7F0001), float.NaN, float.NegativeInfinity, new Lcoord(-8, 2040)),
        },
        ["land-plain"] = new CorpusEntry { Title = "plain", FoundBy = "spec", Seed = "1,2", Case = new LandCase(new CellId(0x3A240031), 150.5f, -0f, new Lcoord(0, 0)) },
        ["walk-two-steps"] = new CorpusEntry
        {
            Title = "south and back",
            Invariant = "NO-BOUNDARY-FREEZE",
            FoundBy = "fuzz",
            Catches = ["clamp-106"],
            Walk = new Walk(new CellId(0x36420039), new Vector3(191.99998f, 0, 0), [new BodySphere(new Vector3(0, 0, 0.5f), 11f), new BodySphere(new Vector3(1.5f, -2, 0.5f), 0.25f)], [new Vector2(3.0517578E-05f, 0), new Vector2(-24, 1e-7f)]),
        },
        ["parts-two"] = new CorpusEntry
        {
            Title = "two parts, the second across the north line",
            Invariant = "PARTS-COVERAGE",
            FoundBy = "hand",
            Catches = ["ace-same-block-guard"],
            Parts = new PartsCase(
            [
                new Part(new CellId(0x80800024), new Frame(new Vector3(100f, 90f, 0.5f), Quaternion.Identity), new Box(new Vector3(-1, -1, -1), new Vector3(1, 1, 1)), 1f, false),
                new Part(new CellId(0x80800028), new Frame(new Vector3(101f, 191.75f, 0.5f), Quaternion.Normalize(new Quaternion(0, 0, 0.3826834f, 0.9238795f))), new Box(new Vector3(-0.5f, -2, 0), new Vector3(0.5f, 2, 1.25f)), 0.5f, true),
            ]),
        },
    };
}
