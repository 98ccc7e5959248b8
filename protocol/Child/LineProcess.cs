using System.Collections.Concurrent;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using AcPhys.Contract;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Child;

/// <summary>
/// A child process spoken to one line at a time over stdin/stdout, with a per-exchange timeout. Its stderr is the
/// implementation's log: every line goes to a sink (passed through) and the last lines are kept for error messages.
/// Anything that stops an answer (exit, hang, broken pipe) becomes an <see cref="AdapterFailureException"/>.
/// </summary>
internal sealed partial class LineProcess : IDisposable
{
    private const int TailLines = 20;
    private const int SigKill = 9;
    private const int MaxStderrChars = 1000;
    private const int PipeBytes = 1 << 20;

    // On Linux and macOS the implementation runs as the leader of its own process group (setsid), with a watcher in
    // that group that ends the group once acphys is gone: SIGKILL of acphys included, which no handler sees. The
    // watcher polls the parent once a second and holds none of the pipes, so EOF on the implementation's stdout still
    // means it closed it. "$1" is the implementation's command line, run by a second sh exactly as before.
    private const string GroupScript =
        "p=$PPID; ( trap '' INT TERM HUP; while kill -0 \"$p\" 2>/dev/null; do sleep 1; done; kill -TERM 0; sleep 1; kill -KILL 0 ) </dev/null >/dev/null 2>&1 & exec /bin/sh -c \"$1\"";

    private static readonly ConcurrentDictionary<int, byte> LiveGroups = new();
    private static readonly ConcurrentDictionary<string, byte> LiveTags = new();

    private readonly Process process;
    private readonly string commandLine;
    private readonly ConcurrentQueue<string> tail = new();
    private readonly Action<string>? stderrSink;
    private static int exitHooked;
    private BoundedLineReader? answers;
    private Task<string?>? pending;
    private bool dead;
    private int receiving;
    private int group;
    private string tag = string.Empty;
    private string? stdoutPipe;
    private Stream? stdin;
    private byte[] queued = new byte[64 * 1024];
    private int queuedBytes;
    private int stdoutFd = -1;
    private long deadline;
    private Func<bool>? waitForAnswer;

    private LineProcess(Process process, string commandLine, Action<string>? stderrSink)
    {
        this.process = process;
        this.commandLine = commandLine;
        this.stderrSink = stderrSink;
    }

    /// <summary>Gets the last lines the child wrote to stderr.</summary>
    public IReadOnlyList<string> StderrTail => tail.ToArray();

    /// <summary>Starts <paramref name="commandLine"/> through the platform shell.</summary>
    /// <param name="commandLine">The command line, as typed in a shell.</param>
    /// <param name="stderrSink">Receives each stderr line of the child, or null to only keep the tail.</param>
    /// <param name="maxLineBytes">The most bytes of one answer line (<see cref="BoundedLineReader"/>).</param>
    /// <returns>The running process.</returns>
    /// <exception cref="AdapterFailureException">It could not be started.</exception>
    public static LineProcess Start(string commandLine, Action<string>? stderrSink, int maxLineBytes = BoundedLineReader.DefaultMaxBytes)
    {
        bool grouped = !OperatingSystem.IsWindows() && File.Exists("/usr/bin/setsid");
        var info = OperatingSystem.IsWindows()
            ? new ProcessStartInfo("cmd.exe") { ArgumentList = { "/d", "/c", commandLine } }
            : grouped
                ? new ProcessStartInfo("/usr/bin/setsid") { ArgumentList = { "/bin/sh", "-c", GroupScript, "acphys-impl", commandLine } }
                : new ProcessStartInfo("/bin/sh") { ArgumentList = { "-c", commandLine } };
        info.RedirectStandardInput = true;
        info.RedirectStandardOutput = true;
        info.RedirectStandardError = true;
        info.UseShellExecute = false;
        info.StandardInputEncoding = new UTF8Encoding(false);
        info.StandardOutputEncoding = new UTF8Encoding(false);
        info.StandardErrorEncoding = new UTF8Encoding(false);
        string tag = ImplProcesses.NewTag();
        info.Environment[ImplProcesses.Variable] = tag; // inherited by all it starts, a setsid grandchild too

        var process = new Process { StartInfo = info };
        var child = new LineProcess(process, commandLine, stderrSink);
        process.ErrorDataReceived += (_, e) => child.OnStderr(e.Data);
        try
        {
            process.Start();
        }
        catch (Exception e) when (e is System.ComponentModel.Win32Exception or InvalidOperationException)
        {
            process.Dispose();
            throw new AdapterFailureException($"could not start '{commandLine}': {e.Message}", e);
        }

        child.tag = tag;
        LiveTags[tag] = 0;
        if (grouped)
        {
            child.group = process.Id;
            LiveGroups[process.Id] = 0;
            EnsureExitHook();
        }

        process.BeginErrorReadLine();
        process.StandardInput.AutoFlush = true;
        child.stdin = process.StandardInput.BaseStream; // requests are written as bytes (Queue, Flush); the writer stays empty
        child.answers = new BoundedLineReader(process.StandardOutput.BaseStream, maxLineBytes);
        if (process.StandardOutput.BaseStream is System.IO.Pipes.PipeStream pipe)
        {
            int fd = pipe.SafePipeHandle.DangerousGetHandle().ToInt32();
            child.stdoutPipe = ImplProcesses.NameOf(fd);
            if (!OperatingSystem.IsWindows())
            {
                child.stdoutFd = fd;
                child.waitForAnswer = child.WaitForAnswer;
                _ = Poll.GrowPipe(fd, PipeBytes);
            }
        }

        if (process.StandardInput.BaseStream is System.IO.Pipes.PipeStream input && !OperatingSystem.IsWindows())
        {
            // Room for ~80 scene loads ahead of the child (issue 26): with the default 64 KiB the tool blocked writing
            // whenever the child fell a few scenes behind, and each side then waited for the other in turn.
            _ = Poll.GrowPipe(input.SafePipeHandle.DangerousGetHandle().ToInt32(), PipeBytes);
        }

        return child;
    }

