using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Values;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// A scene on the wire as retail dat records (docs/protocol.md, "Scenes as dat records"): an object with the record
/// folder's <c>manifest</c> (as manifest.json holds it) and <c>records</c>, each record's file name mapped to its raw
/// bytes in base64 — the folder <c>acphys scene export --dat</c> writes, carried in one line.
/// </summary>
public static class DatWire
{
    /// <summary>Writes a scene's records as a property.</summary>
    /// <param name="w">The writer (inside an object).</param>
    /// <param name="name">The property name.</param>
    /// <param name="scene">The scene.</param>
    public static void WriteScene(Utf8JsonWriter w, string name, Scene scene)
    {
        long t = WireProfile.Start();
        var export = DatRoundTrip.Records(scene); // written once per scene: the conformance check reads the same records back
        w.WriteStartObject(name);
        w.WritePropertyName("manifest");
        DatManifestJson.Write(w, export.Manifest); // compact, as the request line's writer is
        w.WriteStartObject("records");
        foreach (var (record, bytes) in export.Records)
        {
            w.WriteBase64String(record.File, bytes);
        }

        w.WriteEndObject();
        w.WriteEndObject();
        WireProfile.Stop("tool: load_scene dat field (incl. Write)", t);
    }

    /// <summary>Reads a scene from its records.</summary>
    /// <param name="field">The object <see cref="WriteScene"/> writes.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="WireException">Not such an object, or any defect of the manifest or a record (the reader's message, naming the record and byte offset).</exception>
    public static Scene ReadScene(JsonElement field) => WireProfile.Time("child: DatWire.ReadScene", () => ReadSceneTimed(field));

    private static Scene ReadSceneTimed(JsonElement field)
    {
        if (field.ValueKind != JsonValueKind.Object)
        {
            throw new WireException("field \"dat\" must be an object with \"manifest\" and \"records\"");
        }

        var records = Wire.Field(field, "records");
        if (records.ValueKind != JsonValueKind.Object)
        {
            throw new WireException("field \"dat.records\" must be an object mapping record file names to base64");
        }

        var bytes = new Dictionary<string, byte[]>(StringComparer.Ordinal);
        foreach (var p in records.EnumerateObject())
        {
            if (p.Value.ValueKind != JsonValueKind.String || !p.Value.TryGetBytesFromBase64(out var data))
            {
                throw new WireException($"dat.records.{Wire.Brief(p.Name, 24)}: not a base64 string");
            }

            if (!bytes.TryAdd(p.Name, data))
            {
                throw new WireException($"dat.records: {Wire.Brief(p.Name, 24)} appears twice");
            }
        }

        try
        {
            var manifest = WireProfile.Time("dat read: manifest JSON", () => DatManifestJson.Read(Wire.Field(field, "manifest"), "dat.manifest"));
            var listed = manifest.Records.Select(r => r.File).ToHashSet(StringComparer.Ordinal);
            if (bytes.Keys.FirstOrDefault(k => !listed.Contains(k)) is { } extra)
            {
                throw new WireException($"dat.records: {Wire.Brief(extra, 24)} is not listed in the manifest");
            }

            return DatSceneReader.Read(manifest, r => bytes.TryGetValue(r.File, out var b)
                ? b
                : throw new InputFormatException($"dat.records: {r.File} ({r.Type} {RecordIds.Text(r.Id)}) is listed in the manifest but not sent"));
        }
        catch (InputFormatException e)
        {
            // A scene the records hold that breaks the scene rules arrives worded by DatSceneReader ("the scene the records describe is not valid: ...").
            throw new WireException("invalid dat records: " + e.Message, e);
        }
    }
}
