using System.Buffers.Binary;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// A container laid out byte by byte from ../shared/spec/dat-container.md alone, independently of the product's writer:
/// blocks handed out from shuffled slots (chains scattered and out of order), nodes and the header written here with
/// their own offsets. Tests use it to build valid containers and to plant damage (explicit block lists and links).
/// </summary>
internal sealed class HandLaidContainer
{
    // dat-container.md "Header": at 0x140, FileType, BlockSize, FileSize, DataSet, DataSubset, FreeHead, FreeTail,
    // FreeCount, BTree, ... (u32 each).
    private const int HeaderAt = 0x140;
    private const int NodeBytes = 1716; // 62 branches × 4 + count 4 + 61 entries × 24

    private readonly List<uint> free;

    public HandLaidContainer(uint blockSize, int slots, int seed)
    {
        BlockSize = blockSize;
        uint first = (uint)((0x190 + blockSize - 1) / blockSize * blockSize);
        Bytes = new byte[first + (slots * blockSize)];
        free = [.. Enumerable.Range(0, slots).Select(i => first + ((uint)i * blockSize))];
        var random = new Random(seed);
        for (int i = free.Count - 1; i > 0; i--)
        {
            int j = random.Next(i + 1);
            (free[i], free[j]) = (free[j], free[i]);
        }
    }

    public uint BlockSize { get; }

    public byte[] Bytes { get; private set; }

    /// <summary>Takes n scattered free block offsets.</summary>
    public uint[] Take(int n)
    {
        var taken = free.GetRange(0, n).ToArray();
        free.RemoveRange(0, n);
        return taken;
    }

    /// <summary>Lays a payload over scattered blocks; returns the first block's offset.</summary>
    public uint Chain(byte[] payload)
    {
        int per = (int)BlockSize - 4;
        var blocks = Take(Math.Max(1, (payload.Length + per - 1) / per));
        Lay(blocks, payload, 0);
        return blocks[0];
    }

    /// <summary>Lays a payload over the given blocks in order; the last block's link word is <paramref name="lastLink"/>.</summary>
    public void Lay(IReadOnlyList<uint> blocks, byte[] payload, uint lastLink)
    {
        int per = (int)BlockSize - 4;
        for (int i = 0; i < blocks.Count; i++)
        {
            U32(blocks[i], i + 1 < blocks.Count ? blocks[i + 1] : lastLink);
            int from = i * per;
            int n = Math.Clamp(payload.Length - from, 0, per);
            payload.AsSpan(from, n).CopyTo(Bytes.AsSpan((int)blocks[i] + 4));
        }
    }

    /// <summary>A directory node's 1,716 bytes: branches, count, entries (id, offset, size; flags, date, iteration 0).</summary>
    public static byte[] Node(IReadOnlyList<uint> branches, IReadOnlyList<(uint Id, uint Offset, uint Size)> entries, uint? count = null)
    {
        var node = new byte[NodeBytes];
        for (int i = 0; i < branches.Count; i++)
        {
            BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(i * 4), branches[i]);
        }

        BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(248), count ?? (uint)entries.Count);
        for (int i = 0; i < entries.Count; i++)
        {
            int at = 252 + (i * 24);
            BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(at + 4), entries[i].Id);
            BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(at + 8), entries[i].Offset);
            BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(at + 12), entries[i].Size);
            BinaryPrimitives.WriteUInt32LittleEndian(node.AsSpan(at + 20), 1);
        }

        return node;
    }

    /// <summary>Writes the header: block size, file size (the real length unless given), data set, root node.</summary>
    public void Header(uint root, uint dataSet = 2, uint? fileSize = null)
    {
        U32(HeaderAt + 4, BlockSize);
        U32(HeaderAt + 8, fileSize ?? (uint)Bytes.Length);
        U32(HeaderAt + 12, dataSet);
        U32(HeaderAt + 32, root);
    }

    /// <summary>Builds a valid container of the objects: a leaf root when they fit one node, else a two-level tree.</summary>
    public static HandLaidContainer Of(IReadOnlyList<(uint Id, byte[] Bytes)> objects, uint blockSize, int seed)
    {
        int per = (int)blockSize - 4;
        int nodeBlocks = (NodeBytes + per - 1) / per;
        int leaves = (objects.Count + 60) / 61;
        int slots = objects.Sum(o => Math.Max(1, (o.Bytes.Length + per - 1) / per)) + ((leaves + 3) * nodeBlocks);
        var c = new HandLaidContainer(blockSize, slots, seed);
        var laid = objects.OrderBy(o => o.Id).Select(o => (o.Id, c.Chain(o.Bytes), (uint)o.Bytes.Length)).ToList();
        if (laid.Count <= 61)
        {
            c.Header(c.Chain(Node([], laid)));
            return c;
        }

        // Two levels: leaves of up to 60 entries, the entry after each leaf (but the last) is a separator in the root.
        var branches = new List<uint>();
        var separators = new List<(uint, uint, uint)>();
        int at = 0;
        while (at < laid.Count)
        {
            int n = Math.Min(60, laid.Count - at);
            branches.Add(c.Chain(Node([], laid.GetRange(at, n))));
            at += n;
            if (at < laid.Count)
            {
                separators.Add(laid[at]);
                at++;
            }
        }

        if (branches.Count == separators.Count)
        {
            branches.Add(c.Chain(Node([], [])));
        }

        if (separators.Count > 61)
        {
            throw new ArgumentException("the hand-laid builder makes two levels only (at most 61 × 61 + 61 objects)");
        }

        c.Header(c.Chain(Node(branches, separators)));
        return c;
    }

    public void U32(long at, uint value) => BinaryPrimitives.WriteUInt32LittleEndian(Bytes.AsSpan((int)at), value);

    public void Truncate(int length) => Bytes = Bytes[..length];
}
