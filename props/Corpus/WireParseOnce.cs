using System.Text;
using System.Text.Json;
using AcPhys.Protocol.Messages;
using Xunit.Abstractions;

namespace AcPhys.Props.Corpus;

/// <summary>
/// Parse once (issue #26): <see cref="Wire.Parse(string)"/> reads a line in one pass, yet accepts and refuses exactly what the
/// step-by-step <see cref="Wire.ParseChecked"/> does (JSON, an object, readable text, distinct keys), with the same words;
/// and <see cref="Wire.Parse(System.ReadOnlyMemory{byte})"/> (how serve reads a valid UTF-8 request) does the same from the line's bytes.
/// </summary>
public sealed class WireParseOnce(ITestOutputHelper output)
{
    private const int Seed = 0x26B;

    // Keys that collide only after unescaping ("a" and "\u0061"), unreadable ones (a lone surrogate escape), non-ASCII ones.
    private static readonly string[] Keys = ["a", "b", "op", "\\u0061", "\\ud800", "\\uDC01x", "\\ud83d\\ude00", "é", "\\u00e9", "\\\\ud800", "cell"];

    private static readonly string[] Strings = ["x", "\\ud800", "\\udfff", "\\uD83D\\uDE00", "é", "\\u00e9", "\\\\ud900", "0xA9B40031", "\\n", "\\uD7FF", "\\uE000"];

    [Fact(DisplayName = "Wire.Parse accepts and refuses exactly what the step-by-step checks do, with the same message (20,000 lines, seed 0x26B)")]
    public void ParseEqualsTheStepByStepChecks()
    {
        var random = new Random(Seed);
        int accepted = 0, refused = 0;
        for (int i = 0; i < 20_000; i++)
        {
            string line = Line(random);
            string fast = Outcome(() => Wire.Parse(line));
            string slow = Outcome(() => Wire.ParseChecked(line));
            Assert.True(fast == slow, $"seed {Seed}, line {i}: Wire.Parse gave {fast}, the step-by-step checks {slow}. Replay: Wire.Parse({JsonSerializer.Serialize(line)})");
            byte[] utf8 = Encoding.UTF8.GetBytes(line);
            bool fromWire = Encoding.UTF8.GetString(utf8) == line; // a line with a lone surrogate char never comes off the wire
            string bytes = fromWire ? Outcome(() => Wire.Parse(utf8)) : fast;
            Assert.True(bytes == fast, $"seed {Seed}, line {i}: Wire.Parse of the line's bytes gave {bytes}, of its text {fast}. Replay: Wire.Parse(UTF-8 of {JsonSerializer.Serialize(line)})");
            if (fast.StartsWith("accepted", StringComparison.Ordinal))
            {
                accepted++;
            }
            else
            {
                refused++;
            }
        }

        output.WriteLine($"20000 lines: {accepted} accepted, {refused} refused, every one alike");
        Assert.True(accepted > 2000 && refused > 2000, $"the lines must exercise both outcomes: {accepted} accepted, {refused} refused");
    }

    private static string Outcome(Func<JsonDocument> parse)
    {
        try
        {
            using var doc = parse();
            return "accepted " + doc.RootElement.GetRawText();
        }
        catch (WireException e)
        {
            return "refused " + e.Message;
        }
        catch (Exception e) when (e is ArgumentException or InvalidOperationException)
        {
            return $"threw {e.GetType().Name}: {e.Message}";
        }
    }

    private static string Line(Random random)
    {
        var text = new StringBuilder();
        switch (random.Next(12))
        {
            case 0:
                Value(random, text, depth: 2); // any value at the root: not always an object
                break;
            default:
                Object(random, text, depth: 0);
                break;
        }

        string line = text.ToString();
        return random.Next(10) switch
        {
            0 when line.Length > 2 => line[..random.Next(1, line.Length)], // cut: not JSON
            1 => line + (random.Next(2) == 0 ? " x" : ",{}"), // trailing text
            2 => line.Insert(random.Next(line.Length + 1), "\ud800"), // a raw lone surrogate in the .NET string
            _ => line,
        };
    }

    private static void Object(Random random, StringBuilder text, int depth)
    {
        text.Append('{');
        int count = random.Next(5);
        for (int k = 0; k < count; k++)
        {
            text.Append(k == 0 ? string.Empty : ",").Append('"').Append(Keys[random.Next(Keys.Length)]).Append("\":");
            Value(random, text, depth + 1);
        }

        text.Append('}');
    }

    private static void Value(Random random, StringBuilder text, int depth)
    {
        switch (random.Next(depth >= 4 ? 4 : 7))
        {
            case 0:
                text.Append(random.Next(-1000, 1000));
                break;
            case 1:
                text.Append('"').Append(Strings[random.Next(Strings.Length)]).Append('"');
                break;
            case 2:
                text.Append(random.Next(2) == 0 ? "true" : "null");
                break;
            case 3:
                text.Append("1.5e39");
                break;
            case 4:
            case 5:
                Object(random, text, depth);
                break;
            default:
                text.Append('[');
                int count = random.Next(4);
                for (int k = 0; k < count; k++)
                {
                    text.Append(k == 0 ? string.Empty : ",");
                    Value(random, text, depth + 1);
                }

                text.Append(']');
                break;
        }
    }
}
