namespace AcPhys.Protocol.Pipeline;

/// <summary>
/// The thread a child's pipelined passes read its answers on, one per <see cref="Client.ProcessAdapter"/> and reused by
/// every pass: a fuzz campaign runs one pipelined pass per input, and starting a thread for each cost about as much as
/// the whole input on the reference (issue 40: <c>land</c> served at a tenth of the in-process rate). One job at a time.
/// </summary>
internal sealed class ReaderThread : IDisposable
{
    private readonly object gate = new(); // Monitor.Wait/Pulse: not a System.Threading.Lock
    private readonly string name;
    private Thread? thread;
    private Action? job;
    private bool busy;
    private bool disposed;

    /// <summary>Initializes a new instance of the <see cref="ReaderThread"/> class; the thread starts with the first job.</summary>
    /// <param name="name">The thread's name.</param>
    public ReaderThread(string name) => this.name = name;

    /// <summary>Runs <paramref name="work"/> on the thread.</summary>
    /// <param name="work">The job; an exception escaping it ends the process, as on a thread of its own.</param>
    /// <exception cref="InvalidOperationException">The previous job has not been joined, or the thread was disposed.</exception>
    public void Start(Action work)
    {
        lock (gate)
        {
            if (busy || disposed)
            {
                throw new InvalidOperationException(disposed ? "the reader thread was disposed" : "the reader thread is still busy");
            }

            job = work;
            busy = true;
            if (thread is null)
            {
                thread = new Thread(Loop) { IsBackground = true, Name = name };
                thread.Start();
            }
            else
            {
                Monitor.PulseAll(gate);
            }
        }
    }

    /// <summary>Waits until the job started last has returned.</summary>
    public void Join()
    {
        lock (gate)
        {
            while (busy)
            {
                Monitor.Wait(gate);
            }
        }
    }

    /// <summary>Lets the thread end once its job (if any) returned.</summary>
    public void Dispose()
    {
        lock (gate)
        {
            disposed = true;
            Monitor.PulseAll(gate);
        }
    }

    private void Loop()
    {
        while (true)
        {
            Action work;
            lock (gate)
            {
                while (job is null && !disposed)
                {
                    Monitor.Wait(gate);
                }

                if (job is null)
                {
                    return;
                }

                work = job;
                job = null;
            }

            try
            {
                work();
            }
            finally
            {
                lock (gate)
                {
                    busy = false;
                    Monitor.PulseAll(gate);
                }
            }
        }
    }
}
