namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// What a container reader has done: blocks and directory nodes read, bytes fetched. Tests bound a hostile file's cost by
/// these counts, never by a clock; the benchmark reports them beside times.
/// </summary>
public sealed class ContainerWork
{
    private long blocks;
    private long nodes;
    private long bytes;
    private long objects;

    /// <summary>Gets the number of chain blocks visited (link word read).</summary>
    public long Blocks => Interlocked.Read(ref blocks);

    /// <summary>Gets the number of directory nodes read.</summary>
    public long Nodes => Interlocked.Read(ref nodes);

    /// <summary>Gets the number of bytes read from the file.</summary>
    public long Bytes => Interlocked.Read(ref bytes);

    /// <summary>Gets the number of objects fetched (directory nodes not counted).</summary>
    public long Objects => Interlocked.Read(ref objects);

    /// <summary>Summarises the counts.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"{Blocks} blocks, {Nodes} directory nodes, {Objects} objects, {Bytes} bytes read";

    internal void Block(int read)
    {
        Interlocked.Increment(ref blocks);
        Interlocked.Add(ref bytes, read);
    }

    internal void Node() => Interlocked.Increment(ref nodes);

    internal void Object() => Interlocked.Increment(ref objects);
}