    /// <summary>Gets a value indicating whether the child failed earlier (it is not spoken to again).</summary>
    public bool Dead => dead;

    /// <summary>Sends one line and waits for one answer line.</summary>
    /// <param name="request">The request line.</param>
    /// <param name="what">What the request is, for messages (the op name).</param>
    /// <param name="timeout">How long to wait for the answer.</param>
    /// <returns>The answer line.</returns>
    /// <exception cref="AdapterFailureException">The child exited, closed its stdout or did not answer in time.</exception>
    public string Exchange(string request, string what, TimeSpan timeout)
    {
        Send(request, what);
        return Receive(what, request, timeout);
    }

    /// <summary>Sends one line without waiting for its answer (a pipelined request; <see cref="Receive"/> reads the answers in order).</summary>
    /// <param name="request">The request line.</param>
    /// <param name="what">What the request is, for messages (the op name).</param>
    /// <exception cref="AdapterFailureException">The child failed earlier or its stdin is closed.</exception>
    public void Send(string request, string what)
    {
        Queue(request, what);
        Flush(what);
    }

    /// <summary>Gets how many bytes of queued requests are not yet written to the child.</summary>
    public int QueuedBytes => queuedBytes;

    /// <summary>Queues one request line; it reaches the child at the next <see cref="Flush"/> (the same thread sends).</summary>
    /// <param name="request">The request line.</param>
    /// <param name="what">What the request is, for messages (the op name).</param>
    /// <exception cref="AdapterFailureException">The child failed earlier.</exception>
    /// <remarks>Issue 26: one write (and one wake-up of the child) per request was most of a served gate's kernel time;
    /// a pipelined run queues its requests and writes them in batches, and flushes before anything waits for an answer.
    /// The bytes are what the standard-input writer sent (UTF-8 without a byte order mark, lone surrogates as U+FFFD,
    /// the platform's line end).</remarks>
    public void Queue(string request, string what) => Queue(new RequestLine(request), what);

    /// <summary>Queues one request line (its bytes copied as they are, or its text encoded); see <see cref="Queue(string, string)"/>.</summary>
    /// <param name="request">The request line.</param>
    /// <param name="what">What the request is, for messages (the op name).</param>
    /// <exception cref="AdapterFailureException">The child failed earlier.</exception>
    public void Queue(RequestLine request, string what)
    {
        if (dead)
        {
            throw new AdapterFailureException($"'{commandLine}' is no longer running (it failed earlier)");
        }

        string end = Environment.NewLine;
        int need = (request.HasUtf8 ? request.Utf8.Length : Encoding.UTF8.GetByteCount(request.Text)) + Encoding.UTF8.GetByteCount(end);
        if (queued.Length - queuedBytes < need)
        {
            Array.Resize(ref queued, Math.Max(queued.Length * 2, queuedBytes + need));
        }

        var free = queued.AsSpan(queuedBytes);
        if (request.HasUtf8)
        {
            request.Utf8.CopyTo(free);
            queuedBytes += request.Utf8.Length;
        }
        else
        {
            queuedBytes += Encoding.UTF8.GetBytes(request.Text, free);
        }

        queuedBytes += Encoding.UTF8.GetBytes(end, queued.AsSpan(queuedBytes));
    }

