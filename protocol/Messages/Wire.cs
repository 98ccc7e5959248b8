using System.Buffers;
using System.Text;
using System.Text.Json;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The value encoding of protocol v1 (docs/protocol.md): one JSON object per line; cell ids as <c>"0xAABBCCCC"</c>;
/// coordinates as JSON numbers read as float32, the non-finite ones as the strings <c>"NaN"</c>, <c>"Infinity"</c>,
/// <c>"-Infinity"</c>; lcoords as JSON integers.
/// </summary>
public static partial class Wire
{
    /// <summary>The protocol version this code speaks.</summary>
    public const int Version = 1;

    // The default limits (depth 64, no comments, no trailing commas) plus duplicate keys refused while parsing.
    private static readonly JsonDocumentOptions StrictOptions = new() { AllowDuplicateProperties = false };

    internal static readonly JsonWriterOptions WriterOptions = new() { Indented = false, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    /// <summary>Builds one message line (no newline) with the fields <paramref name="fields"/> writes.</summary>
    /// <param name="fields">Writes the object's properties.</param>
    /// <returns>The compact JSON text.</returns>
    /// <remarks>The buffer and writer are the thread's own, reused (issue 26: a fresh growing buffer and writer per
    /// line was most of what both ends of a served gate allocated); a line built while another is being built (a
    /// request that loads its scene first) takes the next one.</remarks>
    public static string Line(Action<Utf8JsonWriter> fields) => Built(fields, 0, static (bytes, _) => Encoding.UTF8.GetString(bytes));

    /// <summary>Builds one message line as its UTF-8 bytes (see <see cref="Line"/>: the same text).</summary>
    /// <param name="fields">Writes the object's properties.</param>
    /// <returns>The compact JSON text's bytes, no line end.</returns>
    public static byte[] LineUtf8(Action<Utf8JsonWriter> fields) => Built(fields, 0, static (bytes, _) => bytes.ToArray());

    /// <summary>Whether <paramref name="line"/> is exactly the UTF-8 of the line <paramref name="fields"/> builds (see <see cref="Line"/>).</summary>
    /// <param name="line">The line's bytes.</param>
    /// <param name="fields">Writes the object's properties.</param>
    /// <returns>True when byte for byte equal.</returns>
    public static bool LineIs(ReadOnlySpan<byte> line, Action<Utf8JsonWriter> fields)
    {
        var writer = LineWriter.Rent();
        try
        {
            return writer.Write(fields).SequenceEqual(line);
        }
        finally
        {
            writer.Return();
        }
    }

    /// <summary>Parses one message line into its root object.</summary>
    /// <param name="line">The line.</param>
    /// <returns>The parsed document (dispose it).</returns>
    /// <exception cref="WireException">Not a JSON object, a key given twice in one object, or a string or name in it is not valid text.</exception>
    /// <remarks>
    /// Parse once (issue #26): a well-formed line is parsed by one pass that also refuses duplicate keys
    /// (<see cref="JsonDocumentOptions.AllowDuplicateProperties"/>), after one scan of its text for a surrogate escape.
    /// Only a line that fails (or may hold a surrogate escape) is read again by <see cref="ParseChecked"/>, the checks
    /// one by one, so every refusal keeps its order and words.
    /// </remarks>
    public static JsonDocument Parse(string line) =>
        (AcPhys.Formats.Corpus.JsonStrings.MayHoldSurrogateEscape(line.AsSpan()) ? null : OnePass(() => JsonDocument.Parse(line, StrictOptions)))
        ?? ParseChecked(line);

    /// <summary>Parses one message line given as valid UTF-8, exactly as <see cref="Parse(string)"/> parses its text.</summary>
    /// <param name="line">The line's bytes (valid UTF-8; they must stay unchanged while the document is used).</param>
    /// <returns>The parsed document (dispose it).</returns>
    /// <exception cref="WireException">As <see cref="Parse(string)"/>.</exception>
    public static JsonDocument Parse(ReadOnlyMemory<byte> line) =>
        (AcPhys.Formats.Corpus.JsonStrings.MayHoldSurrogateEscape(line.Span) ? null : OnePass(() => JsonDocument.Parse(line, StrictOptions)))
        ?? ParseChecked(Encoding.UTF8.GetString(line.Span));

    // The one pass: the strict parse, an object, readable text; null sends the line to ParseChecked for the words.
    private static JsonDocument? OnePass(Func<JsonDocument> parse)
    {
        JsonDocument doc;
        try
        {
            doc = parse();
        }
        catch (JsonException)
        {
            return null; // not JSON, or a duplicate key: worded by ParseChecked
        }

        if (doc.RootElement.ValueKind == JsonValueKind.Object && AcPhys.Formats.Corpus.JsonStrings.FirstUnreadable(doc.RootElement, "$") is null)
        {
            return doc;
        }

        doc.Dispose();
        return null;
    }

    /// <summary>Parses one message line and checks it step by step: JSON, an object, readable text, distinct keys.</summary>
    /// <param name="line">The line.</param>
    /// <returns>The parsed document (dispose it).</returns>
    /// <exception cref="WireException">The first defect, worded for the reader.</exception>
    public static JsonDocument ParseChecked(string line)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(line);
        }
        catch (JsonException e)
        {
            throw new WireException("not JSON: " + e.Message, e);
        }

