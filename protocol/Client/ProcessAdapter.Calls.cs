using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Client;

/// <summary>One request's round trip: written, live or streamed, its answer read as a value, a finding or a protocol failure.</summary>
public sealed partial class ProcessAdapter
{
    // The whole error text, escaped as JSON escapes it: the failure file keeps all of it, the console line cuts it.
    private static string ErrorText(JsonElement error) =>
        InputQuote.TryText(error) is { } text ? "\"" + InputQuote.Escape(text) + "\"" : Wire.Show(error);

    private static JsonDocument ParseAnswer(string answer, string op, string who)
    {
        try
        {
            return Wire.Parse(answer);
        }
        catch (WireException e)
        {
            throw new AdapterFailureException($"'{who}' answered '{op}' with something that is not protocol v1 ({e.Message}): {Wire.Brief(answer, 200)}", e);
        }
    }

    private bool LcoordAnswer<TQuery>(Message<TQuery, (bool Ok, int X, int Y)> message, TQuery query, out Lcoord lcoord)
    {
        var (ok, x, y) = Ask(message, query);
        lcoord = new Lcoord(x, y);
        return ok;
    }

    // One query of the table: its request written, its answer read and its guess made by the table's row.
    private TAnswer Ask<TQuery, TAnswer>(Message<TQuery, TAnswer> message, TQuery query) =>
        Call(message.Op, message.Name, message.Answer, w => message.WriteRequest(w, query), message.Answer.Read, r => message.Ask(r, query));

    // One query: live (a round trip), or within a pipelined run (Pipelined) guessed and streamed.
    private T Call<T>(Op op, string name, Answer<T> shape, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read, Func<ICellPhysics, T> guess)
    {
        if ((Ops & op) == 0)
        {
            throw new NotSupportedException($"{Name} does not offer {OpNames.Names(op)[0]}");
        }

        if (InWorldFrame)
        {
            RefuseUnposable(name, fields);
        }

        return session is { } s
            ? s.Query(name, shape, () => Streamed(name, fields), (request, answer) => Interpret(name, request, answer, read), () => WireProfile.Time("tool: guess (reference, incl. its scene build)", () => guess(guesser.Value)), () => Live(name, Request(name, fields), read))
            : Live(name, Request(name, fields), read);
    }

    // A world-frame point a double cannot carry exactly (WorldFrame) is refused before the query is asked or counted:
    // a pipelined pass that counted it would pair every later answer with the wrong query (false failures at base seed
    // 7700123001), and one that skipped it in the first pass only would replay another run. The request is written
    // without its scene (nothing is loaded) and converted; its points are all the conversion reads.
    private void RefuseUnposable(string name, Action<Utf8JsonWriter> fields)
    {
        probing = true;
        try
        {
            _ = WorldFrame.ToWorld(Wire.Line(w =>
            {
                w.WriteString("op", name);
                fields(w);
            }));
        }
        finally
        {
            probing = false;
        }
    }

    // A scene load or unload: transport, streamed within a pipelined run's first pass, live otherwise.
    private T Transport<T>(string name, Answer<T> shape, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read, T guess, string? loads, string? unloads)
    {
        if ((Capabilities & Capability.LoadScene) == 0)
        {
            throw new NotSupportedException($"{Name} does not offer load_scene");
        }

        return session is { Streaming: true } s
            ? s.Transport(name, shape, Streamed(name, fields), (r, answer) => Interpret(name, r, answer, read), guess, loads, unloads)
            : Live(name, Request(name, fields), read);
    }

    // Every request line, streamed or awaited; a world-frame child gets its points in world coordinates (WorldFrame).
    private string Request(string name, Action<Utf8JsonWriter> fields)
    {
        string request = Written(name, fields, Wire.Line);
        return InWorldFrame ? WorldFrame.ToWorld(request) : request;
    }

    // A streamed request: its bytes as written (text only when quoted), or the converted text for a world-frame child.
    private RequestLine Streamed(string name, Action<Utf8JsonWriter> fields) =>
        InWorldFrame ? new RequestLine(Request(name, fields)) : new RequestLine(Written(name, fields, Wire.LineUtf8));

    // The op and its fields as one line (text or bytes), timed when profiling.
    private static T Written<T>(string name, Action<Utf8JsonWriter> fields, Func<Action<Utf8JsonWriter>, T> line)
    {
        long t = WireProfile.Start();
        var written = line(w =>
        {
            w.WriteString("op", name);
            fields(w);
        });
        if (WireProfile.On)
        {
            WireProfile.Stop("tool: request line (" + name + ", nested)", t);
        }

        return written;
    }

    private T Live<T>(string name, string request, Func<JsonElement, T> read)
    {
        lock (gate)
        {
            return Interpret(name, request, child.Exchange(request, name, timeout), read);
        }
    }

    // An answer line as a call reads it: the value, a finding ({"error": ...}) or a protocol failure (exit 2).
    private T Interpret<T>(string name, string request, string answer, Func<JsonElement, T> read)
    {
        using var doc = ParseAnswer(answer, name, Name);
        if (doc.RootElement.TryGetProperty("error", out var error))
        {
            throw new ImplementationErrorException($"{name} answered error {ErrorText(error)}");
        }

        try
        {
            return read(doc.RootElement);
        }
        catch (WireException e)
        {
            throw new AdapterFailureException($"'{Name}' answered '{name}' with something that is not protocol v1: {e.Message}. Request: {Wire.Brief(request, 200)} Answer: {Wire.Brief(answer, 200)}", e);
        }
    }
}