    /// <summary>Writes every queued request to the child.</summary>
    /// <param name="what">What the last request is, for messages (the op name).</param>
    /// <exception cref="AdapterFailureException">The child's stdin is closed.</exception>
    public void Flush(string what)
    {
        if (queuedBytes == 0)
        {
            return;
        }

        int count = queuedBytes;
        queuedBytes = 0; // written or lost with the child: never written twice
        try
        {
            stdin!.Write(queued, 0, count);
            stdin.Flush();
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException)
        {
            throw Died($"could not send '{what}' (the pipe is closed)", e);
        }

        if (queued.Length > 1 << 20)
        {
            queued = new byte[64 * 1024]; // one huge request does not keep its buffer for the rest of the run
        }
    }

    /// <summary>Waits for the next answer line. One thread at a time may receive; another may <see cref="Send"/> meanwhile.</summary>
    /// <param name="what">What the request answered is, for messages (the op name).</param>
    /// <param name="request">The request line (a string, or a <see cref="RequestLine"/> spelt only for a message).</param>
    /// <param name="timeout">How long an answer may take (--timeout), for messages.</param>
    /// <param name="wait">How long to wait now (what is left of <paramref name="timeout"/> for a pipelined answer); null waits <paramref name="timeout"/>.</param>
    /// <returns>The answer line.</returns>
    /// <exception cref="AdapterFailureException">The child exited, closed its stdout or did not answer in time.</exception>
    public string Receive(string what, object request, TimeSpan timeout, TimeSpan? wait = null)
    {
        // Two readers at once would take each other's answers (and one found `pending` cleared by the other: a
        // NullReferenceException on the pipeline's reader thread). PipelineSession drains its reader before any live call.
        if (Interlocked.Exchange(ref receiving, 1) != 0)
        {
            throw new InvalidOperationException($"two threads read the answers of '{commandLine}' at once");
        }

        try
        {
            return ReceiveOne(what, request, timeout, wait);
        }
        finally
        {
            Volatile.Write(ref receiving, 0);
        }
    }

    /// <summary>Waits for the next answer line as <see cref="Receive"/> does, and gives its bytes (issue 26: the pipelined
    /// reader compares them with the expected line and spells the text only when it needs it).</summary>
    /// <param name="what">What the request answered is, for messages (the op name).</param>
    /// <param name="request">The request line, for messages.</param>
    /// <param name="timeout">How long an answer may take (--timeout), for messages.</param>
    /// <param name="wait">How long to wait now; null waits <paramref name="timeout"/>.</param>
    /// <returns>The answer line; its bytes are valid until the next receive.</returns>
    /// <exception cref="AdapterFailureException">As <see cref="Receive"/>.</exception>
    internal AnswerLine ReceiveLine(string what, object request, TimeSpan timeout, TimeSpan? wait = null)
    {
        if (Interlocked.Exchange(ref receiving, 1) != 0)
        {
            throw new InvalidOperationException($"two threads read the answers of '{commandLine}' at once");
        }

        try
        {
            if (dead || waitForAnswer is null)
            {
                return AnswerLine.OfText(ReceiveOne(what, request, timeout, wait));
            }

            return ReceiveSynchronously(answers!, what, request, timeout, wait, static (r, waitFor) => r.ReadLineUtf8(waitFor) is { } bytes ? AnswerLine.OfBytes(bytes) : null);
        }
        finally
        {
            Volatile.Write(ref receiving, 0);
        }
    }

