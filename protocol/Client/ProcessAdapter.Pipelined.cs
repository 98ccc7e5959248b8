using System.Runtime.ExceptionServices;
using AcPhys.Contract;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Pipeline;

namespace AcPhys.Protocol.Client;

/// <summary>Speculation: a pipelined run's passes (<see cref="PipelineSession"/>) and the guesses' optional fields.</summary>
public sealed partial class ProcessAdapter
{
    /// <summary>
    /// Runs <paramref name="run"/> (one invariant's whole run: its cases, shrinking and re-checks) against a child that
    /// announced <c>pipeline</c> without waiting for each answer: every query is answered at once with a guess (the
    /// reference in the declared mode) and streamed to the child, whose answers are compared as they arrive. When every
    /// answer equalled its guess, that result is the live run's; otherwise <paramref name="run"/> runs again with the
    /// answers before the first difference replayed, the differing one as the child gave it, and the rest guessed and
    /// streamed again (live after a few differences) — the same result as a live run (docs/protocol.md, "Pipelining").
    /// Without <c>pipeline</c> it just runs.
    /// </summary>
    /// <typeparam name="T">The run's result.</typeparam>
    /// <param name="run">The run; called again after each pass in which an answer differed (what an earlier call reported is to be discarded).</param>
    /// <returns>The result.</returns>
    /// <remarks>The adapter must be used from the calling thread only while it runs.</remarks>
    public T Pipelined<T>(Func<T> run)
    {
        if (!Pipelines || session is not null)
        {
            return run();
        }

        List<string> ids;
        lock (loaded)
        {
            ids = [.. loaded.Select(e => e.Id)];
        }

        using var s = new PipelineSession(child, timeout, ids, reader);
        session = s;
        try
        {
            for (int pass = 1; ; pass++)
            {
                T result = default!;
                ExceptionDispatchInfo? thrown = null;
                try
                {
                    long r = WireProfile.Start();
                    result = run();
                    WireProfile.Stop("tool: pipelined runs (all)", r);
                }
                catch (Exception e) when (e is not OutOfMemoryException)
                {
                    thrown = ExceptionDispatchInfo.Capture(e);
                }

                long f = WireProfile.Start();
                bool stands = s.Finish();
                WireProfile.Stop("tool: pass end, waiting for the child", f);
                if (stands)
                {
                    PipelineCounts = (PipelineCounts.Runs + 1, PipelineCounts.Replays + (pass > 1 ? 1 : 0));
                    thrown?.Throw();
                    return result;
                }

                if (differences.Count < 5 && s.Difference is { } why)
                {
                    differences.Add(why);
                }

                s.NextPass(UnloadQuietly);
                lock (loaded)
                {
                    loaded.Clear();
                }
            }
        }
        finally
        {
            session = null;
        }
    }

    // After a difference: the child may hold scenes the first pass loaded; an unknown id is no finding here.
    private void UnloadQuietly(string id)
    {
        try
        {
            Live("unload_scene", Request("unload_scene", w => w.WriteString("scene_id", id)), Answers.Ok.Read);
        }
        catch (ImplementationErrorException)
        {
            // Not loaded after all (its load was refused): nothing to unload.
        }
    }

    // The optional find_cell fields (loaded, hits_interior_cell) a child reports are learnt from its first answer, on
    // open land and in scenes apart; a guess carries only those, since the answer read from the child has only those.
    private FindCellResult Learn(FindCellResult answer, bool scene)
    {
        reported[scene ? 1 : 0].Learn(answer);
        return answer;
    }

    private IReadOnlyList<FindCellResult> LearnAll(IReadOnlyList<FindCellResult> answers, bool scene)
    {
        if (answers.Count > 0)
        {
            Learn(answers[0], scene);
        }

        return answers;
    }

    private FindCellResult Project(FindCellResult guess, bool scene) => reported[scene ? 1 : 0].Project(guess);

    private IReadOnlyList<FindCellResult> ProjectAll(IReadOnlyList<FindCellResult> guesses, bool scene)
    {
        if (reported[scene ? 1 : 0].ReportsAll)
        {
            return guesses; // every optional field reported: the guesses as they are (issue 26: a copy per step cost the main thread)
        }

        var projected = new FindCellResult[guesses.Count];
        for (int i = 0; i < projected.Length; i++)
        {
            projected[i] = Project(guesses[i], scene);
        }

        return projected;
    }
}
