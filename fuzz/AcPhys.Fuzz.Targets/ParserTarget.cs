using System.Text;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// A parser target: bytes → one of the project's readers. The reader may reject an input only with
/// <see cref="InputFormatException"/>; any other exception escapes and is a bug. An input it accepts must also
/// survive write → read → write unchanged (<see cref="RoundTripException"/> otherwise).
/// </summary>
public abstract class ParserTarget : FuzzTarget
{
    /// <summary>Tokens of the corpus format and of JSON, for afl-fuzz's dictionary.</summary>
    private static readonly string[] Tokens =
    [
        "\"format\"", "\"acphys-case\"", "\"version\"", "\"kind\"", "\"land\"", "\"walk\"", "\"title\"", "\"invariant\"",
        "\"foundBy\"", "\"hand\"", "\"props\"", "\"fuzz\"", "\"spec\"", "\"seed\"", "\"catches\"", "\"case\"", "\"cell\"",
        "\"x\"", "\"y\"", "\"z\"", "\"r\"", "\"lcoord\"", "\"start\"", "\"body\"", "\"steps\"", "\"0x7FFFFFFF\"",
        "\"NaN\"", "\"Infinity\"", "\"-Infinity\"", "null", "true", "false", "1e39", "-0", "2147483648", "\\u0000", "\\uffff",
        "[", "]", "{", "}", ":", ",",
    ];

    /// <inheritdoc/>
    public sealed override TargetKind Kind => TargetKind.Parser;

    /// <inheritdoc/>
    public sealed override IReadOnlyList<string> Dictionary => Tokens;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = ParserSeeds.Entries.ToDictionary(
        e => e.Key,
        e => Encoding.UTF8.GetBytes(CorpusJson.Write(e.Value)));

    /// <inheritdoc/>
    public sealed override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data =>
        {
            CorpusEntry? entry;
            try
            {
                entry = Read(data);
            }
            catch (InputFormatException)
            {
                return; // a clean rejection is the reader doing its job
            }

            if (entry is null)
            {
                return;
            }

            string text = CorpusJson.Write(entry);
            string again = CorpusJson.Write(CorpusJson.Read(text, "rewritten"));
            if (again != text)
            {
                throw new RoundTripException($"{Name}: an accepted input does not survive write → read → write:\n{text}\n---\n{again}");
            }
        };
    }

    /// <summary>Reads the input with the reader under test.</summary>
    /// <param name="data">The bytes.</param>
    /// <returns>The entry read, or null when the input was rejected before the reader (not the reader's concern).</returns>
    /// <exception cref="InputFormatException">The reader's clean rejection.</exception>
    protected abstract CorpusEntry? Read(ReadOnlySpan<byte> data);
}
