using System.Collections.Concurrent;
using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Pipeline;

/// <summary>
/// One speculative run against a child that announced <c>pipeline</c> (docs/protocol.md, "Pipelining"). In the first
/// pass every query is answered at once with a guess (the reference in the implementation's declared mode) and streamed
/// to the child without waiting; a reader thread takes the child's answers in order and compares each with its guess.
/// When every answer equals its guess, the pass is what a live run gives (a run is a deterministic function of its
/// answers). Otherwise the caller runs again: the queries before the first difference are answered with the same
/// guesses (they were the child's answers), the one that differed with the child's answer, and the rest are guessed and
/// streamed again — up to <see cref="MaxPasses"/> passes, after which the rest is asked live.
/// </summary>
/// <remarks>
/// A query whose guess cannot be made (the reference threw, or the answer's optional fields are not known yet) is sent
/// and awaited within the pass, and its answer kept for the replay. Scene loads and unloads travel in the stream too
/// (client-chosen ids); they are transport, not queries, so the replay pass never replays them: after a difference every
/// scene the child may hold is unloaded and loaded again on demand.
/// </remarks>
internal sealed partial class PipelineSession : IDisposable
{
    /// <summary>The most passes of one run: after as many differences the rest of the run is asked live.</summary>
    public const int MaxPasses = 6;

    // Queued requests are written when this many bytes wait, or the oldest has waited this long (issue 26: a write
    // and a wake-up of the child per request was most of a served gate's kernel time), and before anything waits.
    private const int FlushBytes = 32 * 1024;
    private static readonly long FlushTicks = Stopwatch.Frequency / 1000;

    private readonly LineProcess child;
    private readonly TimeSpan timeout;
    private readonly List<string> names = [];
    private readonly Dictionary<int, (string Request, string Line)> awaited = [];
    private BlockingCollection<Sent> inFlight = [];
    private readonly ReaderThread reader;
    private readonly HashSet<string> maybeLoaded;
    private readonly Lock sync = new();
    private readonly object handoff = new();
    private readonly List<Sent> queued = [];
    private long queuedSince;
    private int divergedAt = -1;
    private string? divergedRequest;
    private string? divergedLine;
    private AdapterFailureException? failure;
    private AdapterFailureException? childFailure;
    private AdapterFailureException? sendFailure;
    private int next;
    private int building = -1;
    private long lastAnswer;
    private int frontier;
    private int liveFrom = int.MaxValue;
    private int passes = 1;
    private int divergedPass;

    // Answers the child gave after the first difference of a pass (read to keep the stream aligned), by query slot:
    // the next pass takes one as the child's answer while its requests are those of the previous pass, slot for slot
    // (the child then saw the very requests the live run sends), instead of asking again (issue 40: a fuzz input near a
    // planted fault differed on several answers, one more pass and round trip each). Never with scene loads in the stream.
    private readonly Dictionary<int, (string Request, string Line)> after = [];
    private Dictionary<int, (string Request, string Line)> reusable = [];
    private volatile bool transported;

    /// <summary>Initializes a new instance of the <see cref="PipelineSession"/> class and starts its reader.</summary>
    /// <param name="child">The child (its answers are read by this session's reader until <see cref="Finish"/>).</param>
    /// <param name="timeout">The most one answer may take, counted from its request or the previous answer, whichever is later.</param>
    /// <param name="loadedIds">The scene ids the child holds now.</param>
    /// <param name="reader">The thread that reads the answers (the adapter's, idle between sessions).</param>
    public PipelineSession(LineProcess child, TimeSpan timeout, IEnumerable<string> loadedIds, ReaderThread reader)
    {
        this.child = child;
        this.timeout = timeout;
        maybeLoaded = [.. loadedIds];
        this.reader = reader;
        reader.Start(Read);
    }

    /// <summary>Gets a value indicating whether the query being built is streamed (its scene loads then travel in the stream too).</summary>
    public bool Streaming { get; private set; }

    /// <summary>Gets how many queries the speculative pass asked (for tests and the benchmark).</summary>
    public int Queries => names.Count;

    /// <summary>Gets what differed first, for the report (the op, the request and the answer, cut), or null.</summary>
    public string? Difference { get; private set; }

    private bool Diverged => Volatile.Read(ref divergedAt) >= 0;

