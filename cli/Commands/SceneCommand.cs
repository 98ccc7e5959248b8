using System.CommandLine;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Scenes;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>scene</c> verb: <c>export</c> a scene as retail dat records, <c>import</c> them back (docs/dat-scenes.md).</summary>
internal static class SceneCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var file = new Argument<string>("file") { Description = "A scene-walk corpus file, or a bare scene JSON object." };
        var dat = new Option<string>("--dat") { Description = "The record folder to write (XXXXXXXX.bin per record and manifest.json; atomically).", HelpName = "DIR", Required = true };
        var export = new Command("export", "Write a scene as retail dat records (EnvCell, Environment, LandblockInfo, Landblock) plus a manifest.") { file, dat };
        export.SetAction(parse => Guard.Run("scene export", () => Export(parse.GetValue(file) ?? string.Empty, parse.GetValue(dat) ?? string.Empty)));

        var dir = new Argument<string>("dir") { Description = "A record folder written by scene export." };
        var output = new Option<string>("--output", "-o") { Description = "The corpus file (or bare scene, when the folder has no walk) to write, atomically.", HelpName = "FILE", Required = true };
        var import = new Command("import", "Read a record folder back into a scene-walk corpus file (or a bare scene).") { dir, output };
        import.SetAction(parse => Guard.Run("scene import", () => Import(parse.GetValue(dir) ?? string.Empty, parse.GetValue(output) ?? string.Empty)));

        return new Command("scene", "Convert scenes to and from retail dat records; extract one from dat files.") { export, import, SceneFromDat.Create(), SceneToDat.Create() };
    }

    private static int Export(string path, string dir)
    {
        OutputPath.CheckFolder("--dat", dir); // every path problem is exit 3 before the work (issue 28)
        OutputPath.CheckDistinct([("--dat", dir)], [path]);
        if (!File.Exists(path))
        {
            throw new UsageException($"{(path.Length == 0 ? "''" : path)}: no such file");
        }

        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"{path}: cannot read: {e.Message}");
        }

        DatExport export;
        if (IsCorpusFile(text))
        {
            var entry = CorpusJson.Read(text, path);
            if (entry.SceneWalk is null)
            {
                throw new UsageException($"{path}: $.kind: scene export takes a scene walk; this file is kind \"{entry.Kind}\"");
            }

            export = DatFolder.Export(entry, Path.GetFileName(path));
        }
        else
        {
            Scene scene;
            try
            {
                scene = SceneJson.Read(text, path);
            }
            catch (InputFormatException e)
            {
                throw new UsageException(e.Message, e);
            }

            export = DatSceneWriter.Write(scene, Path.GetFileNameWithoutExtension(path), Path.GetFileName(path));
        }

        try
        {
            DatFolder.Write(dir, export);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new OutputPathException($"cannot write '{dir}' (--dat): {e.Message}", e);
        }

        var counts = export.Records.GroupBy(r => r.Record.Type).Select(g => $"{g.Count()} {g.Key}");
        Terminal.Line($"scene export: wrote {dir}: {export.Records.Count} records ({string.Join(", ", counts)}) and {DatFolder.ManifestName}");
        return ExitCodes.Ok;
    }

    private static int Import(string dir, string output)
    {
        OutputPath.Check("-o", output);
        OutputPath.CheckDistinct([("-o", output)], [dir]);
        if (!DatFolder.IsRecordFolder(dir))
        {
            throw new UsageException($"{(dir.Length == 0 ? "''" : dir)}: not a record folder (no {DatFolder.ManifestName})");
        }

        var (manifest, scene) = DatFolder.Read(dir);
        bool walk = manifest is { Header: not null, Walk: not null };
        string text = walk
            ? CorpusJson.Write(manifest.Header! with { SceneWalk = new AcPhys.Formats.Cases.SceneWalk(scene, manifest.Walk!) })
            : SceneJson.Write(scene);
        OutputPath.Write(output, text);
        Terminal.Line($"scene import: wrote {output} ({(walk ? "scene-walk corpus file" : "bare scene")}: {scene})");
        return ExitCodes.Ok;
    }

    private static bool IsCorpusFile(string text)
    {
        try
        {
            using var doc = JsonDocument.Parse(text);
            return doc.RootElement.ValueKind == JsonValueKind.Object && doc.RootElement.TryGetProperty("format", out _);
        }
        catch (JsonException)
        {
            return false;
        }
    }
}
