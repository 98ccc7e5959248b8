using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Pipeline;

/// <summary>The stream: requests queued and handed to the child in batches, and the reader thread that takes the child's answers in order, each compared with its guess as it arrives.</summary>
internal sealed partial class PipelineSession : IDisposable
{
    private void Send(Sent sent)
    {
        if (Diverged)
        {
            sent.Done?.Set();
            return; // nothing more is sent after a difference: the pass is discarded
        }

        if (inFlight.IsAddingCompleted)
        {
            throw new InvalidOperationException("a query was streamed after the pass went live"); // Live drained the stream
        }

        try
        {
            child.Queue(sent.Request, sent.Name);
            sent.Request.Written();
        }
        catch (AdapterFailureException e)
        {
            sent.Done?.Set();
            Diverge(sent.Query, null, null, e, primary: false);
            return;
        }

        inFlight.Add(sent);
        long now = Stopwatch.GetTimestamp();
        if (queued.Count == 0)
        {
            queuedSince = now;
        }

        queued.Add(sent);
        if (child.QueuedBytes >= FlushBytes || now - queuedSince >= FlushTicks)
        {
            Hand();
        }
    }

    // Writes the queued requests to the child. Each one's answer is timed from here (the reader waits for this hand-off
    // before it starts the clock), so a request held in the queue never counts against the child.
    private void Hand()
    {
        if (queued.Count == 0)
        {
            return;
        }

        var first = queued[0];
        lock (handoff)
        {
            long now = Stopwatch.GetTimestamp();
            foreach (var sent in queued)
            {
                sent.At = now;
                sent.Handed = true;
            }

            Monitor.PulseAll(handoff);
        }

        string last = queued[^1].Name;
        queued.Clear();
        try
        {
            long t = WireProfile.Start();
            child.Flush(last);
            WireProfile.Stop("tool: send (pipe write)", t);
        }
        catch (AdapterFailureException e)
        {
            // The reader then fails every answer still awaited; what it saw first (a hang, an exit) is what is reported.
            Diverge(first.Query, null, null, e, primary: false);
        }
    }

    // The reader's side of the hand-off: a request still queued is not the child's to answer yet.
    private void AwaitHanded(Sent sent)
    {
        if (sent.Handed)
        {
            return;
        }

        lock (handoff)
        {
            while (!sent.Handed)
            {
                Monitor.Wait(handoff);
            }
        }
    }

    private void Diverge(int query, string? request, string? line, AdapterFailureException? failed, bool primary = true)
    {
        lock (sync)
        {
            childFailure ??= primary ? failed : null;
            sendFailure ??= primary ? null : failed;
            if (divergedAt >= 0 && divergedAt <= query)
            {
                return;
            }

            divergedRequest = request;
            divergedLine = line;
            divergedPass = passes;
            Difference = failed is not null ? "the implementation failed: " + Wire.Brief(failed.Message, 160)
                : line is null ? "a scene load or unload was not answered as guessed"
                : $"{Wire.Brief(request!, 160)} was answered {Wire.Brief(line, 160)}";
            failure = failed;
            Volatile.Write(ref divergedAt, query);
        }
    }

    // The reader: one answer per sent request, in order, each within the timeout of its request or the previous
    // answer; after a difference the answers are still read (the stream stays aligned) but not compared.
    private void Read()
    {
        bool dead = false;
        foreach (var sent in inFlight.GetConsumingEnumerable())
        {
            try
            {
                if (dead)
                {
                    continue;
                }

                AwaitHanded(sent);
                long since = Math.Max(sent.At, lastAnswer);
                bool failedBefore = child.Dead; // then a failed send said what happened, and this is only "no longer running"
                AnswerLine line;
                try
                {
                    line = child.ReceiveLine(sent.Name, sent.Request, timeout, timeout - Stopwatch.GetElapsedTime(since));
                }
                catch (AdapterFailureException e)
                {
                    dead = true;
                    Diverge(sent.Query, null, null, e, primary: !failedBefore);
                    continue;
                }

                lastAnswer = Stopwatch.GetTimestamp();
                if (Diverged && sent.Done is null)
                {
                    if (!sent.IsTransport && !sent.Request.IsCut && divergedPass == passes && sent.Query > divergedAt)
                    {
                        after[sent.Query] = (sent.Request.Text, line.Text); // the next pass may take it (Reuse)
                    }

                    continue;
                }

                bool same;
                try
                {
                    long m = WireProfile.Start();
                    same = sent.Matches(line);
                    WireProfile.Stop("tool: compare (reader thread)", m);
                }
                catch (Exception e) when (e is not OutOfMemoryException)
                {
                    same = false; // an error answer or one that is not protocol v1: the replay reads it as the live call would
                }

                if (!same)
                {
                    Diverge(sent.Query, sent.IsTransport ? null : sent.Request.Text, sent.IsTransport ? null : line.Text, null);
                }
            }
            finally
            {
                sent.Done?.Set();
            }
        }
    }
}
