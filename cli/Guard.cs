using System.Runtime.InteropServices;
using AcPhys.Contract;
using AcPhys.Formats;

namespace AcPhys.Cli;

/// <summary>
/// Runs a command's body with the tool's error policy: bad input, unreadable files and implementations that cannot
/// answer become a one-line message and exit 2; a bug of the tool is one line and exit 70 (the stack trace with
/// <c>ACPHYS_DEBUG=1</c>); Ctrl-C (SIGINT) and SIGTERM stop the run with 130 / 143, never a stack trace.
/// </summary>
internal static class Guard
{
    private static Action? stopReport;
    private static Action<string>? abort;
    private static string? abortMessage;
    private static int returned;

    /// <summary>Gets a value indicating whether the command has finished and the process is ending normally (not through an Environment.Exit elsewhere).</summary>
    public static bool Returned => Volatile.Read(ref returned) != 0;

    /// <summary>Stops the running command at once with exit 2 and one message (an in-process implementation that hangs, issue 28).</summary>
    /// <param name="message">What went wrong.</param>
    /// <returns>Whether a command was running to stop.</returns>
    public static bool Abort(string message)
    {
        var stop = Volatile.Read(ref abort);
        stop?.Invoke(message);
        return stop is not null;
    }

    /// <summary>Registers what the running command prints when a signal stops it (its partial results).</summary>
    /// <param name="report">Prints them; runs on the signal's thread while the work may still be going.</param>
    public static void OnStop(Action report) => Volatile.Write(ref stopReport, report);

    /// <summary>Runs <paramref name="body"/> on a worker thread and maps its outcome to an exit code.</summary>
    /// <param name="verb">The command name, for messages.</param>
    /// <param name="body">The work; returns the exit code.</param>
    /// <returns>The exit code.</returns>
    public static int Run(string verb, Func<int> body)
    {
        stopReport = null;
        // Not disposed on purpose: an interrupted worker may still signal them while the process is exiting.
        var done = new ManualResetEventSlim();
        var stopped = new ManualResetEventSlim();
        int signalExit = 0;

        void OnSignal(PosixSignalContext context, int code)
        {
            context.Cancel = true;
            Interlocked.CompareExchange(ref signalExit, code, 0);
            stopped.Set();
        }

        using var sigint = PosixSignalRegistration.Create(PosixSignal.SIGINT, c => OnSignal(c, ExitCodes.Interrupted));
        using var sigterm = PosixSignalRegistration.Create(PosixSignal.SIGTERM, c => OnSignal(c, ExitCodes.Terminated));
        Volatile.Write(ref abort, message =>
        {
            Volatile.Write(ref abortMessage, message);
            Interlocked.CompareExchange(ref signalExit, ExitCodes.ToolError, 0);
            stopped.Set();
        });

        int exit = ExitCodes.ToolError;
        Exception? error = null;
        var worker = new Thread(() =>
        {
            try
            {
                InternalErrorDrill.Check(verb);
                exit = body();
            }
            catch (Exception e)
            {
                error = e;
            }
            finally
            {
                done.Set();
            }
        })
        {
            IsBackground = true,
            Name = "acphys " + verb,
        };

        worker.Start();
        WaitHandle.WaitAny([done.WaitHandle, stopped.WaitHandle]);
        Volatile.Write(ref abort, null);
        Volatile.Write(ref returned, 1);
        if (!done.IsSet)
        {
            Terminal.RestoreCursor();
            Terminal.Error(verb, Volatile.Read(ref abortMessage) ?? (signalExit == ExitCodes.Terminated ? "terminated" : "interrupted"));
            try
            {
                Volatile.Read(ref stopReport)?.Invoke(); // what the command had finished (issue 19: a killed verify printed nothing)
            }
            catch (Exception e) when (e is IOException or InvalidOperationException)
            {
                Terminal.Error(verb, "could not print what had finished: " + e.Message);
            }

            return signalExit;
        }

        return error is null ? exit : Report(verb, error);
    }

    private static string FirstLine(string message) =>
        AcPhys.Formats.Values.InputQuote.Brief(message.Split('\n', 2)[0].TrimEnd('\r'), 200);

    private static int Report(string verb, Exception error)
    {
        switch (error)
        {
            case OutputPathException:
                Terminal.Error(verb, error.Message);
                return ExitCodes.OutputError;
            case AcPhys.Formats.Dat.Container.DatContainerException:
                Terminal.Error(verb, error.Message);
                return ExitCodes.BadDat;
            case UsageException or InputFormatException:
                Terminal.Error(verb, error.Message);
                break;
            case AdapterFailureException:
                Terminal.Error(verb, "the implementation could not answer: " + error.Message);
                break;
            default:
                // A bug of the tool: one line for a user (the exception's message cut, it may quote input), the whole trace for a developer.
                bool debug = AcPhys.Spec.Running.ToolEnvironment.Process.Debug;
                Terminal.Error(verb, $"internal error: {error.GetType().Name}: {FirstLine(error.Message)}{(debug ? string.Empty : " (set ACPHYS_DEBUG=1 for the stack trace)")}");
                if (debug)
                {
                    Console.Error.WriteLine(error);
                }

                return ExitCodes.InternalError;
        }

        return ExitCodes.ToolError;
    }
}
