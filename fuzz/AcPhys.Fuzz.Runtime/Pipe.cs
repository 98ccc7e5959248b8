using System.Buffers.Binary;
using System.Runtime.InteropServices;

namespace AcPhys.Fuzz.Runtime;

/// <summary>Reads and writes the 4-byte little-endian words of the AFL forkserver pipes.</summary>
internal static unsafe class Pipe
{
    /// <summary>Reads one word.</summary>
    /// <param name="fd">The control descriptor (198).</param>
    /// <param name="value">The word read.</param>
    /// <returns>False at end of file or on error: afl-fuzz has gone.</returns>
    internal static bool TryReadWord(int fd, out uint value)
    {
        byte* buffer = stackalloc byte[4];
        int done = 0;
        while (done < 4)
        {
            nint n = LibC.Read(fd, buffer + done, 4 - done);
            if (n > 0)
            {
                done += (int)n;
            }
            else if (n < 0 && Marshal.GetLastPInvokeError() == LibC.EINTR)
            {
                continue;
            }
            else
            {
                value = 0;
                return false;
            }
        }

        value = BinaryPrimitives.ReadUInt32LittleEndian(new ReadOnlySpan<byte>(buffer, 4));
        return true;
    }

    /// <summary>Writes one word.</summary>
    /// <param name="fd">The status descriptor (199).</param>
    /// <param name="value">The word to write.</param>
    /// <returns>False on error: afl-fuzz has gone.</returns>
    internal static bool TryWriteWord(int fd, uint value)
    {
        byte* buffer = stackalloc byte[4];
        BinaryPrimitives.WriteUInt32LittleEndian(new Span<byte>(buffer, 4), value);
        int done = 0;
        while (done < 4)
        {
            nint n = LibC.Write(fd, buffer + done, 4 - done);
            if (n > 0)
            {
                done += (int)n;
            }
            else if (n < 0 && Marshal.GetLastPInvokeError() == LibC.EINTR)
            {
                continue;
            }
            else
            {
                return false;
            }
        }

        return true;
    }
}
