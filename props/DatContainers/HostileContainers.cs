using AcPhys.Formats.Dat.Container;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// DAT-CONTAINER-HOSTILE: every damage dat-container.md names (a chain that loops, points past the end or is shorter
/// than its size; a directory that loops, is too deep or counts past 61; a truncated file) ends in a
/// DatContainerException naming the object and the offset, after bounded work (asserted on the reader's counters).
/// </summary>
public sealed class HostileContainers
{
    private const uint Bs = 256;
    private const uint Id = 0x12340100;

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a looping block chain is refused at the repeated block, having read each block once")]
    public void LoopingChain()
    {
        var (c, blocks) = OneObject(3 * 252);
        c.Lay([blocks[0], blocks[1], blocks[2]], new byte[3 * 252], lastLink: 0);
        c.U32(blocks[1], blocks[0]); // block 1 links back to block 0; the size asks for a third block
        var (e, blocksRead) = Fetch(c);
        Assert.Equal(Id, e.ObjectId);
        Assert.Equal(blocks[0], e.Offset);
        Assert.Contains("loops", e.Message);
        Assert.Equal(2, blocksRead);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a link past the end of the file is refused, naming the link's offset")]
    public void LinkPastTheEnd()
    {
        var (c, blocks) = OneObject(2 * 252);
        c.U32(blocks[0], (uint)c.Bytes.Length + 4096);
        var (e, blocksRead) = Fetch(c);
        Assert.Equal(Id, e.ObjectId);
        Assert.Equal(c.Bytes.Length + 4096, e.Offset);
        Assert.Contains("outside the file", e.Message);
        Assert.Equal(1, blocksRead);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a last block that runs past the end of the file is refused")]
    public void BlockRunsPastTheEnd()
    {
        var (c, blocks) = OneObject(2 * 252);
        c.U32(blocks[0], (uint)c.Bytes.Length - 8);
        var (e, _) = Fetch(c);
        Assert.Equal(c.Bytes.Length - 8, e.Offset);
        Assert.Contains("runs past the end", e.Message);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a chain shorter than the directory's size (sizes disagree) is refused where it ends")]
    public void ChainShorterThanSize()
    {
        var (c, blocks) = OneObject(2 * 252);
        c.U32(blocks[0], 0);
        var (e, blocksRead) = Fetch(c);
        Assert.Equal(blocks[0], e.Offset);
        Assert.Contains("ends after 252 of the 504 bytes", e.Message);
        Assert.Equal(1, blocksRead);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a size the file cannot hold is refused before anything is allocated or read (no out-of-memory)")]
    public void SizeBeyondTheFile()
    {
        var c = new HandLaidContainer(Bs, 8, seed: 1);
        uint start = c.Chain(new byte[10]);
        c.Header(c.Chain(HandLaidContainer.Node([], [(Id, start, uint.MaxValue)])));
        var (e, blocksRead) = Fetch(c);
        Assert.Equal(start, e.Offset);
        Assert.Contains("cannot hold", e.Message);
        Assert.Equal(0, blocksRead);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a directory whose node is its own child (a loop) is refused after reading it once")]
    public void LoopingDirectory()
    {
        var c = new HandLaidContainer(Bs, 40, seed: 2);
        var rootBlocks = c.Take(7); // 1,716 bytes in 252-byte payloads
        var leaf = c.Chain(HandLaidContainer.Node([], []));
        c.Lay(rootBlocks, HandLaidContainer.Node([rootBlocks[0], leaf], [(Id, leaf, 0)]), 0);
        c.Header(rootBlocks[0]);
        var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(new MemoryBlockSource(c.Bytes)));
        Assert.Null(e.ObjectId);
        Assert.Equal(rootBlocks[0], e.Offset);
        Assert.Contains("loops", e.Message);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a directory deeper than 12 levels (a chain of one-child nodes) is refused after at most 12 nodes")]
    public void OverDeepDirectory()
    {
        var c = new HandLaidContainer(Bs, 7 * 40, seed: 3);
        var offsets = Enumerable.Range(0, 30).Select(_ => c.Take(7)).ToList();
        for (int i = 0; i < offsets.Count; i++)
        {
            uint[] child = i + 1 < offsets.Count ? [offsets[i + 1][0]] : [];
            c.Lay(offsets[i], HandLaidContainer.Node(child, []), 0);
        }

        c.Header(offsets[0][0]);
        var source = new CountingSource(c.Bytes);
        var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(source));
        Assert.Equal(offsets[DatContainer.MaxDepth][0], e.Offset);
        Assert.Contains("deeper than 12", e.Message);
        Assert.True(source.Reads <= (DatContainer.MaxDepth * 7 * 2) + 1, $"{source.Reads} reads");
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: an entry count above 61 is refused at the node")]
    public void CountAbove61()
    {
        var c = new HandLaidContainer(Bs, 16, seed: 4);
        uint root = c.Chain(HandLaidContainer.Node([], [], count: 62));
        c.Header(root);
        var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(new MemoryBlockSource(c.Bytes)));
        Assert.Equal(root, e.Offset);
        Assert.Contains("at most 61", e.Message);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: an object listed twice is refused, naming it")]
    public void DuplicateId()
    {
        var c = new HandLaidContainer(Bs, 16, seed: 5);
        uint a = c.Chain([1, 2, 3]);
        c.Header(c.Chain(HandLaidContainer.Node([], [(Id, a, 3), (Id, a, 3)])));
        var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(new MemoryBlockSource(c.Bytes)));
        Assert.Equal(Id, e.ObjectId);
    }

    [Theory(DisplayName = "DAT-CONTAINER-HOSTILE: a truncated file (inside the header, or shorter than the header's FileSize, or cut through a block) is refused")]
    [InlineData(0x10)]
    [InlineData(0x150)]
    [InlineData(-100)]
    public void Truncated(int cut)
    {
        var objects = ContainerTestObjects.Sized(30, Bs, seed: 6);
        var bytes = DatContainerWriter.ToBytes(objects, DatSet.Cell, Bs);
        int length = cut > 0 ? cut : bytes.Length + cut;
        var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(new MemoryBlockSource(bytes[..length], "cut.dat")));
        Assert.StartsWith("cut.dat: offset 0x", e.Message);
        Assert.Contains("truncated", e.Message);
    }

    [Fact(DisplayName = "DAT-CONTAINER-HOSTILE: a block size of 0 or 4 (no payload: a chain could not advance) is refused at the header")]
    public void BlockSizeWithoutPayload()
    {
        foreach (uint size in new uint[] { 0, 4, 7 })
        {
            var bytes = DatContainerWriter.ToBytes([], DatSet.Cell, Bs);
            System.Buffers.Binary.BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(0x144), size);
            var e = Assert.Throws<DatContainerException>(() => DatContainer.Open(new MemoryBlockSource(bytes)));
            Assert.Equal(0x144, e.Offset);
        }
    }

    private static (HandLaidContainer C, uint[] Blocks) OneObject(int size)
    {
        var c = new HandLaidContainer(Bs, 24, seed: size);
        var blocks = c.Take((size + 251) / 252);
        c.Lay(blocks, new byte[size], 0);
        c.Header(c.Chain(HandLaidContainer.Node([], [(Id, blocks[0], (uint)size)])));
        return (c, blocks);
    }

    /// <summary>Opens the container (its directory is sound) and fetches the damaged object: the error and the blocks the fetch read.</summary>
    private static (DatContainerException E, long Blocks) Fetch(HandLaidContainer c)
    {
        using var container = DatContainer.Open(new MemoryBlockSource(c.Bytes));
        long before = container.Work.Blocks;
        var e = Assert.Throws<DatContainerException>(() => container.Read(Id));
        return (e, container.Work.Blocks - before);
    }

    private sealed class CountingSource(byte[] bytes) : IBlockSource
    {
        public long Length => bytes.Length;

        public string Name => "counting";

        public int Reads { get; private set; }

        public void Read(long offset, Span<byte> into)
        {
            Reads++;
            bytes.AsSpan((int)offset, into.Length).CopyTo(into);
        }

        public void Dispose()
        {
        }
    }
}
