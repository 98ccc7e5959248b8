using AcPhys.Formats.Dat.Container;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// DAT-CONTAINER-READ: a container written by the product's writer, and one laid out independently from
/// dat-container.md (scattered chains, block sizes 256 and 1,024, one- and two-level directories), are read back
/// object for object, byte for byte.
/// </summary>
public sealed class ContainerReadBack
{
    public static TheoryData<uint, int> Shapes => new() { { 256, 40 }, { 256, 900 }, { 1024, 61 }, { 1024, 62 }, { 1024, 4000 } };

    [Theory(DisplayName = "DAT-CONTAINER-READ: the writer's container reads back object for object (block size, objects)")]
    [MemberData(nameof(Shapes))]
    public void WriterRoundTrip(uint blockSize, int count)
    {
        var objects = ContainerTestObjects.Sized(count, blockSize, seed: count);
        using var c = DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(objects, DatSet.Cell, blockSize)));
        SameObjects(objects, c);
        Assert.Equal(blockSize, c.Header.BlockSize);
        Assert.Equal((uint)DatSet.Cell, c.Header.DataSet);
        Assert.Equal(count <= 61 ? 1 : count <= 3843 ? 2 : 3, c.Depth); // 61 entries per leaf; 62 × 61 + 61 = 3,843 in two levels
    }

    [Theory(DisplayName = "DAT-CONTAINER-READ: a container laid out by hand from the facts file (scattered chains) reads back object for object")]
    [InlineData(256u, 50)]
    [InlineData(256u, 412)]
    [InlineData(1024u, 412)]
    public void HandLaidRoundTrip(uint blockSize, int count)
    {
        var objects = ContainerTestObjects.Sized(count, blockSize, seed: 3);
        var laid = HandLaidContainer.Of(objects, blockSize, seed: 11);
        using var c = DatContainer.Open(new MemoryBlockSource(laid.Bytes));
        SameObjects(objects, c);
        Assert.Equal(count <= 61 ? 1 : 2, c.Depth);
    }

    [Fact(DisplayName = "DAT-CONTAINER-READ: the corpus scenes' cell records, hand-laid and written, read back the same from both, and from a file")]
    public void CorpusRecordsBothWays()
    {
        var objects = ContainerTestObjects.CorpusCellRecords;
        Assert.True(objects.Count >= 20, $"{objects.Count} corpus records");
        using var laid = DatContainer.Open(new MemoryBlockSource(HandLaidContainer.Of(objects, 1024, seed: 5).Bytes));
        SameObjects(objects, laid);
        string path = Path.Combine(Path.GetTempPath(), "acphys-container-" + Guid.NewGuid().ToString("N") + ".dat");
        try
        {
            Assert.Equal(objects.Count, DatContainerWriter.Write(path, objects, DatSet.Cell, 256));
            using var written = DatContainer.Open(path);
            SameObjects(objects, written);
            Assert.Equal(new FileInfo(path).Length, written.Header.FileSize);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact(DisplayName = "DAT-CONTAINER-READ: an object is fetched on demand: opening reads the directory only, one fetch reads only that object's blocks")]
    public void OnDemand()
    {
        var objects = ContainerTestObjects.Sized(500, 256, seed: 9);
        using var c = DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(objects, DatSet.Portal, 256)));
        Assert.Equal(0, c.Work.Objects);
        Assert.Equal(c.NodeCount, c.Work.Nodes);
        long before = c.Work.Blocks;
        var (id, bytes) = objects.MaxBy(o => o.Bytes.Length);
        Assert.Equal(bytes, c.Read(id));
        Assert.Equal((bytes.Length + 251) / 252, c.Work.Blocks - before);
        Assert.Null(c.TryRead(0x7FFFFFFF));
    }

    private static void SameObjects(IReadOnlyList<(uint Id, byte[] Bytes)> objects, DatContainer c)
    {
        Assert.Equal(objects.Count, c.Count);
        Assert.Equal(objects.Select(o => o.Id).Order(), c.Ids);
        foreach (var (id, bytes) in objects)
        {
            Assert.Equal(bytes, c.Read(id));
        }
    }
}