        var kind = doc.RootElement.ValueKind;
        if (kind != JsonValueKind.Object)
        {
            doc.Dispose(); // the kind is read first: a disposed document's root cannot be asked (issue #19)
            throw new WireException($"expected a JSON object, got {kind}");
        }

        if (AcPhys.Formats.Corpus.JsonStrings.FirstUnreadable(doc.RootElement, "$") is { } bad)
        {
            doc.Dispose();
            throw new WireException($"{bad}: not valid text (a lone UTF-16 surrogate escape)");
        }

        if (AcPhys.Formats.Corpus.JsonKeys.FirstDuplicate(doc.RootElement) is { } duplicate)
        {
            doc.Dispose();
            throw new WireException(AcPhys.Formats.Corpus.JsonKeys.Message(duplicate));
        }

        return doc;
    }

    /// <summary>Shows a JSON value briefly, for messages.</summary>
    /// <param name="v">The value.</param>
    /// <returns>At most 80 characters of its text (<see cref="AcPhys.Formats.Values.InputQuote"/>).</returns>
    public static string Show(JsonElement v) => AcPhys.Formats.Values.InputQuote.Json(v);

    /// <summary>Cuts a text to a length, for messages.</summary>
    /// <param name="text">The text.</param>
    /// <param name="max">The most characters to keep.</param>
    /// <returns>The text, cut with an ellipsis when longer.</returns>
    public static string Brief(string text, int max)
    {
        text = AcPhys.Formats.Values.InputQuote.Escape(text); // the peer's text never reaches a console or report raw (issue 28)
        return text.Length <= max ? text : text[..max] + "...";
    }

    // A line built in the thread's reusable writer and taken (decoded, copied, compared) before the writer is returned.
    private delegate T FromLine<TState, T>(ReadOnlySpan<byte> line, TState state);

    private static T Built<TState, T>(Action<Utf8JsonWriter> fields, TState state, FromLine<TState, T> take)
    {
        var line = LineWriter.Rent();
        try
        {
            return take(line.Write(fields), state);
        }
        finally
        {
            line.Return();
        }
    }

    // One thread's reusable line buffers, one per nesting level in use.
    private sealed class LineWriter
    {
        private const int MaxKeptBytes = 1 << 20;

        [ThreadStatic]
        private static List<LineWriter>? pool;

        [ThreadStatic]
        private static int depth;

        private readonly ArrayBufferWriter<byte> buffer = new(4096);
        private readonly Utf8JsonWriter writer;

        private LineWriter() => writer = new Utf8JsonWriter(buffer, WriterOptions);

        public static LineWriter Rent()
        {
            var lines = pool ??= [];
            if (depth == lines.Count)
            {
                lines.Add(new LineWriter());
            }

            return lines[depth++];
        }

        public ReadOnlySpan<byte> Write(Action<Utf8JsonWriter> fields)
        {
            buffer.ResetWrittenCount();
            writer.Reset(buffer); // also after a line whose fields threw half-way
            writer.WriteStartObject();
            fields(writer);
            writer.WriteEndObject();
            writer.Flush();
            return buffer.WrittenSpan;
        }

        public void Return()
        {
            depth--;
            if (buffer.Capacity > MaxKeptBytes)
            {
                pool![depth] = new LineWriter(); // one huge line does not keep its buffer
            }
        }
    }
}
