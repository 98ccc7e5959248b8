using Microsoft.Win32.SafeHandles;

namespace AcPhys.Fuzz.Runtime;

/// <summary>Reads the current test case: from the file afl-fuzz names (<c>@@</c>), or from standard input.</summary>
/// <remarks>
/// Without <c>@@</c>, afl-fuzz rewrites one regular file that is the target's fd 0, and rewinds it, before every
/// input. Reading it with positioned reads (pread at offset 0, length from fstat) needs no rewinding on this side.
/// </remarks>
internal sealed class InputSource
{
    /// <summary>afl-fuzz's MAX_FILE: longer inputs are cut.</summary>
    private const int MaxInput = 1 << 20;

    private readonly string? path;
    private readonly SafeFileHandle stdin = new(0, ownsHandle: false);
    private readonly bool stdinSeekable = LibC.LSeek(0, 0, LibC.SEEK_CUR) >= 0;
    private byte[] buffer = new byte[4096];

    /// <summary>Initializes a new instance of the <see cref="InputSource"/> class.</summary>
    /// <param name="path">The input file, or null for standard input.</param>
    public InputSource(string? path) => this.path = path;

    /// <summary>Reads the whole current input.</summary>
    /// <returns>The input bytes; valid until the next call.</returns>
    public ReadOnlySpan<byte> Read()
    {
        if (path is not null)
        {
            using var handle = File.OpenHandle(path);
            return ReadAll(handle);
        }

        if (stdinSeekable)
        {
            return ReadAll(stdin);
        }

        // A pipe or terminal (outside afl-fuzz): a single input, read to its end.
        using var stream = Console.OpenStandardInput();
        using var copy = new MemoryStream();
        stream.CopyTo(copy);
        return copy.ToArray();
    }

    private ReadOnlySpan<byte> ReadAll(SafeFileHandle handle)
    {
        int length = (int)Math.Min(RandomAccess.GetLength(handle), MaxInput);
        if (buffer.Length < length)
        {
            buffer = new byte[Math.Max(length, buffer.Length * 2)];
        }

        int done = 0;
        while (done < length)
        {
            int n = RandomAccess.Read(handle, buffer.AsSpan(done, length - done), done);
            if (n <= 0)
            {
                break;
            }

            done += n;
        }

        return buffer.AsSpan(0, done);
    }
}
