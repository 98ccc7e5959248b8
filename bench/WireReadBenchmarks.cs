using System.Reflection;
using AcPhys.Contract;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using BenchmarkDotNet.Attributes;

namespace AcPhys.Bench;

/// <summary>
/// Reading protocol v1 lines as the two ends do (issue #26, "parse once"): the server reads a request and its fields,
/// the client an answer. The lines (bench/WireLines) are median lines of a served <c>acphys verify</c> run.
/// </summary>
[MemoryDiagnoser]
public class WireReadBenchmarks
{
    private readonly string findCell = Line("find_cell");
    private readonly string findCellWalk = Line("find_cell_walk");
    private readonly string loadSceneDat = Line("load_scene_dat");
    private readonly string loadSceneJson = Line("load_scene_json");
    private readonly string findCellAnswer = Line("find_cell_answer");
    private readonly string findCellWalkAnswer = Line("find_cell_walk_answer");
    private readonly Scene sceneForRecords = SceneOf(Line("load_scene_json"));

    [Benchmark(Description = "server: find_cell request (open land, 153 B)")]
    public int FindCellRequest()
    {
        using var doc = Wire.Parse(findCell);
        var r = doc.RootElement;
        return Wire.ReadCell(r, "cell").GetHashCode() + Wire.ReadSpheres(r, "spheres").Length + Wire.ReadOrigin(r).GetHashCode() + Wire.ReadOptionalCell(r, "current").GetHashCode();
    }

    [Benchmark(Description = "server: find_cell_walk request (2.6 KB)")]
    public int FindCellWalkRequest()
    {
        using var doc = Wire.Parse(findCellWalk);
        return WalkWire.ReadFields(doc.RootElement, null).Steps.Count;
    }

    [Benchmark(Description = "server: load_scene request, dat records (12 KB)")]
    public int LoadSceneDatRequest()
    {
        using var doc = Wire.Parse(loadSceneDat);
        return DatWire.ReadScene(doc.RootElement.GetProperty("dat")).Cells.Count;
    }

    [Benchmark(Description = "server: load_scene request, scene JSON (1.8 KB)")]
    public int LoadSceneJsonRequest()
    {
        using var doc = Wire.Parse(loadSceneJson);
        return SceneJson.Read(doc.RootElement.GetProperty("scene"), "find_cell", "$.scene").Cells.Count;
    }

    [Benchmark(Description = "client: the load_scene scene written as dat records")]
    public int WriteSceneRecords() => AcPhys.Formats.Dat.DatSceneWriter.Write(sceneForRecords, "wire", "load_scene").Records.Count;

    [Benchmark(Description = "client: find_cell answer (147 B)")]
    public int FindCellAnswer()
    {
        using var doc = Wire.Parse(findCellAnswer);
        return Wire.ReadFindCell(doc.RootElement).Cells.Count;
    }

    [Benchmark(Description = "client: find_cell_walk answer (6.1 KB)")]
    public int FindCellWalkAnswer()
    {
        using var doc = Wire.Parse(findCellWalkAnswer);
        var root = doc.RootElement;
        return WalkWire.ReadAnswer(root, root.GetProperty("steps").GetArrayLength()).Count;
    }

    private static Scene SceneOf(string line)
    {
        using var doc = Wire.Parse(line);
        return SceneJson.Read(doc.RootElement.GetProperty("scene"), "find_cell", "$.scene");
    }

    private static string Line(string name)
    {
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(name + ".jsonl")
            ?? throw new InvalidOperationException($"bench/WireLines/{name}.jsonl is not embedded");
        using var reader = new StreamReader(stream);
        return reader.ReadLine() ?? throw new InvalidOperationException($"bench/WireLines/{name}.jsonl is empty");
    }
}
