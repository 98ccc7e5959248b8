using System.Buffers.Binary;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// The header of a dat container ("DiskFileInfo_t", dat-container.md "Header"), at byte offset 0x140: fifteen u32 words,
/// VersionMajor (16 raw bytes), VersionMinor.
/// </summary>
/// <param name="FileType">FileType (not checked by the reader).</param>
/// <param name="BlockSize">The size of every block of a chain, link word included.</param>
/// <param name="FileSize">The file's size as the header states it.</param>
/// <param name="DataSet">Which database (not checked by the reader; the writer writes 1 portal, 2 cell).</param>
/// <param name="DataSubset">DataSubset.</param>
/// <param name="FreeHead">First free block.</param>
/// <param name="FreeTail">Last free block.</param>
/// <param name="FreeCount">Free block count.</param>
/// <param name="BTree">The file offset of the root directory node.</param>
/// <param name="NewLru">NewLRU.</param>
/// <param name="OldLru">OldLRU.</param>
/// <param name="UseLru">UseLRU (true when 1).</param>
/// <param name="MasterMapId">MasterMapID.</param>
/// <param name="EnginePackVersion">EnginePackVersion.</param>
/// <param name="GamePackVersion">GamePackVersion.</param>
/// <param name="VersionMinor">VersionMinor (VersionMajor's 16 raw bytes are kept by <see cref="Parse"/> callers only as bytes).</param>
public readonly record struct ContainerHeader(
    uint FileType,
    uint BlockSize,
    uint FileSize,
    uint DataSet,
    uint DataSubset,
    uint FreeHead,
    uint FreeTail,
    uint FreeCount,
    uint BTree,
    uint NewLru,
    uint OldLru,
    uint UseLru,
    uint MasterMapId,
    uint EnginePackVersion,
    uint GamePackVersion,
    uint VersionMinor)
{
    /// <summary>The header's file offset.</summary>
    public const int Offset = 0x140;

    /// <summary>The header's length: 15 words, 16 bytes, 1 word.</summary>
    public const int Length = (15 * 4) + 16 + 4;

    /// <summary>The first byte after the header.</summary>
    public const int End = Offset + Length;

    /// <summary>The file offset of <see cref="BlockSize"/>.</summary>
    public const int BlockSizeOffset = Offset + 4;

    /// <summary>The file offset of <see cref="FileSize"/>.</summary>
    public const int FileSizeOffset = Offset + 8;

    /// <summary>The file offset of <see cref="BTree"/>.</summary>
    public const int BTreeOffset = Offset + 32;

    /// <summary>Reads the header from its <see cref="Length"/> bytes.</summary>
    /// <param name="b">The bytes at <see cref="Offset"/>.</param>
    /// <returns>The header.</returns>
    public static ContainerHeader Parse(ReadOnlySpan<byte> b)
    {
        return new ContainerHeader(W(b, 0), W(b, 1), W(b, 2), W(b, 3), W(b, 4), W(b, 5), W(b, 6), W(b, 7), W(b, 8), W(b, 9), W(b, 10), W(b, 11), W(b, 12), W(b, 13), W(b, 14), BinaryPrimitives.ReadUInt32LittleEndian(b[76..]));

        static uint W(ReadOnlySpan<byte> b, int i) => BinaryPrimitives.ReadUInt32LittleEndian(b[(i * 4)..]);
    }

    /// <summary>Writes the header into its <see cref="Length"/> bytes (VersionMajor zero).</summary>
    /// <param name="b">The bytes at <see cref="Offset"/>.</param>
    public void WriteTo(Span<byte> b)
    {
        uint[] words = [FileType, BlockSize, FileSize, DataSet, DataSubset, FreeHead, FreeTail, FreeCount, BTree, NewLru, OldLru, UseLru, MasterMapId, EnginePackVersion, GamePackVersion];
        for (int i = 0; i < words.Length; i++)
        {
            BinaryPrimitives.WriteUInt32LittleEndian(b[(i * 4)..], words[i]);
        }

        b.Slice(60, 16).Clear();
        BinaryPrimitives.WriteUInt32LittleEndian(b[76..], VersionMinor);
    }
}