    private string ReceiveOne(string what, object request, TimeSpan timeout, TimeSpan? wait)
    {
        if (dead)
        {
            throw new AdapterFailureException($"'{commandLine}' is no longer running (it failed earlier)");
        }

        var reader = answers!;
        if (waitForAnswer is not null)
        {
            return ReceiveSynchronously(reader, what, request, timeout, wait, static (r, waitFor) => r.ReadLine(waitFor));
        }

        pending ??= reader.ReadLineAsync().AsTask(); // asynchronous: no pool thread blocks while the child thinks
        bool answered;
        try
        {
            answered = pending.Wait(wait is { } w ? (w < TimeSpan.Zero ? TimeSpan.Zero : w) : timeout);
        }
        catch (AggregateException e) when (e.InnerException is LineTooLongException tooLong)
        {
            dead = true;
            Kill();
            throw new AdapterFailureException($"'{commandLine}' answered '{what}' with a {tooLong.Message}; it was stopped");
        }
        catch (AggregateException e)
        {
            throw Died($"reading the answer to '{what}' failed", e.InnerException ?? e);
        }

        if (!answered)
        {
            throw TimedOut(what, request, timeout);
        }

        string? line = pending.Result;
        pending = null;
        return line ?? throw Died($"closed its stdout instead of answering '{what}'", null);
    }

    // Linux and macOS: this thread waits for the child's output with poll(2) and reads it itself (issue 26: the
    // asynchronous read cost a pool thread's hand-off and a sched_yield spin per answer — 18 % of a served gate's samples).
    private T ReceiveSynchronously<T>(BoundedLineReader reader, string what, object request, TimeSpan timeout, TimeSpan? wait, Func<BoundedLineReader, Func<bool>, T?> read)
        where T : class
    {
        var allowed = wait is { } w ? (w < TimeSpan.Zero ? TimeSpan.Zero : w) : timeout;
        deadline = allowed >= TimeSpan.FromDays(1) ? long.MaxValue : Stopwatch.GetTimestamp() + (long)(allowed.TotalSeconds * Stopwatch.Frequency);
        T? line;
        try
        {
            line = read(reader, waitForAnswer!);
        }
        catch (TimeoutException)
        {
            throw TimedOut(what, request, timeout);
        }
        catch (LineTooLongException tooLong)
        {
            dead = true;
            Kill();
            throw new AdapterFailureException($"'{commandLine}' answered '{what}' with a {tooLong.Message}; it was stopped");
        }
        catch (IOException e)
        {
            throw Died($"reading the answer to '{what}' failed", e);
        }

        return line ?? throw Died($"closed its stdout instead of answering '{what}'", null);
    }

    // Waits until the child's stdout has input, its end or an error (a read then returns at once); false at the deadline.
    private bool WaitForAnswer()
    {
        while (true)
        {
            long left = deadline == long.MaxValue ? -1 : deadline - Stopwatch.GetTimestamp();
            if (deadline != long.MaxValue && left <= 0)
            {
                return Poll.Readable(stdoutFd, 0);
            }

            int ms = left < 0 ? -1 : (int)Math.Min(int.MaxValue, (left * 1000 + Stopwatch.Frequency - 1) / Stopwatch.Frequency);
            if (Poll.Readable(stdoutFd, ms))
            {
                return true;
            }
        }
    }

    private AdapterFailureException TimedOut(string what, object request, TimeSpan timeout)
    {
        dead = true;
        if (stdoutPipe is not null && ImplProcesses.ClosedStdout(tag, stdoutPipe, commandLine))
        {
            // Alive, but nothing of it can answer any more (issue 28: this was reported as a slow answer).
            Kill();
            return new AdapterFailureException(
                string.Create(CultureInfo.InvariantCulture, $"'{commandLine}' closed its stdout but is still running, so it cannot answer '{what}'; it was killed after {timeout.TotalSeconds:0.###} s (--timeout){TailText()}"));
        }

        Kill();
        return new AdapterFailureException(
            string.Create(CultureInfo.InvariantCulture, $"'{commandLine}' did not answer '{what}' within {timeout.TotalSeconds:0.###} s (--timeout); it was killed. Request: {Wire.Brief(request.ToString() ?? string.Empty, 200)}{TailText()}"));
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        try
        {
            if (!process.HasExited)
            {
                if (!dead && queuedBytes > 0)
                {
                    Flush("end of input");
                }

                process.StandardInput.Close(); // end of input: a well-behaved implementation exits
                if (!process.WaitForExit(1000))
                {
                    Kill();
                }
            }
        }
        catch (Exception e) when (e is IOException or InvalidOperationException or AdapterFailureException)
        {
            Kill();
        }

        KillGroup();
        process.Dispose();
    }
}
