using System.Diagnostics;
using System.Text;
using System.Text.RegularExpressions;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// Progress honesty (issue 19): a long command whose output goes to a log prints a progress line every
/// <c>ACPHYS_PROGRESS_SECONDS</c> (30 s by default; about 1 s here); a verify stopped by SIGTERM prints what it had
/// finished; a signal to bench leaves no child behind (it starts none).
/// </summary>
public sealed partial class ProgressTests
{
    [Fact(DisplayName = "A redirected verify prints progress lines, and on SIGTERM a summary of what it had finished, exit 143")]
    public void VerifyLogsProgressAndSummarisesWhenTerminated()
    {
        using var run = new LiveRun(["verify", "--cases", "20000"], new Dictionary<string, string> { ["ACPHYS_PROGRESS_SECONDS"] = "1" });
        Assert.True(Poll.Until(TimeSpan.FromMinutes(4), () => Done().Match(run.Err).Success), "no progress line with a finished invariant: " + run.Err);
        Signals.Send("TERM", run.Process.Id);
        Assert.True(run.Process.WaitForExit(30_000), "verify did not stop on SIGTERM");
        run.Process.WaitForExit(); // the output readers finish

        Assert.True(run.Process.ExitCode == 143, $"exit {run.Process.ExitCode}\n{run.Out}\n{run.Err}");
        Assert.Contains("acphys verify: terminated", run.Err, StringComparison.Ordinal);
        var summary = Stopped().Match(run.Out);
        Assert.True(summary.Success, "no partial summary: " + run.Out);
        Assert.True(int.Parse(summary.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) >= 1, summary.Value);
        Assert.True(Heartbeat().Matches(run.Err).Count >= 1, run.Err);
    }

    [Fact(DisplayName = "A redirected bench prints progress lines; SIGTERM stops it with 143 and it had no child process to leave behind")]
    public void BenchLogsProgressAndLeavesNoChild()
    {
        using var run = new LiveRun(["bench", "--round-ms", "50", "--rounds", "5"], new Dictionary<string, string> { ["ACPHYS_PROGRESS_SECONDS"] = "0.5" });
        Assert.True(Poll.Until(TimeSpan.FromMinutes(2), () => run.Err.Contains("acphys bench: ", StringComparison.Ordinal)), "no progress line: " + run.Err);
        var children = Signals.Children(run.Process.Id);
        Signals.Send("TERM", run.Process.Id);
        Assert.True(run.Process.WaitForExit(30_000), "bench did not stop on SIGTERM");
        Assert.Equal(143, run.Process.ExitCode);
        Assert.Empty(children); // bench measures in-process: nothing to orphan
    }

    [GeneratedRegex(@"acphys verify reference: [1-9]\d*/\d+ done after")]
    private static partial Regex Done();

    [GeneratedRegex(@"acphys verify reference: \d+/\d+ done after")]
    private static partial Regex Heartbeat();

    [GeneratedRegex(@"verify: stopped after (\d+) of 47 invariants, \d+ passed, \d+ failed, \d+ not tested, the rest not run")]
    private static partial Regex Stopped();

    /// <summary>acphys running with stdout and stderr collected as they come.</summary>
    private sealed class LiveRun : IDisposable
    {
        private readonly StringBuilder stdout = new();
        private readonly StringBuilder stderr = new();

        public LiveRun(IEnumerable<string> args, IReadOnlyDictionary<string, string> environment)
        {
            Process = new Process { StartInfo = Acphys.Info(args, environment) };
            Process.OutputDataReceived += (_, e) => Append(stdout, e.Data);
            Process.ErrorDataReceived += (_, e) => Append(stderr, e.Data);
            Process.Start();
            Process.BeginOutputReadLine();
            Process.BeginErrorReadLine();
        }

        public Process Process { get; }

        public string Out => Read(stdout);

        public string Err => Read(stderr);

        public void Dispose()
        {
            if (!Process.HasExited)
            {
                Process.Kill(entireProcessTree: true);
            }

            Process.Dispose();
        }

        private static void Append(StringBuilder sb, string? line)
        {
            if (line is not null)
            {
                lock (sb)
                {
                    sb.Append(line).Append('\n');
                }
            }
        }

        private static string Read(StringBuilder sb)
        {
            lock (sb)
            {
                return sb.ToString();
            }
        }
    }
}
