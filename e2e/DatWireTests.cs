using System.Text.Json;
using System.Text.Json.Nodes;
using AcPhys.Contract;
using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.E2E;

/// <summary>A scene sent as retail dat records (load_scene with <c>dat</c>) is the same scene as its JSON; bad records are clear errors.</summary>
public sealed class DatWireTests
{
    // Every scene walk of the corpus (seeds, regressions) and the documented example estates.
    public static TheoryData<string> SceneWalkFiles => new(
        new[] { Path.Combine(RepoPaths.Corpus, "seeds"), Path.Combine(RepoPaths.Corpus, "regressions"), Path.Combine(RepoPaths.Root, "docs", "examples") }
            .SelectMany(d => Directory.EnumerateFiles(d, "*.json"))
            .Where(f => CorpusJson.ReadFile(f).SceneWalk is not null)
            .Select(f => Path.GetRelativePath(RepoPaths.Root, f))
            .Order(StringComparer.Ordinal));

    [Theory(DisplayName = "Every step of a scene walk answers the same from the scene's dat records as from its JSON (static and transition)")]
    [MemberData(nameof(SceneWalkFiles))]
    public void RecordsAnswerLikeJson(string file)
    {
        var sw = CorpusJson.ReadFile(Path.Combine(RepoPaths.Root, file)).SceneWalk!;
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        string fromDat = SceneId(server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            DatWire.WriteScene(w, "dat", sw.Scene);
        })));
        string fromJson = SceneId(server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(sw.Scene));
        })));
        int compared = 0;
        foreach (bool loadCells in new[] { false, true })
        {
            foreach (var step in SceneWalkRunner.Run(ReferenceAdapter.Instance, sw, loadCells))
            {
                string Ask(string id) => server.Answer(Wire.Line(w =>
                {
                    w.WriteString("op", "find_cell");
                    w.WriteString("scene_id", id);
                    Wire.WriteCell(w, "cell", step.Query.Cell);
                    Wire.WriteSpheres(w, "spheres", step.Query.Spheres);
                    if (step.Current.IsNone)
                    {
                        w.WriteNull("current");
                    }
                    else
                    {
                        Wire.WriteCell(w, "current", step.Current);
                    }

                    w.WriteBoolean("load_cells", loadCells);
                }));
                string json = Ask(fromJson);
                Assert.StartsWith("{\"cells\":", json, StringComparison.Ordinal);
                Assert.Equal(json, Ask(fromDat));
                compared++;
            }
        }

        Assert.True(compared > 0, $"{file}: no steps compared");
    }

    [Fact(DisplayName = "serve announces dat_records with load_scene, and not when told not to")]
    public void HelloAnnouncesDatRecords()
    {
        static IEnumerable<string?> Ops(ProtocolServer s)
        {
            using var doc = JsonDocument.Parse(s.Answer("{\"op\":\"hello\",\"protocol\":1}"));
            return [.. doc.RootElement.GetProperty("ops").EnumerateArray().Select(e => e.GetString())];
        }

        Assert.Contains("dat_records", Ops(new ProtocolServer(ReferenceAdapter.Instance)));
        Assert.DoesNotContain("dat_records", Ops(new ProtocolServer(ReferenceAdapter.Instance) { DatRecords = false }));
        Assert.DoesNotContain("dat_records", Ops(new ProtocolServer(ReferenceAdapter.Instance) { LoadScenes = false }));
    }

    [Fact(DisplayName = "Bad dat records in load_scene are errors naming the defect, and the server keeps serving")]
    public void BadRecordsAreClearErrors()
    {
        var scene = SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 20, (0xB4 * 192.0) + 50, 0, 2, 6f, 6f, 0, true, false));
        string good = Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            DatWire.WriteScene(w, "dat", scene);
        });
        using var doc = JsonDocument.Parse(good);
        var records = doc.RootElement.GetProperty("dat").GetProperty("records");
        string envCell = records.EnumerateObject().First(p => p.Name.EndsWith("0100.bin", StringComparison.Ordinal)).Name;
        string bytes = records.GetProperty(envCell).GetString()!;
        var server = new ProtocolServer(ReferenceAdapter.Instance);

        string truncated = good.Replace(bytes, Convert.ToBase64String(Convert.FromBase64String(bytes)[..10]), StringComparison.Ordinal);
        Assert.Matches("^\\{\"error\":\"malformed request: invalid dat records: EnvCell 0x[0-9A-F]{8}.*byte", server.Answer(truncated));
        Assert.Contains("not a base64 string", server.Answer(good.Replace(bytes, "@@@", StringComparison.Ordinal)), StringComparison.Ordinal);
        var missing = JsonNode.Parse(good)!;
        missing["dat"]!["records"]!.AsObject().Remove(envCell);
        Assert.Contains("listed in the manifest but not sent", server.Answer(missing.ToJsonString()), StringComparison.Ordinal);
        Assert.Contains("must be an object with", server.Answer("{\"op\":\"load_scene\",\"dat\":[]}"), StringComparison.Ordinal);
        Assert.StartsWith("{\"scene_id\":", server.Answer(good), StringComparison.Ordinal);
    }

    private static string SceneId(string answer)
    {
        using var doc = JsonDocument.Parse(answer);
        Assert.True(doc.RootElement.TryGetProperty("scene_id", out var id), answer);
        return id.GetString()!;
    }
}