    /// <summary>Asks one query (not a scene load or unload) in the current pass.</summary>
    /// <typeparam name="T">The answer type.</typeparam>
    /// <param name="name">The op name (for messages and the replay's check).</param>
    /// <param name="shape">The answer's shape: a child's line that is the guess's expected line is the guess, unparsed.</param>
    /// <param name="request">Builds the request line (it may load a scene first).</param>
    /// <param name="interpret">Reads an answer line to the request as the live call does: the value, or the exception it throws.</param>
    /// <param name="guess">The speculated answer, or null when none can be made.</param>
    /// <param name="live">The live call, for the replay pass after the first difference.</param>
    /// <returns>The answer.</returns>
    /// <remarks>A query that throws while its request is built takes no slot: the next query gets the slot it would have
    /// had, so every later answer stays paired with its own query in every pass.</remarks>
    public T Query<T>(string name, Answer<T> shape, Func<RequestLine> request, Func<string, string, T> interpret, Func<T>? guess, Func<T> live)
    {
        int at = next;
        if (at < frontier || at == divergedAt || at >= liveFrom)
        {
            next++;
            return at < frontier ? Known(at, name, interpret, guess)
                : at == divergedAt ? Differed(interpret, live)
                : Live(live);
        }

        return reusable.Count > 0 && !transported ? Reuse(at, name, shape, request, interpret, guess) : Speculate(at, name, shape, request, interpret, guess);
    }

    /// <summary>Sends a scene load or unload within the speculative pass, answered at once with its guess.</summary>
    /// <typeparam name="T">The answer type.</typeparam>
    /// <param name="name">The op name.</param>
    /// <param name="shape">The answer's shape.</param>
    /// <param name="request">The request line.</param>
    /// <param name="interpret">Reads the answer line.</param>
    /// <param name="guess">The answer a conforming child gives (its id echoed, or ok).</param>
    /// <param name="loads">The id the request loads, or null.</param>
    /// <param name="unloads">The id the request unloads, or null.</param>
    /// <returns>The guess.</returns>
    public T Transport<T>(string name, Answer<T> shape, RequestLine request, Func<string, string, T> interpret, T guess, string? loads, string? unloads)
    {
        transported = true;
        if (loads is not null)
        {
            lock (sync)
            {
                maybeLoaded.Add(loads);
            }
        }

        int owner = building >= 0 ? building : next;
        Send(new Sent(owner, name, request, true, line =>
        {
            bool same = shape.Is(line.Bytes, guess) || SameAnswer.Of(interpret(request.Text, line.Text), guess);
            if (same && unloads is not null)
            {
                lock (sync)
                {
                    maybeLoaded.Remove(unloads);
                }
            }

            return same;
        }));
        return guess;
    }

    /// <summary>Ends a pass: waits for every answer still in flight.</summary>
    /// <returns>True when every answer equalled its guess (the pass stands as the live run's).</returns>
    public bool Finish()
    {
        Drain();
        return !(Diverged && divergedPass == passes); // a failure found in an earlier pass is final: this pass reported it
    }

    /// <summary>
    /// Prepares the next pass after a difference: the differing answer becomes known, the queries after it are guessed
    /// and streamed again (or asked live after <see cref="MaxPasses"/> passes, after a failed scene load, or after the
    /// child failed). Every scene the child may hold is unloaded first (unless it failed), so scenes load again on demand.
    /// </summary>
    /// <param name="unload">Unloads one id live (an error answer is ignored there).</param>
    public void NextPass(Action<string> unload)
    {
        int at = divergedAt;
        passes++;
        if (divergedLine is not null && failure is null)
        {
            awaited[at] = (divergedRequest!, divergedLine);
            frontier = at + 1;
        }
        else
        {
            frontier = at; // the query asks again, live (Differed)
        }

        liveFrom = passes >= MaxPasses || failure is not null || divergedLine is null ? Math.Min(liveFrom, at + 1) : liveFrom;
        if (divergedLine is not null && failure is null)
        {
            divergedAt = -1; // the difference is known now; the pass may find the next one
        }

        if (names.Count > frontier)
        {
            names.RemoveRange(frontier, names.Count - frontier);
        }

        reusable = transported || divergedLine is null || failure is not null ? [] : after.Where(e => e.Key >= frontier).ToDictionary();
        after.Clear();

        next = 0;
        if (childFailure is null && !child.Dead)
        {
            foreach (string id in maybeLoaded.Order(StringComparer.Ordinal))
            {
                unload(id);
            }
        }

        lock (sync)
        {
            maybeLoaded.Clear();
        }

        inFlight.Dispose();
        inFlight = [];
        reader.Start(Read);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        if (!inFlight.IsAddingCompleted)
        {
            Finish();
        }

        inFlight.Dispose();
    }

