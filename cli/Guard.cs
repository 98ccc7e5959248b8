using System.Runtime.InteropServices;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Corpus;

namespace AcPhys.Cli;

/// <summary>
/// Runs a command's body with the tool's error policy: bad input, unreadable files and implementations that cannot
/// answer become a one-line message and exit 2; Ctrl-C (SIGINT) and SIGTERM stop the run with 130 / 143, never a stack trace.
/// </summary>
internal static class Guard
{
    /// <summary>Runs <paramref name="body"/> on a worker thread and maps its outcome to an exit code.</summary>
    /// <param name="verb">The command name, for messages.</param>
    /// <param name="body">The work; returns the exit code.</param>
    /// <returns>The exit code.</returns>
    public static int Run(string verb, Func<int> body)
    {
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

        int exit = ExitCodes.ToolError;
        Exception? error = null;
        var worker = new Thread(() =>
        {
            try
            {
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
        if (!done.IsSet)
        {
            Terminal.RestoreCursor();
            Terminal.Error(verb, signalExit == ExitCodes.Terminated ? "terminated" : "interrupted");
            return signalExit;
        }

        return error is null ? exit : Report(verb, error);
    }

    private static int Report(string verb, Exception error)
    {
        switch (error)
        {
            case OutputPathException:
                Terminal.Error(verb, error.Message);
                return ExitCodes.OutputError;
            case UsageException or CorpusFormatException or AcPhys.Spec.Dat.DatFormatException:
                Terminal.Error(verb, error.Message);
                break;
            case AdapterFailureException:
                Terminal.Error(verb, "the implementation could not answer: " + error.Message);
                break;
            default:
                Terminal.Error(verb, $"internal error: {error.GetType().Name}: {error.Message} (set ACPHYS_DEBUG=1 for the stack trace)");
                if (Environment.GetEnvironmentVariable("ACPHYS_DEBUG") is "1" or "true")
                {
                    Console.Error.WriteLine(error);
                }

                break;
        }

        return ExitCodes.ToolError;
    }
}
