using AcPhys.Formats.Dat;
using AcPhys.Props.Dat;

namespace AcPhys.Props.DatContainers;

/// <summary>Objects to put in test containers: the corpus scenes' records and sized filler.</summary>
internal static class ContainerTestObjects
{
    /// <summary>Gets the cell-dat records of every corpus scene walk (distinct ids; the two cottage files share theirs).</summary>
    public static IReadOnlyList<(uint Id, byte[] Bytes)> CorpusCellRecords { get; } = [.. DatTestSupport.CorpusSceneWalks
        .SelectMany(e => DatSceneWriter.Write(e.Entry.SceneWalk!.Scene, "t", "m").Records)
        .Where(r => !r.Record.PortalDat)
        .DistinctBy(r => r.Record.Id)
        .Select(r => (r.Record.Id, r.Bytes))];

    /// <summary>Objects of sizes around the block payload boundaries (0, 1, payload − 1, payload, payload + 1, several blocks).</summary>
    /// <param name="count">How many.</param>
    /// <param name="blockSize">The block size the sizes are chosen around.</param>
    /// <param name="seed">The seed.</param>
    /// <returns>The objects, ids ascending from 0x01000000 in a shuffled order.</returns>
    public static List<(uint Id, byte[] Bytes)> Sized(int count, uint blockSize, int seed)
    {
        var random = new Random(seed);
        int per = (int)blockSize - 4;
        int[] sizes = [0, 1, 4, per - 1, per, per + 1, (2 * per) - 3, 2 * per, (3 * per) + 7, 1716];
        var objects = new List<(uint, byte[])>();
        for (int i = 0; i < count; i++)
        {
            var bytes = new byte[i < sizes.Length ? sizes[i] : random.Next(0, 3 * per)];
            random.NextBytes(bytes);
            objects.Add((0x01000000u + (uint)(i * 7), bytes));
        }

        return [.. objects.OrderBy(_ => random.Next())];
    }
}
