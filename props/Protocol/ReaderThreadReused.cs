using AcPhys.Protocol.Pipeline;

namespace AcPhys.Props.Protocol;

/// <summary>
/// The pipeline's reader thread is one per adapter and reused by every pass (issue 40: a thread started per fuzz input
/// cost as much as the input): jobs run one at a time, in order, on the same thread; Join waits for the last one.
/// </summary>
public sealed class ReaderThreadReused
{
    [Fact(DisplayName = "READER-THREAD: 200 jobs run one after another on one thread, each finished when Join returns")]
    public void JobsRunInOrderOnOneThread()
    {
        using var reader = new ReaderThread("test reader");
        var threads = new HashSet<int>();
        int done = 0;
        bool inOrder = true;
        for (int i = 0; i < 200; i++)
        {
            int expected = i;
            reader.Start(() =>
            {
                Thread.Sleep(expected % 50 == 0 ? 5 : 0); // a slow job now and then: Join must wait for it
                threads.Add(Environment.CurrentManagedThreadId);
                inOrder &= expected == done; // no Assert here: an exception on the reader thread ends the process
                done++;
            });
            reader.Join();
            Assert.Equal(i + 1, done);
        }

        Assert.True(inOrder);
        var only = Assert.Single(threads);
        Assert.NotEqual(Environment.CurrentManagedThreadId, only);
    }

    [Fact(DisplayName = "READER-THREAD: a second job before Join, or a job after Dispose, is refused")]
    public void OneJobAtATime()
    {
        var reader = new ReaderThread("test reader");
        using var release = new ManualResetEventSlim();
        reader.Start(release.Wait);
        Assert.Throws<InvalidOperationException>(() => reader.Start(() => { }));
        release.Set();
        reader.Join();
        reader.Dispose();
        Assert.Throws<InvalidOperationException>(() => reader.Start(() => { }));
    }
}
