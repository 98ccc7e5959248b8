using System.Text;
using AcPhys.Protocol.Child;

namespace AcPhys.Props.Protocol;

/// <summary>How the tool reads a child's answers on the thread that waits for them (issue 26): a wait that gives up
/// keeps what was read of the line, and the next read finishes it.</summary>
public sealed class LineReaderWaits
{
    [Fact(DisplayName = "A wait that gives up mid-line raises TimeoutException; the next read returns the whole line, then the next")]
    public void GivingUpKeepsThePartialLine()
    {
        var stream = new ChunkStream("{\"ok\":", "true}\n{\"ok\":false}\n");
        var reader = new BoundedLineReader(stream);
        int waits = 0;
        bool patient = false;
        bool Wait()
        {
            waits++;
            return patient || stream.Delivered == 0; // the first chunk arrives; the peer then falls silent
        }

        Assert.Throws<TimeoutException>(() => reader.ReadLine(Wait));
        patient = true;
        Assert.Equal("{\"ok\":true}", reader.ReadLine(Wait));
        Assert.Equal("{\"ok\":false}", reader.ReadLine(Wait));
        Assert.Null(reader.ReadLine(Wait));
        Assert.True(waits >= 4, $"waited {waits} times");
    }

    [Fact(DisplayName = "A buffered whole line is returned without waiting")]
    public void BufferedLineNeedsNoWait()
    {
        var reader = new BoundedLineReader(new ChunkStream("a\nb\n"));
        Assert.Equal("a", reader.ReadLine(() => true));
        Assert.True(reader.HasBufferedLine);
        Assert.Equal("b", reader.ReadLine(() => throw new InvalidOperationException("waited for a buffered line")));
    }

    [Fact(DisplayName = "A line over the limit is refused while waiting reads, and the line after it is read")]
    public void TooLongWhileWaiting()
    {
        var reader = new BoundedLineReader(new ChunkStream(new string('x', 40), new string('y', 40) + "\nnext\n"), maxBytes: 50);
        Assert.Throws<LineTooLongException>(() => reader.ReadLine(() => true));
        Assert.Equal("next", reader.ReadLine(() => true));
    }

    // Hands out one chunk per read, as a pipe does when the peer writes in pieces.
    private sealed class ChunkStream(params string[] chunks) : Stream
    {
        private readonly Queue<byte[]> queue = new(chunks.Select(Encoding.UTF8.GetBytes));

        public int Delivered { get; private set; }

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => false;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override int Read(byte[] buffer, int offset, int count)
        {
            if (!queue.TryDequeue(out var chunk))
            {
                return 0;
            }

            Assert.True(chunk.Length <= count);
            chunk.CopyTo(buffer, offset);
            Delivered++;
            return chunk.Length;
        }

        public override void Flush()
        {
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
