using System.Buffers.Binary;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// Reads one object through its block chain (dat-container.md "Block chains"): each block starts with the offset of the
/// next (0 = last) and carries BlockSize − 4 payload bytes, the last one the rest. Bounded on hostile files: the size is
/// checked against what the file can hold before anything is allocated, every block must lie inside the file, a block
/// visited twice is a loop, and a chain that ends early disagrees with its size; each is a
/// <see cref="DatContainerException"/> naming the object and the offset.
/// </summary>
public static class BlockChain
{
    /// <summary>Reads an object's bytes.</summary>
    /// <param name="source">The container's bytes.</param>
    /// <param name="blockSize">The header's block size (checked by the caller: at least 8).</param>
    /// <param name="start">The offset of the first block.</param>
    /// <param name="size">The payload size the directory states.</param>
    /// <param name="id">The object, for messages (null for a directory node).</param>
    /// <param name="work">The counters to add to.</param>
    /// <returns>The payload, link words removed.</returns>
    /// <exception cref="DatContainerException">The chain is damaged.</exception>
    public static byte[] Read(IBlockSource source, uint blockSize, uint start, uint size, uint? id, ContainerWork work)
    {
        string what = id is null ? "directory node: " : string.Empty;
        long payload = blockSize - 4;
        long blocksNeeded = (size + payload - 1) / payload;
        // A chain of distinct blocks cannot hold more than the file's blocks: refuse before allocating (no out-of-memory).
        if (blocksNeeded > (source.Length / blockSize) + 1)
        {
            throw new DatContainerException(source.Name, id, start, $"{what}size {size} needs {blocksNeeded} blocks of {blockSize}; the file ({source.Length} bytes) cannot hold them");
        }

        var data = new byte[size];
        if (size == 0)
        {
            return data;
        }

        var seen = new HashSet<long>();
        Span<byte> link = stackalloc byte[4];
        long at = start;
        int filled = 0;
        while (true)
        {
            if (at <= 0 || at + 4 > source.Length)
            {
                throw new DatContainerException(source.Name, id, at, $"{what}block {seen.Count} of the chain lies outside the file ({source.Length} bytes)");
            }

            if (!seen.Add(at))
            {
                throw new DatContainerException(source.Name, id, at, $"{what}the chain loops: block {seen.Count} is the block at this offset again");
            }

            int take = (int)Math.Min(payload, size - filled);
            if (at + 4 + take > source.Length)
            {
                throw new DatContainerException(source.Name, id, at, $"{what}block {seen.Count - 1} of the chain runs past the end of the file ({source.Length} bytes)");
            }

            source.Read(at, link);
            source.Read(at + 4, data.AsSpan(filled, take));
            work.Block(4 + take);
            filled += take;
            if (filled == size)
            {
                // The last block's link word is not looked at: a reader stops at the size, as ACE does.
                return data;
            }

            uint next = BinaryPrimitives.ReadUInt32LittleEndian(link);
            if (next == 0)
            {
                throw new DatContainerException(source.Name, id, at, $"{what}the chain ends after {filled} of the {size} bytes the directory states");
            }

            at = next;
        }
    }
}
