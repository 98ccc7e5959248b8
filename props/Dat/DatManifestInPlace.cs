using System.Text.Json;
using System.Text.Json.Nodes;
using AcPhys.Formats;
using AcPhys.Formats.Dat;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>
/// A <c>load_scene</c> request's manifest is read in place, inside the parsed request, not written out and parsed again
/// (issue 26, parse once): it must answer exactly as the manifest.json reader answers the same text.
/// </summary>
public sealed class DatManifestInPlace(ITestOutputHelper output)
{
    private const int Seed = 0x26D;

    [Fact(DisplayName = "DAT-MANIFEST-ONCE: a manifest read in place gives the manifest, or the refusal, that its text gives (3,000 damaged manifests of 200 generated scenes, seed 0x26D)")]
    public void InPlaceReadAnswersAsTheTextRead()
    {
        var random = new Random(Seed);
        var manifests = DatTestSupport.Generated(200, 0xDA82).Select(s => DatManifestJson.Write(DatSceneWriter.Write(s, "test", "memory").Manifest)).ToArray();
        int refused = 0, deep = 0;
        for (int i = 0; i < 3000; i++)
        {
            var node = JsonNode.Parse(manifests[random.Next(manifests.Length)])!;
            string damage = i % 10 == 0 ? "none" : Damage(node, random);
            deep += damage.StartsWith("nested", StringComparison.Ordinal) ? 1 : 0;
            string text = node.ToJsonString();
            using var doc = JsonDocument.Parse(text, new JsonDocumentOptions { MaxDepth = 64 });
            string fromText = Outcome(() => DatManifestJson.Read(text, "dat.manifest"));
            string inPlace = Outcome(() => DatManifestJson.Read(doc.RootElement, "dat.manifest"));
            Assert.True(fromText == inPlace, $"seed {Seed}, manifest {i} ({damage}): from its text {fromText}; in place {inPlace}");
            refused += fromText.StartsWith("refused", StringComparison.Ordinal) ? 1 : 0;
        }

        output.WriteLine($"3000 manifests: {refused} refused, {deep} nested past the in-place depth; every one alike");
        Assert.True(refused > 1000 && refused < 2900, $"the damage must refuse some manifests and spare others: {refused} of 3000 refused");
        Assert.True(deep > 50, $"too few manifests nested past the in-place depth: {deep}");
    }

    private static string Damage(JsonNode root, Random random)
    {
        var obj = root.AsObject();
        var keys = obj.Select(p => p.Key).ToArray();
        string key = keys[random.Next(keys.Length)];
        switch (random.Next(5))
        {
            case 0:
                obj.Remove(key);
                return $"{key} removed";
            case 1:
                obj[key] = random.Next(2) == 0 ? JsonValue.Create("0x7") : JsonValue.Create(-3);
                return $"{key} retyped";
            case 2:
                obj["unknownField"] = 1;
                return "unknown field";
            case 3:
                JsonNode nested = new JsonArray();
                int depth = random.Next(15, 40);
                for (int d = 0; d < depth; d++)
                {
                    nested = new JsonArray(nested);
                }

                obj[key] = nested;
                return $"nested {depth} deep at {key}";
            default:
                if (obj["records"] is JsonArray { Count: > 0 } records)
                {
                    records[random.Next(records.Count)]!.AsObject()["id"] = "0xZZ";
                    return "record id unreadable";
                }

                obj.Remove(key);
                return $"{key} removed";
        }
    }

    private static string Outcome(Func<DatManifest> read)
    {
        try
        {
            var m = read();
            return $"accepted {DatManifestJson.Write(m)}";
        }
        catch (InputFormatException e)
        {
            return "refused " + e.Message;
        }
    }
}