    // The request is built (its scene loads streamed, owned by the slot to come) before the slot is taken.
    private T Speculate<T>(int at, string name, Answer<T> shape, Func<RequestLine> request, Func<string, string, T> interpret, Func<T>? guess)
    {
        int outer = building;
        building = at;
        Streaming = true;
        RequestLine line;
        try
        {
            line = request();
        }
        finally
        {
            building = outer;
            Streaming = false;
        }

        next++;
        names.Add(name);

        T value = default!;
        bool guessed = false;
        if (guess is not null)
        {
            try
            {
                value = guess();
                guessed = true;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                // No guess for this one: ask it and wait below.
            }
        }

        if (guessed)
        {
            Send(new Sent(at, name, line, false, answer => shape.Is(answer.Bytes, value) || SameAnswer.Of(interpret(line.Text, answer.Text), value)));
            return value;
        }

        if (Diverged)
        {
            throw new InvalidOperationException("speculative pass abandoned after a difference"); // the pass is discarded
        }

        // Asked and awaited within the pass: the reader hands the answer over in order.
        using var done = new ManualResetEventSlim();
        string? received = null;
        Send(new Sent(at, name, line, false, answer =>
        {
            received = answer.Text; // kept: the bytes are the reader's until its next line
            return true;
        })
        { Done = done });
        Hand(); // what it waits for reaches the child first
        done.Wait();
        if (received is null)
        {
            throw (Exception?)failure ?? new InvalidOperationException("speculative pass abandoned after a difference");
        }

        awaited[at] = (line.Text, received);
        return interpret(line.Text, received);
    }

    // A query after the frontier whose request is the one the previous pass sent in this slot, every slot before it
    // since the frontier having been the same too: the child's answer read then is the live run's answer. The first
    // request that differs (or a slot the previous pass never sent) ends the reuse for the rest of the pass.
    private T Reuse<T>(int at, string name, Answer<T> shape, Func<RequestLine> request, Func<string, string, T> interpret, Func<T>? guess)
    {
        if (!reusable.TryGetValue(at, out var kept))
        {
            reusable.Clear();
            return Speculate(at, name, shape, request, interpret, guess);
        }

        int outer = building;
        building = at;
        Streaming = true; // a scene the request loads travels in the stream, as in Speculate (and ends the reuse)
        RequestLine line;
        try
        {
            line = request();
        }
        finally
        {
            building = outer;
            Streaming = false;
        }

        if (transported || line.Text != kept.Request)
        {
            reusable.Clear();
            return Speculate(at, name, shape, () => line, interpret, guess);
        }

        next++;
        names.Add(name);
        awaited[at] = kept; // a later pass replays it as known
        return interpret(kept.Request, kept.Line);
    }

    // A query before the frontier: its answer is known (the child's answer equalled the guess, or was kept).
    private T Known<T>(int at, string name, Func<string, string, T> interpret, Func<T>? guess)
    {
        if (names[at] != name)
        {
            throw new InvalidOperationException($"pass {passes} asked '{name}' as query {at}, the first pass '{names[at]}': a run is not a deterministic function of its answers");
        }

        return awaited.TryGetValue(at, out var kept) ? interpret(kept.Request, kept.Line) : guess!();
    }

    // The query whose answer differed, when the difference is not an answer to replay: the child failed (it is
    // reported as it failed), or a scene load or unload differed (the query asks again, live).
    private T Differed<T>(Func<string, string, T> interpret, Func<T> live) =>
        failure is not null ? throw childFailure ?? sendFailure ?? failure
        : divergedLine is not null ? interpret(divergedRequest!, divergedLine)
        : Live(live);

    // A child that failed in an earlier pass (hung, exited) is reported as it failed, not as "no longer running".
    private T Live<T>(Func<T> live)
    {
        if (child.Dead && (childFailure ?? sendFailure) is { } failed)
        {
            throw failed;
        }

        Drain();
        return live();
    }

    // A live call reads its answer on this thread, so the reader must have taken every streamed answer first: two
    // threads must never read the child's stdout at once (LineProcess.Receive has one reader).
    private void Drain()
    {
        if (!inFlight.IsAddingCompleted)
        {
            Hand();
            inFlight.CompleteAdding();
            reader.Join();
        }
    }

    // A request in flight: what it is, when it was sent, and how its answer is compared.
    private sealed record Sent(int Query, string Name, RequestLine Request, bool IsTransport, Func<AnswerLine, bool> Matches)
    {
        private volatile bool handed;

        public long At { get; set; }

        // Set (after At) when the request is written to the child.
        public bool Handed { get => handed; set => handed = value; }

        public ManualResetEventSlim? Done { get; init; }
    }
}
