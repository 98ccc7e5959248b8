using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Judging;

namespace AcPhys.Spec.Capture;

/// <summary>A finding minimised: the walk file's entry, how many frames it kept, and what its replay violates.</summary>
/// <param name="Entry">The walk case with the port's recorded answers.</param>
/// <param name="Frames">The frames it kept (queries of the walk).</param>
/// <param name="Violated">The invariants its replay violates (recorded answers against the reference).</param>
internal sealed record MinimisedCapture(CorpusEntry Entry, int Frames, IReadOnlyList<string> Violated);

/// <summary>
/// Shrinks a finding of a capture to the shortest walk that still shows it: from the last agreed frame before its span
/// (earlier frames dropped), frames are delta-debugged away (halves, quarters, … then one at a time) and the remaining
/// positions snapped to simpler numbers (as <see cref="WalkShrinker"/> does), by the project's shrink loop
/// (<see cref="GreedyShrink"/>). A candidate still shows the finding when its replay (the recorded answers judged by the
/// ordinary walk invariants against the reference) fails first at a step that the capture judge, at that frame's printed
/// precision, also finds divergent with the same cause — so the walk written never asserts what the capture could not.
/// </summary>
internal sealed class CaptureMinimiser
{
    /// <summary>Most candidates tried per finding.</summary>
    public const int Budget = 4000;

    private readonly ICellPhysics reference;
    private readonly OutdoorJudge judge;
    private readonly CaseMode? mode;

    /// <summary>Initializes a new instance of the <see cref="CaptureMinimiser"/> class.</summary>
    /// <param name="pick">The declared pick.</param>
    /// <param name="outdoor">The declared outdoor fidelity.</param>
    /// <param name="mode">The mode to store in the file (null: retail).</param>
    public CaptureMinimiser(PickPolicy pick, OutdoorFidelity outdoor, CaseMode? mode)
    {
        reference = new ReferenceAdapter(pick, outdoor: outdoor);
        judge = new OutdoorJudge(pick, outdoor);
        this.mode = mode;
    }

    /// <summary>Minimises a span's window.</summary>
    /// <param name="span">The span (its <see cref="DivergentSpan.Window"/> kept by the checker).</param>
    /// <param name="source">The capture's name, for the title.</param>
    /// <returns>The minimised case, or null when the window shows nothing a walk can replay (e.g. no recorded cells).</returns>
    public MinimisedCapture? Minimise(DivergentSpan span, string source)
    {
        var start = span.Window.Where(f => !f.Cell.IsNone).ToArray();
        if (start.Length == 0 || !Shows(start, span.Cause))
        {
            return null;
        }

        var least = GreedyShrink.Run(start, Candidates, c => Shows(c, span.Cause), Budget);
        var (walk, recorded) = CaptureWalk.Of(least, least[0].Body);
        var run = CaseRun.Of(new RecordedPhysics(walk, recorded, reference), walk);
        string title = $"capture {Path.GetFileName(source)}: frame {span.First.Number} (line {span.First.Line}), {span.Describe()}";
        var entry = new CorpusEntry
        {
            Title = title.Length <= CorpusJson.MaxTitle ? title : title[..CorpusJson.MaxTitle],
            Invariant = run.Judgement.ViolatedIds.FirstOrDefault(),
            FoundBy = FinderNames.Capture,
            Mode = mode,
            Walk = walk,
            Recorded = recorded,
        };
        return new MinimisedCapture(entry, least.Length, run.Judgement.ViolatedIds);
    }

    private static IEnumerable<KeptFrame[]> Candidates(KeptFrame[] frames)
    {
        for (int parts = 2; parts <= frames.Length; parts *= 2)
        {
            int size = (frames.Length + parts - 1) / parts;
            for (int from = 0; from < frames.Length; from += size)
            {
                int end = Math.Min(frames.Length, from + size);
                KeptFrame[] rest = [.. frames.AsSpan(0, from), .. frames.AsSpan(end)];
                if (rest.Length > 0 && rest.Length < frames.Length)
                {
                    yield return rest;
                }
            }
        }

        for (int i = 0; i < frames.Length && frames.Length > 1; i++)
        {
            yield return [.. frames.AsSpan(0, i), .. frames.AsSpan(i + 1)];
        }

        var body = frames[0].Body;
        for (int s = body.Length - 1; s >= 1; s--)
        {
            BodySphere[] fewer = [.. body.Take(s), .. body.Skip(s + 1)];
            yield return [.. frames.Select(f => f with { Body = fewer })];
        }

        for (int i = 0; i < frames.Length; i++)
        {
            var f = frames[i];
            double bx = LandDefs.BlockLength * Math.Floor(f.WorldX / LandDefs.BlockLength), by = LandDefs.BlockLength * Math.Floor(f.WorldY / LandDefs.BlockLength);
            foreach (float x in Snap.Simpler((float)(f.WorldX - bx)))
            {
                yield return With(frames, i, f with { World = f.World with { X = bx + x } });
            }

            foreach (float y in Snap.Simpler((float)(f.WorldY - by)))
            {
                yield return With(frames, i, f with { World = f.World with { Y = by + y } });
            }
        }
    }

    private static KeptFrame[] With(KeptFrame[] frames, int i, KeptFrame f)
    {
        var copy = frames.ToArray();
        copy[i] = f;
        return copy;
    }

    private bool Shows(KeptFrame[] frames, string cause)
    {
        var (walk, recorded) = CaptureWalk.Of(frames, frames[0].Body);
        var run = CaseRun.Of(new RecordedPhysics(walk, recorded, reference), walk);
        if (run.FirstViolatingStep is not int step || step >= frames.Length)
        {
            return false;
        }

        var query = frames[step].Query(step == 0 ? CellId.None : frames[step - 1].Cell) with { Body = frames[0].Body };
        var verdict = judge.Judge(query);
        return verdict.Kind == VerdictKind.Diverges && CaptureCauses.Of(query, verdict) == cause;
    }
}
