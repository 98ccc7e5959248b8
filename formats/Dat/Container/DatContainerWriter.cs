using System.Buffers.Binary;

namespace AcPhys.Formats.Dat.Container;

/// <summary>Which database a container is (written into the header's DataSet; the reader does not check it).</summary>
public enum DatSet
{
    /// <summary>client_portal.dat.</summary>
    Portal = 1,

    /// <summary>client_cell_1.dat.</summary>
    Cell = 2,
}

/// <summary>
/// Writes a dat container in the layout dat-container.md states, for tests, fixtures and benchmarks: the header at
/// 0x140, every object a contiguous chain of blocks from the first block boundary after the header, then a B-tree
/// directory (entries sorted by id, at most 61 per node, internal nodes with count + 1 children) written children
/// first, the root last. Written to a temp file beside the target and renamed: a killed run leaves no half file.
/// </summary>
public static class DatContainerWriter
{
    /// <summary>Writes a container.</summary>
    /// <param name="path">The file to write (replaced).</param>
    /// <param name="objects">The objects: id and bytes (ids unique), written in this order, streamed.</param>
    /// <param name="set">The database.</param>
    /// <param name="blockSize">The block size (retail: 256 portal, 1,024 cell... any of 8..1 MiB).</param>
    /// <returns>The number of objects written.</returns>
    public static int Write(string path, IEnumerable<(uint Id, byte[] Bytes)> objects, DatSet set, uint blockSize = 1024)
    {
        string full = Path.GetFullPath(path);
        string temp = Path.Combine(Path.GetDirectoryName(full) ?? ".", "." + Path.GetFileName(full) + "." + Environment.ProcessId + "." + Guid.NewGuid().ToString("N")[..8] + ".tmp");
        try
        {
            int count;
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.ReadWrite, FileShare.None, 1 << 16))
            {
                count = Write(stream, objects, set, blockSize);
                stream.Flush(flushToDisk: true);
            }

            File.Move(temp, full, overwrite: true);
            return count;
        }
        finally
        {
            if (File.Exists(temp))
            {
                File.Delete(temp);
            }
        }
    }

    /// <summary>Writes a container into memory.</summary>
    /// <param name="objects">The objects.</param>
    /// <param name="set">The database.</param>
    /// <param name="blockSize">The block size.</param>
    /// <returns>The bytes.</returns>
    public static byte[] ToBytes(IEnumerable<(uint Id, byte[] Bytes)> objects, DatSet set, uint blockSize = 1024)
    {
        using var stream = new MemoryStream();
        Write(stream, objects, set, blockSize);
        return stream.ToArray();
    }

    /// <summary>Writes a container into a seekable stream positioned at 0.</summary>
    /// <param name="stream">The stream.</param>
    /// <param name="objects">The objects.</param>
    /// <param name="set">The database.</param>
    /// <param name="blockSize">The block size.</param>
    /// <returns>The number of objects written.</returns>
    public static int Write(Stream stream, IEnumerable<(uint Id, byte[] Bytes)> objects, DatSet set, uint blockSize = 1024)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(blockSize, DatContainer.MinBlockSize);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(blockSize, DatContainer.MaxBlockSize);
        var chains = new ChainWriter(stream, blockSize);
        var entries = new List<DirectoryEntry>();
        var ids = new HashSet<uint>();
        foreach (var (id, bytes) in objects)
        {
            if (!ids.Add(id))
            {
                throw new ArgumentException($"object {RecordIds.Text(id)} given twice", nameof(objects));
            }

            entries.Add(new DirectoryEntry(0, id, chains.Append(bytes), (uint)bytes.Length, 0, 0));
        }

        entries.Sort((a, b) => a.Id.CompareTo(b.Id));
        uint root = WriteTree(chains, entries, 0, entries.Count, Height(entries.Count));
        var header = new ContainerHeader(0, blockSize, checked((uint)chains.End), (uint)set, 0, 0, 0, 0, root, 0, 0, 0, 0, 0, 0, 0);
        chains.Finish(header);
        return entries.Count;
    }

    /// <summary>The height of the smallest B-tree of 61-entry nodes holding <paramref name="n"/> entries (a subtree of height h holds up to 62^h − 1).</summary>
    private static int Height(int n)
    {
        int h = 1;
        for (long cap = DirectoryNode.BranchSlots - 1; cap < n; cap = (cap * DirectoryNode.BranchSlots) + (DirectoryNode.BranchSlots - 1))
        {
            h++;
        }

        return h;
    }

    private static long Capacity(int height)
    {
        long cap = 0;
        for (int i = 0; i < height; i++)
        {
            cap = (cap * DirectoryNode.BranchSlots) + (DirectoryNode.BranchSlots - 1);
        }

        return cap;
    }

    private static uint WriteTree(ChainWriter chains, List<DirectoryEntry> sorted, int from, int count, int height)
    {
        if (height == 1)
        {
            return chains.Append(new DirectoryNode([], sorted.GetRange(from, count)).Write());
        }

        // c children of at most Capacity(height − 1) entries each and c − 1 separators: c · (cap + 1) ≥ count + 1.
        long cap = Capacity(height - 1);
        int c = (int)((count + 1 + cap) / (cap + 1));
        c = Math.Max(c, 2);
        int inChildren = count - (c - 1);
        var branches = new List<uint>();
        var separators = new List<DirectoryEntry>();
        int at = from;
        for (int i = 0; i < c; i++)
        {
            int size = (inChildren / c) + (i < inChildren % c ? 1 : 0);
            branches.Add(WriteTree(chains, sorted, at, size, height - 1));
            at += size;
            if (i < c - 1)
            {
                separators.Add(sorted[at]);
                at++;
            }
        }

        return chains.Append(new DirectoryNode(branches, separators).Write());
    }

    /// <summary>Appends chains of contiguous blocks; the header is written last.</summary>
    private sealed class ChainWriter
    {
        private readonly Stream stream;
        private readonly uint blockSize;
        private readonly byte[] block;

        public ChainWriter(Stream stream, uint blockSize)
        {
            this.stream = stream;
            this.blockSize = blockSize;
            block = new byte[blockSize];
            End = ((ContainerHeader.End + blockSize - 1) / blockSize) * blockSize;
            stream.SetLength(0);
            stream.Write(new byte[End]);
        }

        public long End { get; private set; }

        public uint Append(byte[] bytes)
        {
            uint start = checked((uint)End);
            int payload = (int)blockSize - 4;
            int blocks = Math.Max(1, (bytes.Length + payload - 1) / payload);
            for (int i = 0; i < blocks; i++)
            {
                Array.Clear(block);
                int take = Math.Min(payload, bytes.Length - (i * payload));
                uint next = i == blocks - 1 ? 0 : checked((uint)(End + blockSize));
                BinaryPrimitives.WriteUInt32LittleEndian(block, next);
                bytes.AsSpan(i * payload, take).CopyTo(block.AsSpan(4));
                stream.Write(block);
                End += blockSize;
            }

            return start;
        }

        public void Finish(ContainerHeader header)
        {
            var bytes = new byte[ContainerHeader.Length];
            header.WriteTo(bytes);
            stream.Position = ContainerHeader.Offset;
            stream.Write(bytes);
            stream.Position = End;
        }
    }
}
