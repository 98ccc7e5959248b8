using System.Collections.Concurrent;
using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Text;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Protocol;

/// <summary>
/// A child process spoken to one line at a time over stdin/stdout, with a per-exchange timeout. Its stderr is the
/// implementation's log: every line goes to a sink (passed through) and the last lines are kept for error messages.
/// Anything that stops an answer (exit, hang, broken pipe) becomes an <see cref="AdapterFailureException"/>.
/// </summary>
internal sealed class LineProcess : IDisposable
{
    private const int TailLines = 20;
    private const int SigKill = 9;
    private const int MaxStderrChars = 1000;

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
        child.answers = new BoundedLineReader(process.StandardOutput.BaseStream, maxLineBytes);
        if (process.StandardOutput.BaseStream is System.IO.Pipes.PipeStream pipe)
        {
            child.stdoutPipe = ImplProcesses.NameOf(pipe.SafePipeHandle.DangerousGetHandle().ToInt32());
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
        if (dead)
        {
            throw new AdapterFailureException($"'{commandLine}' is no longer running (it failed earlier)");
        }

        try
        {
            process.StandardInput.WriteLine(request);
        }
        catch (IOException e)
        {
            throw Died($"could not send '{what}' (the pipe is closed)", e);
        }
    }

    /// <summary>Waits for the next answer line. One thread at a time may receive; another may <see cref="Send"/> meanwhile.</summary>
    /// <param name="what">What the request answered is, for messages (the op name).</param>
    /// <param name="request">The request line (or its first characters), for messages.</param>
    /// <param name="timeout">How long an answer may take (--timeout), for messages.</param>
    /// <param name="wait">How long to wait now (what is left of <paramref name="timeout"/> for a pipelined answer); null waits <paramref name="timeout"/>.</param>
    /// <returns>The answer line.</returns>
    /// <exception cref="AdapterFailureException">The child exited, closed its stdout or did not answer in time.</exception>
    public string Receive(string what, string request, TimeSpan timeout, TimeSpan? wait = null)
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

    private string ReceiveOne(string what, string request, TimeSpan timeout, TimeSpan? wait)
    {
        if (dead)
        {
            throw new AdapterFailureException($"'{commandLine}' is no longer running (it failed earlier)");
        }

        var reader = answers!;
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
            dead = true;
            if (stdoutPipe is not null && ImplProcesses.ClosedStdout(tag, stdoutPipe, commandLine))
            {
                // Alive, but nothing of it can answer any more (issue 28: this was reported as a slow answer).
                Kill();
                throw new AdapterFailureException(
                    string.Create(CultureInfo.InvariantCulture, $"'{commandLine}' closed its stdout but is still running, so it cannot answer '{what}'; it was killed after {timeout.TotalSeconds:0.###} s (--timeout){TailText()}"));
            }

            Kill();
            throw new AdapterFailureException(
                string.Create(CultureInfo.InvariantCulture, $"'{commandLine}' did not answer '{what}' within {timeout.TotalSeconds:0.###} s (--timeout); it was killed. Request: {Wire.Brief(request, 200)}{TailText()}"));
        }

        string? line = pending.Result;
        pending = null;
        return line ?? throw Died($"closed its stdout instead of answering '{what}'", null);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        try
        {
            if (!process.HasExited)
            {
                process.StandardInput.Close(); // end of input: a well-behaved implementation exits
                if (!process.WaitForExit(1000))
                {
                    Kill();
                }
            }
        }
        catch (Exception e) when (e is IOException or InvalidOperationException)
        {
            Kill();
        }

        KillGroup();
        process.Dispose();
    }

    /// <summary>Ends every implementation process group still running (acphys is exiting, a signal stopped the run).</summary>
    internal static void KillAllGroups()
    {
        foreach (int pgid in LiveGroups.Keys)
        {
            if (LiveGroups.TryRemove(pgid, out _))
            {
                _ = NativeKill(-pgid, SigKill);
            }
        }

        foreach (string tag in LiveTags.Keys)
        {
            if (LiveTags.TryRemove(tag, out _))
            {
                ImplProcesses.KillTagged(tag);
            }
        }
    }

    private static void EnsureExitHook()
    {
        if (Interlocked.Exchange(ref exitHooked, 1) == 0)
        {
            AppDomain.CurrentDomain.ProcessExit += (_, _) => KillAllGroups();
        }
    }

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
    private static extern int NativeKill(int pid, int signal);

    private void KillGroup()
    {
        if (group != 0 && LiveGroups.TryRemove(group, out _))
        {
            _ = NativeKill(-group, SigKill); // the implementation, anything it started, and the watcher
        }

        if (LiveTags.TryRemove(tag, out _))
        {
            ImplProcesses.KillTagged(tag); // what left the group (setsid) but still carries the run's tag
        }
    }

    private AdapterFailureException Died(string what, Exception? inner)
    {
        dead = true;
        string status = process.WaitForExit(2000)
            ? string.Create(CultureInfo.InvariantCulture, $"exited with code {process.ExitCode}")
            : "is still running";
        string message = $"'{commandLine}' {what}; the process {status}{TailText()}";
        return inner is null ? new AdapterFailureException(message) : new AdapterFailureException(message, inner);
    }

    private string TailText()
    {
        // stderr arrives asynchronously: give the last lines a moment to land before quoting them.
        Thread.Sleep(50);
        var lines = tail.ToArray();
        return lines.Length == 0 ? " (nothing on its stderr)" : $". Last stderr lines:{Environment.NewLine}  " + string.Join(Environment.NewLine + "  ", lines.TakeLast(8));
    }

    private void Kill()
    {
        KillGroup();
        try
        {
            process.Kill(entireProcessTree: true);
            process.WaitForExit(2000);
        }
        catch (Exception e) when (e is InvalidOperationException or System.ComponentModel.Win32Exception or NotSupportedException)
        {
            // Already gone.
        }
    }

    private void OnStderr(string? line)
    {
        if (line is null)
        {
            return;
        }

        line = Values.InputQuote.Line(line, MaxStderrChars); // the child's text: no raw control characters, no endless line (issue 28)
        tail.Enqueue(line);
        while (tail.Count > TailLines && tail.TryDequeue(out _))
        {
        }

        stderrSink?.Invoke(line);
    }
}
