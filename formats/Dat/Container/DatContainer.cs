using System.Globalization;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// A dat container opened read-only (dat-container.md; docs/dat-container.md): the header and the whole directory are
/// read at open, objects one at a time on demand through their block chains, by positioned reads (the file is never
/// loaded whole). Hostile files cost bounded work (<see cref="Work"/>) and end in a <see cref="DatContainerException"/>.
/// </summary>
public sealed class DatContainer : IDisposable
{
    /// <summary>The largest block size accepted (retail uses 256 and 1,024).</summary>
    public const uint MaxBlockSize = 1 << 20;

    /// <summary>The smallest block size accepted: a link word and a payload word.</summary>
    public const uint MinBlockSize = 8;

    /// <summary>The deepest directory accepted: 62¹² nodes' worth of entries is far beyond any 32-bit id space.</summary>
    public const int MaxDepth = 12;

    private readonly IBlockSource source;
    private readonly Dictionary<uint, DirectoryEntry> entries;

    private DatContainer(IBlockSource source, ContainerHeader header, Dictionary<uint, DirectoryEntry> entries, int depth, int nodes, ContainerWork work)
    {
        this.source = source;
        Header = header;
        this.entries = entries;
        Depth = depth;
        NodeCount = nodes;
        Work = work;
    }

    /// <summary>Gets the header.</summary>
    public ContainerHeader Header { get; }

    /// <summary>Gets the container's name (its path).</summary>
    public string Name => source.Name;

    /// <summary>Gets the file's length.</summary>
    public long Length => source.Length;

    /// <summary>Gets the number of objects the directory lists.</summary>
    public int Count => entries.Count;

    /// <summary>Gets the directory's depth (1 = the root is a leaf).</summary>
    public int Depth { get; }

    /// <summary>Gets the number of directory nodes.</summary>
    public int NodeCount { get; }

    /// <summary>Gets the work done so far (blocks, nodes, bytes, objects).</summary>
    public ContainerWork Work { get; }

    /// <summary>Gets the object ids, in ascending order.</summary>
    public IEnumerable<uint> Ids => entries.Keys.Order();

    /// <summary>Opens a container file read-only and reads its header and directory.</summary>
    /// <param name="path">The file.</param>
    /// <returns>The container.</returns>
    /// <exception cref="DatContainerException">The file is not a readable container.</exception>
    /// <exception cref="IOException">The file cannot be opened.</exception>
    public static DatContainer Open(string path) => Open(new FileBlockSource(path));

    /// <summary>Opens a container over any byte source (takes ownership of it).</summary>
    /// <param name="source">The bytes.</param>
    /// <returns>The container.</returns>
    /// <exception cref="DatContainerException">The bytes are not a readable container.</exception>
    public static DatContainer Open(IBlockSource source)
    {
        try
        {
            var work = new ContainerWork();
            var header = ReadHeader(source);
            var (entries, depth, nodes) = ReadDirectory(source, header, work);
            return new DatContainer(source, header, entries, depth, nodes, work);
        }
        catch
        {
            source.Dispose();
            throw;
        }
    }

    /// <summary>Tests whether the directory lists an object.</summary>
    /// <param name="id">The id.</param>
    /// <returns>True when listed.</returns>
    public bool Contains(uint id) => entries.ContainsKey(id);

    /// <summary>Gets an object's directory entry.</summary>
    /// <param name="id">The id.</param>
    /// <param name="entry">The entry.</param>
    /// <returns>True when listed.</returns>
    public bool TryGetEntry(uint id, out DirectoryEntry entry) => entries.TryGetValue(id, out entry);

    /// <summary>Reads one object's bytes (its record, starting with its id).</summary>
    /// <param name="id">The id.</param>
    /// <returns>The bytes, or null when the directory does not list the id.</returns>
    /// <exception cref="DatContainerException">The object's chain is damaged.</exception>
    public byte[]? TryRead(uint id)
    {
        if (!entries.TryGetValue(id, out var e))
        {
            return null;
        }

        Work.Object();
        return BlockChain.Read(source, Header.BlockSize, e.Offset, e.Size, id, Work);
    }

    /// <summary>Reads one object's bytes.</summary>
    /// <param name="id">The id.</param>
    /// <returns>The bytes.</returns>
    /// <exception cref="DatContainerException">Not listed, or its chain is damaged.</exception>
    public byte[] Read(uint id) => TryRead(id) ?? throw new DatContainerException(source.Name, id, Header.BTree, "the directory does not list this object");

    /// <summary>Summarises the container on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"{Name}: {Count} objects, block size {Header.BlockSize}, directory of {NodeCount} nodes and depth {Depth}, {Length} bytes");

    /// <inheritdoc/>
    public void Dispose() => source.Dispose();

    private static ContainerHeader ReadHeader(IBlockSource source)
    {
        if (source.Length < ContainerHeader.End)
        {
            throw new DatContainerException(source.Name, null, source.Length, $"truncated: the header ends at 0x{ContainerHeader.End:X}, the file has {source.Length} bytes");
        }

        var bytes = new byte[ContainerHeader.Length];
        source.Read(ContainerHeader.Offset, bytes);
        var h = ContainerHeader.Parse(bytes);
        if (h.BlockSize is < MinBlockSize or > MaxBlockSize)
        {
            throw new DatContainerException(source.Name, null, ContainerHeader.BlockSizeOffset, $"block size {h.BlockSize}; expected {MinBlockSize}..{MaxBlockSize}");
        }

        if (h.FileSize > source.Length)
        {
            throw new DatContainerException(source.Name, null, ContainerHeader.FileSizeOffset, $"truncated: the header states {h.FileSize} bytes, the file has {source.Length}");
        }

        return h;
    }

    private static (Dictionary<uint, DirectoryEntry> Entries, int Depth, int Nodes) ReadDirectory(IBlockSource source, ContainerHeader header, ContainerWork work)
    {
        // The whole tree, keyed by id, as ACE reads it (the order of entries is not relied on). Bounded: a node offset
        // seen twice is a loop, a path deeper than MaxDepth is refused, and every node is a chain read of 1,716 bytes.
        var all = new Dictionary<uint, DirectoryEntry>();
        var seen = new HashSet<uint>();
        var pending = new Stack<(uint Offset, int Depth, uint Parent)>();
        pending.Push((header.BTree, 1, 0));
        int depth = 0;
        while (pending.Count > 0)
        {
            var (at, d, parent) = pending.Pop();
            if (d > MaxDepth)
            {
                throw new DatContainerException(source.Name, null, at, $"the directory is deeper than {MaxDepth} levels (node reached from the node at 0x{parent:X})");
            }

            if (!seen.Add(at))
            {
                throw new DatContainerException(source.Name, null, at, $"the directory loops: the node at this offset is reached twice (again from the node at 0x{parent:X})");
            }

            var bytes = BlockChain.Read(source, header.BlockSize, at, DirectoryNode.Length, null, work);
            work.Node();
            var node = DirectoryNode.Parse(bytes, (o, m) => new DatContainerException(source.Name, null, at, $"{m} (byte {o} of the node)"));
            depth = Math.Max(depth, d);
            foreach (var e in node.Entries)
            {
                if (!all.TryAdd(e.Id, e))
                {
                    throw new DatContainerException(source.Name, e.Id, at, "the directory lists this object twice");
                }
            }

            for (int i = node.Branches.Count - 1; i >= 0; i--)
            {
                pending.Push((node.Branches[i], d + 1, at));
            }
        }

        return (all, depth, seen.Count);
    }
}
