using System.Text;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Scenes;
using AcPhys.Props.Support;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
using Xunit.Abstractions;

namespace AcPhys.Props.Corpus;

/// <summary>
/// Inputs on which a parser fuzz target (docs/fuzzing.md) once threw something other than the format exception:
/// corpus/regressions/parsers/TARGET-EXCEPTION-HASH.bin. Each must now be read or rejected with the reader's format
/// exception (InputFormatException; InputFormatException for scene-json), and a serve-request input answered line by line.
/// </summary>
public sealed class ParserRegressions(ITestOutputHelper output)
{
    public static TheoryData<string> Files
    {
        get
        {
            var data = new TheoryData<string>();
            string dir = Path.Combine(RepoPaths.Corpus, "regressions", "parsers");
            foreach (var f in Directory.Exists(dir) ? Directory.EnumerateFiles(dir, "*.bin").Order(StringComparer.Ordinal) : Enumerable.Empty<string>())
            {
                data.Add(Path.GetFileName(f));
            }

            return data;
        }
    }

    [Theory(DisplayName = "Parser regression: the reader accepts the input or rejects it with InputFormatException, nothing else")]
    [MemberData(nameof(Files))]
    public void ReadsOrRejectsCleanly(string name)
    {
        byte[] data = File.ReadAllBytes(Path.Combine(RepoPaths.Corpus, "regressions", "parsers", name));
        try
        {
            if (name.StartsWith("walk-json-", StringComparison.Ordinal))
            {
                using var doc = JsonDocument.Parse(data);
                WalkJson.Read(doc.RootElement, name);
            }
            else if (name.StartsWith("serve-request-", StringComparison.Ordinal))
            {
                // As the serve-request target: every line answered, only ever with a JSON object (an error answer for a bad request).
                var server = new ProtocolServer(ReferenceAdapter.Instance);
                foreach (string line in Encoding.UTF8.GetString(data).Split('\n').Take(8).Where(l => l.Length > 0))
                {
                    using var answer = Wire.Parse(server.AnswerChecked(line));
                    output.WriteLine(Wire.Brief(answer.RootElement.GetRawText(), 200));
                }
            }
            else if (name.StartsWith("scene-json-", StringComparison.Ordinal))
            {
                try
                {
                    SceneJson.Read(Encoding.UTF8.GetString(data), name);
                }
                catch (InputFormatException e)
                {
                    output.WriteLine("rejected: " + e.Message);
                }
            }
            else
            {
                Assert.StartsWith("corpus-", name, StringComparison.Ordinal);
                CorpusJson.Read(Encoding.UTF8.GetString(data), name);
            }

            output.WriteLine("accepted");
        }
        catch (InputFormatException e)
        {
            output.WriteLine("rejected: " + e.Message);
        }
    }

    [Fact(DisplayName = "A lone surrogate escape in a corpus file is a format error, not an InvalidOperationException")]
    public void LoneSurrogateIsAFormatError()
    {
        string json = "{\"format\":\"acphys-case\",\"version\":1,\"kind\":\"land\",\"title\":\"\\ud800\",\"foundBy\":\"hand\",\"case\":{}}";

        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(json, "t.json"));
        Assert.Contains("$.title", e.Message, StringComparison.Ordinal);
    }
}
