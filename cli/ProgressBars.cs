using Spectre.Console;

namespace AcPhys.Cli;

/// <summary>
/// A progress bar on stderr for long runs (one step per invariant or check) on an interactive terminal; a log (stderr
/// redirected) gets a line every 30 s instead (<see cref="ProgressLog"/>); <c>--quiet</c> gets neither.
/// </summary>
internal static class ProgressBars
{
    /// <summary>Runs <paramref name="work"/> with a bar of <paramref name="total"/> steps (or progress lines when there is no terminal).</summary>
    /// <param name="title">What is running.</param>
    /// <param name="total">The number of steps.</param>
    /// <param name="work">The work; calls its argument after each step with what just finished.</param>
    /// <param name="enabled">False to run without a bar (<c>--quiet</c>).</param>
    public static void Run(string title, int total, Action<Action<string>> work, bool enabled = true)
    {
        if (!enabled)
        {
            work(_ => { });
            return;
        }

        if (!Terminal.ShowsProgress)
        {
            using var log = new ProgressLog(title, total);
            work(log.Advance);
            return;
        }

        Terminal.Err.Progress()
            .AutoClear(true)
            .HideCompleted(true)
            .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn(), new SpinnerColumn())
            .Start(context =>
            {
                var task = context.AddTask(Markup.Escape(title), maxValue: Math.Max(total, 1));
                work(last =>
                {
                    task.Increment(1);
                    task.Description = Markup.Escape($"{title}: {task.Value:0}/{total} (last {last})");
                });
                task.StopTask();
            });
    }
}
