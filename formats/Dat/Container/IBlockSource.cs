using Microsoft.Win32.SafeHandles;

namespace AcPhys.Formats.Dat.Container;

/// <summary>Positioned reads of a container's bytes: a file (never loaded whole) or a buffer in memory.</summary>
public interface IBlockSource : IDisposable
{
    /// <summary>Gets the number of bytes.</summary>
    long Length { get; }

    /// <summary>Gets the name used in messages.</summary>
    string Name { get; }

    /// <summary>Fills a span from an offset; the caller has checked the range lies within <see cref="Length"/>.</summary>
    /// <param name="offset">The offset.</param>
    /// <param name="into">The destination.</param>
    void Read(long offset, Span<byte> into);
}

/// <summary>A container file read by positioned reads (<see cref="RandomAccess"/>), opened read-only and shared.</summary>
public sealed class FileBlockSource : IBlockSource
{
    private readonly SafeFileHandle handle;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="path">The file.</param>
    public FileBlockSource(string path)
    {
        handle = File.OpenHandle(path, FileMode.Open, FileAccess.Read, FileShare.Read, FileOptions.RandomAccess);
        Length = RandomAccess.GetLength(handle);
        Name = path;
    }

    /// <inheritdoc/>
    public long Length { get; }

    /// <inheritdoc/>
    public string Name { get; }

    /// <inheritdoc/>
    public void Read(long offset, Span<byte> into)
    {
        while (into.Length > 0)
        {
            int n = RandomAccess.Read(handle, into, offset);
            if (n <= 0)
            {
                throw new IOException($"{Name}: the file ended at {offset} while reading (it shrank after opening)");
            }

            into = into[n..];
            offset += n;
        }
    }

    /// <inheritdoc/>
    public void Dispose() => handle.Dispose();
}

/// <summary>A container held in memory (tests, the fuzz target).</summary>
/// <param name="bytes">The container's bytes.</param>
/// <param name="name">The name used in messages.</param>
public sealed class MemoryBlockSource(byte[] bytes, string name = "memory") : IBlockSource
{
    /// <inheritdoc/>
    public long Length => bytes.Length;

    /// <inheritdoc/>
    public string Name => name;

    /// <inheritdoc/>
    public void Read(long offset, Span<byte> into) => bytes.AsSpan((int)offset, into.Length).CopyTo(into);

    /// <inheritdoc/>
    public void Dispose()
    {
    }
}
