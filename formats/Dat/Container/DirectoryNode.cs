using System.Buffers.Binary;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// A directory node (dat-container.md "Directory"): 62 branch offsets, an entry count, room for 61 entries. A node whose
/// first branch is non-zero is internal and has count + 1 children.
/// </summary>
/// <param name="Branches">The child node offsets (count + 1 of them for an internal node, none for a leaf).</param>
/// <param name="Entries">The meaningful entries.</param>
public sealed record DirectoryNode(IReadOnlyList<uint> Branches, IReadOnlyList<DirectoryEntry> Entries)
{
    /// <summary>Branch slots in a node.</summary>
    public const int BranchSlots = 62;

    /// <summary>Entry slots in a node.</summary>
    public const int EntrySlots = 61;

    /// <summary>A node's length: 62 × 4 + 4 + 61 × 24.</summary>
    public const int Length = (BranchSlots * 4) + 4 + (EntrySlots * DirectoryEntry.Length);

    /// <summary>Gets a value indicating whether the node is a leaf.</summary>
    public bool IsLeaf => Branches.Count == 0;

    /// <summary>Reads a node from its <see cref="Length"/> bytes.</summary>
    /// <param name="b">The node object's bytes.</param>
    /// <param name="fail">Builds the error for a problem, given the byte offset within the node and the text.</param>
    /// <returns>The node.</returns>
    public static DirectoryNode Parse(ReadOnlySpan<byte> b, Func<int, string, Exception> fail)
    {
        uint count = BinaryPrimitives.ReadUInt32LittleEndian(b[(BranchSlots * 4)..]);
        if (count > EntrySlots)
        {
            throw fail(BranchSlots * 4, $"directory node entry count {count}; a node holds at most {EntrySlots}");
        }

        var entries = new DirectoryEntry[count];
        for (int i = 0; i < count; i++)
        {
            var e = b[((BranchSlots * 4) + 4 + (i * DirectoryEntry.Length))..];
            entries[i] = new DirectoryEntry(W(e, 0), W(e, 1), W(e, 2), W(e, 3), W(e, 4), W(e, 5));
        }

        if (BinaryPrimitives.ReadUInt32LittleEndian(b) == 0)
        {
            return new DirectoryNode([], entries);
        }

        var branches = new uint[count + 1];
        for (int i = 0; i <= count; i++)
        {
            branches[i] = BinaryPrimitives.ReadUInt32LittleEndian(b[(i * 4)..]);
            if (branches[i] == 0)
            {
                throw fail(i * 4, $"internal directory node: branch {i} of {count + 1} is 0");
            }
        }

        return new DirectoryNode(branches, entries);

        static uint W(ReadOnlySpan<byte> e, int k) => BinaryPrimitives.ReadUInt32LittleEndian(e[(k * 4)..]);
    }

    /// <summary>Writes the node's <see cref="Length"/> bytes (unused slots zero).</summary>
    /// <returns>The bytes.</returns>
    public byte[] Write()
    {
        if (Entries.Count > EntrySlots || (!IsLeaf && Branches.Count != Entries.Count + 1))
        {
            throw new InvalidOperationException($"a node of {Entries.Count} entries and {Branches.Count} branches");
        }

        var b = new byte[Length];
        for (int i = 0; i < Branches.Count; i++)
        {
            BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(i * 4), Branches[i]);
        }

        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(BranchSlots * 4), (uint)Entries.Count);
        for (int i = 0; i < Entries.Count; i++)
        {
            var e = b.AsSpan((BranchSlots * 4) + 4 + (i * DirectoryEntry.Length));
            var x = Entries[i];
            uint[] words = [x.Flags, x.Id, x.Offset, x.Size, x.Date, x.Iteration];
            for (int k = 0; k < words.Length; k++)
            {
                BinaryPrimitives.WriteUInt32LittleEndian(e[(k * 4)..], words[k]);
            }
        }

        return b;
    }
}
