using AcPhys.Contract;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat;
using AcPhys.Props.Support;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Dat;

/// <summary>Shared inputs of the dat-record properties: corpus scene walks, generated scenes, and the in-memory round trip.</summary>
internal static class DatTestSupport
{
    /// <summary>Gets the scene-walk corpus seeds, by file name.</summary>
    public static IReadOnlyList<(string Name, CorpusEntry Entry)> CorpusSceneWalks { get; } =
        [.. Directory.GetFiles(Path.Combine(RepoPaths.Corpus, "seeds"), "*.json").Order(StringComparer.Ordinal)
            .Select(f => (Path.GetFileName(f), CorpusJson.ReadFile(f)))
            .Where(x => x.Item2.SceneWalk is not null)];

    /// <summary>Samples generated scene walks (the scene generators' recipes).</summary>
    /// <param name="count">How many.</param>
    /// <param name="seed">The seed.</param>
    /// <returns>The scenes.</returns>
    public static Scene[] Generated(int count, ulong seed) =>
        [.. Gen.Sample(SceneGens.Recipes.Select(r => r.Build().Scene), count, new Rnd(seed, 0x9E3779B97F4A7C15UL), 50)];

    /// <summary>Samples multi-piece scenes.</summary>
    /// <param name="count">How many.</param>
    /// <param name="seed">The seed.</param>
    /// <returns>The scenes.</returns>
    public static Scene[] MultiPiece(int count, ulong seed) =>
        [.. Gen.Sample(MultiPieceScenes.Scenes, count, new Rnd(seed, 0x9E3779B97F4A7C15UL), 50)];

    /// <summary>Writes a scene as records and reads it back, in memory.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The export and the scene read back.</returns>
    public static (DatExport Export, Scene Back) RoundTrip(Scene scene)
    {
        var export = DatSceneWriter.Write(scene, "test", "memory");
        var bytes = export.Records.ToDictionary(r => r.Record, r => r.Bytes);
        var manifest = DatManifestJson.Read(DatManifestJson.Write(export.Manifest), "manifest.json");
        return (export, DatSceneReader.Read(manifest, r => bytes[r]));
    }

    /// <summary>Returns the CellStructs of an export's Environment record, parsed back.</summary>
    /// <param name="export">The export.</param>
    /// <returns>CellStructs by key.</returns>
    public static Dictionary<uint, CellStructRecord> Structs(DatExport export)
    {
        var (record, bytes) = export.Records.Single(r => r.Record.Type == RecordType.Environment);
        return EnvironmentCodec.Read(bytes, record.Id).ToDictionary(s => s.Key);
    }

    /// <summary>Returns the bytes of an export's Environment record.</summary>
    /// <param name="export">The export.</param>
    /// <returns>The record's bytes.</returns>
    public static byte[] StructBytes(DatExport export) => export.Records.Single(r => r.Record.Type == RecordType.Environment).Bytes;

    /// <summary>Returns the EnvCell records of an export, parsed back, by cell id.</summary>
    /// <param name="export">The export.</param>
    /// <returns>The records.</returns>
    public static Dictionary<uint, EnvCellRecord> Cells(DatExport export) =>
        export.Records.Where(r => r.Record.Type == RecordType.EnvCell).ToDictionary(r => r.Record.Id, r => EnvCellRecord.Read(r.Bytes, r.Record.Id));
}
