namespace AcPhys.Core;

/// <summary>One entry of a <see cref="CellArray"/>: a cell id and whether its cell is loaded (false = a load hint, retail's null payload).</summary>
/// <param name="Id">The cell id.</param>
/// <param name="Loaded">False for a load hint (facts §3.1: retail adds unloaded cells with a null payload).</param>
public readonly record struct CellEntry(CellId Id, bool Loaded);

/// <summary>
/// The ordered, duplicate-free set of cells a query collects (facts §5.9): insertion order is kept, a duplicate id is
/// ignored, removal swaps the last entry into the hole as retail does. Reusable: <see cref="Reset"/> truncates it
/// (facts §6.13: real reset semantics per call) and clears the <see cref="AddedOutside"/> latch. Adding does not
/// allocate once the capacity has grown to the largest query seen.
/// </summary>
public sealed class CellArray
{
    private CellEntry[] entries;

    /// <summary>Initializes an empty array.</summary>
    /// <param name="capacity">Initial capacity.</param>
    public CellArray(int capacity = 16) => entries = new CellEntry[Math.Max(capacity, 4)];

    /// <summary>Gets the number of entries.</summary>
    public int Count { get; private set; }

    /// <summary>Gets or sets a value indicating whether outdoor cells were already collected for this query (facts §3.5).</summary>
    public bool AddedOutside { get; set; }

    /// <summary>Gets the entry at an index, in insertion order (as modified by removals).</summary>
    /// <param name="index">0 ≤ index &lt; Count.</param>
    public CellEntry this[int index] => (uint)index < (uint)Count ? entries[index] : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>Truncates the array and clears the latch (retail truncates; ACE keeps stale entries, facts §7 #6).</summary>
    public void Reset()
    {
        Count = 0;
        AddedOutside = false;
    }

    /// <summary>Appends a cell unless its id is already present.</summary>
    /// <param name="id">The cell id.</param>
    /// <param name="loaded">Whether the cell is loaded.</param>
    /// <returns>True when added.</returns>
    public bool Add(CellId id, bool loaded)
    {
        if (Contains(id))
        {
            return false;
        }

        if (Count == entries.Length)
        {
            Array.Resize(ref entries, entries.Length * 2);
        }

        entries[Count++] = new CellEntry(id, loaded);
        return true;
    }

    /// <summary>Tests whether an id is present.</summary>
    /// <param name="id">The cell id.</param>
    /// <returns>True when present.</returns>
    public bool Contains(CellId id) => IndexOf(id) >= 0;

    /// <summary>Returns the index of an id, or −1.</summary>
    /// <param name="id">The cell id.</param>
    /// <returns>The index.</returns>
    public int IndexOf(CellId id)
    {
        for (int i = 0; i < Count; i++)
        {
            if (entries[i].Id == id)
            {
                return i;
            }
        }

        return -1;
    }

    /// <summary>Removes an id; the last entry moves into its place (retail CCellArray, facts §5.9).</summary>
    /// <param name="id">The cell id.</param>
    /// <returns>True when removed.</returns>
    public bool Remove(CellId id)
    {
        int i = IndexOf(id);
        if (i < 0)
        {
            return false;
        }

        entries[i] = entries[--Count];
        return true;
    }

    /// <summary>Copies the ids, in order, into a new array (for reports; allocates).</summary>
    /// <returns>The ids.</returns>
    public CellId[] ToIdArray()
    {
        var ids = new CellId[Count];
        for (int i = 0; i < Count; i++)
        {
            ids[i] = entries[i].Id;
        }

        return ids;
    }
}
