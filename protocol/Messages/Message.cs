using System.Text.Json;
using AcPhys.Contract;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// One query of protocol v1, written once (issue 42): its request's write (the client) and read (the server), its
/// answer shape (<see cref="Answers"/>), and how an <see cref="ICellPhysics"/> answers it — the server's call and the
/// pipelined client's guess alike. The queries are <see cref="MessageTable"/>.
/// </summary>
/// <typeparam name="TQuery">The query's arguments.</typeparam>
/// <typeparam name="TAnswer">The answer.</typeparam>
public sealed class Message<TQuery, TAnswer> : IServedMessage
{
    private readonly Action<Utf8JsonWriter, TQuery> write;
    private readonly Func<JsonElement, TQuery> read;
    private readonly Func<ICellPhysics, TQuery, TAnswer> ask;

    /// <summary>Initializes a new instance of the <see cref="Message{TQuery, TAnswer}"/> class.</summary>
    /// <param name="op">The operation (its protocol name is the request's <c>op</c>).</param>
    /// <param name="write">Writes the request's fields after <c>op</c>.</param>
    /// <param name="read">Reads them, in the order the server checks them (<see cref="WireException"/> for a bad one).</param>
    /// <param name="answer">The answer shape.</param>
    /// <param name="ask">How an implementation answers the query.</param>
    internal Message(Op op, Action<Utf8JsonWriter, TQuery> write, Func<JsonElement, TQuery> read, Answer<TAnswer> answer, Func<ICellPhysics, TQuery, TAnswer> ask)
    {
        Op = op;
        Name = OpNames.Names(op)[0];
        this.write = write;
        this.read = read;
        Answer = answer;
        this.ask = ask;
    }

    /// <inheritdoc/>
    public Op Op { get; }

    /// <inheritdoc/>
    public string Name { get; }

    /// <summary>Gets the answer shape.</summary>
    public Answer<TAnswer> Answer { get; }

    /// <summary>Writes the request's fields after <c>op</c> (the client's side).</summary>
    /// <param name="w">The writer, inside the request's object.</param>
    /// <param name="query">The query.</param>
    public void WriteRequest(Utf8JsonWriter w, TQuery query) => write(w, query);

    /// <summary>Reads the request's fields (the server's side).</summary>
    /// <param name="request">The request's object.</param>
    /// <returns>The query.</returns>
    /// <exception cref="WireException">A field is missing or is not protocol v1.</exception>
    public TQuery ReadRequest(JsonElement request) => read(request);

    /// <summary>Asks <paramref name="impl"/> the query.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="query">The query.</param>
    /// <returns>Its answer.</returns>
    public TAnswer Ask(ICellPhysics impl, TQuery query) => ask(impl, query);

    /// <inheritdoc/>
    public string Serve(ICellPhysics impl, JsonElement request) => Answer.Line(Ask(impl, ReadRequest(request)));
}

/// <summary>A query of <see cref="MessageTable"/> as the server dispatches it: by name, whatever its types.</summary>
public interface IServedMessage
{
    /// <summary>Gets the operation.</summary>
    Op Op { get; }

    /// <summary>Gets the request's <c>op</c> name.</summary>
    string Name { get; }

    /// <summary>Reads the request, asks <paramref name="impl"/> and writes the answer line.</summary>
    /// <param name="impl">The implementation served.</param>
    /// <param name="request">The request's object.</param>
    /// <returns>The answer line.</returns>
    /// <exception cref="WireException">A field of the request is missing or is not protocol v1.</exception>
    string Serve(ICellPhysics impl, JsonElement request);
}
