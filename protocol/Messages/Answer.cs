using System.Text.Json;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// One answer shape of protocol v1, written once (issue 42): the server writes it, the client reads it, and the
/// pipelined transport matches a child's line against a guess's with it (docs/protocol.md, "Pipelining"). The shapes
/// are <see cref="Answers"/>.
/// </summary>
/// <typeparam name="T">The answer as the tool's calls return it.</typeparam>
public sealed class Answer<T>
{
    private readonly Action<Utf8JsonWriter, T> write;
    private readonly Func<JsonElement, T> read;
    private readonly Func<T, bool>? canonical;
    private readonly Matcher? match;

    /// <summary>Initializes a new instance of the <see cref="Answer{T}"/> class.</summary>
    /// <param name="write">Writes the answer's fields.</param>
    /// <param name="read">Reads them back (<see cref="WireException"/> for a field that is not protocol v1).</param>
    /// <param name="canonical">Which values read back exactly as written (null: all); the others get no expected line and are compared by value.</param>
    /// <param name="match">Matches a line against a value's text without writing it (null: the line is written and compared).</param>
    internal Answer(Action<Utf8JsonWriter, T> write, Func<JsonElement, T> read, Func<T, bool>? canonical = null, Matcher? match = null)
    {
        this.write = write;
        this.read = read;
        this.canonical = canonical;
        this.match = match;
    }

    /// <summary>Whether a line is a value's text, byte for byte.</summary>
    /// <param name="line">The line's UTF-8 bytes.</param>
    /// <param name="value">The value.</param>
    /// <returns>True when it is.</returns>
    internal delegate bool Matcher(ReadOnlySpan<byte> line, T value);

    /// <summary>Writes the answer's fields (the server's side).</summary>
    /// <param name="w">The writer, inside the answer's object.</param>
    /// <param name="value">The answer.</param>
    public void Write(Utf8JsonWriter w, T value) => write(w, value);

    /// <summary>Returns the answer's whole line, as <c>acphys serve</c> writes it.</summary>
    /// <param name="value">The answer.</param>
    /// <returns>The line (no newline).</returns>
    public string Line(T value) => Wire.Line(w => write(w, value));

    /// <summary>Reads an answer (the client's side).</summary>
    /// <param name="answer">The answer's object (not an error answer).</param>
    /// <returns>The value.</returns>
    /// <exception cref="WireException">A field is missing or is not protocol v1.</exception>
    public T Read(JsonElement answer) => read(answer);

    /// <summary>Returns the line a conforming child writes for <paramref name="guess"/>, or null when reading a line cannot give the guess back exactly (a NaN's payload, a <c>loaded</c> not parallel to <c>cells</c>).</summary>
    /// <param name="guess">The guessed answer.</param>
    /// <returns>The line, or null.</returns>
    public string? ExpectedLine(T guess) => Canonical(guess) ? Line(guess) : null;

    /// <summary>
    /// Whether <paramref name="line"/> is <see cref="ExpectedLine"/> of <paramref name="guess"/>, byte for byte: the
    /// pipeline then takes the answer as the guess without parsing it (ANSWER-LINE-READS-BACK); false says nothing.
    /// </summary>
    /// <param name="line">The child's answer line, its UTF-8 bytes.</param>
    /// <param name="guess">The guess.</param>
    /// <returns>True when the bytes are the guess's line.</returns>
    public bool Is(ReadOnlySpan<byte> line, T guess) =>
        Canonical(guess) && (match is null ? Wire.LineIs(line, w => write(w, guess)) : match(line, guess));

    private bool Canonical(T value) => canonical is null || canonical(value);
}
