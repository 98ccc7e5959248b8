using System.Runtime.CompilerServices;
using AcPhys.Contract;

namespace AcPhys.Formats.Dat;

/// <summary>
/// A scene as an implementation that reads dat records sees it: read(write(scene)), cached per scene instance. Portal
/// planes come back as their polygons' planes, rebuilt from float32 vertices (docs/dat-scenes.md, "Round trip"), so an
/// oblique portal's plane may differ from the JSON scene's by float32 rounding; the conformance reference answers on
/// this form for an implementation that announced <c>dat_records</c>, so the rounding is never read as a deviation.
/// </summary>
public static class DatRoundTrip
{
    private static readonly ConditionalWeakTable<Scene, Scene> Cache = [];

    // The last few exports, by scene instance: a scene's load and its read-back come close together, and writing again
    // gives the same bytes. Not a ConditionalWeakTable (issue 26: one dependent handle per scene sent made every
    // collection of the tool slower).
    private static readonly (Scene? Scene, DatExport? Export)[] Recent = new (Scene?, DatExport?)[16];
    private static int next;

    /// <summary>Returns the records a scene travels as (protocol v1 <c>load_scene</c> with <c>dat</c>), written once per scene instance.</summary>
    /// <param name="scene">A valid scene.</param>
    /// <returns>The export (manifest title "wire", source "load_scene").</returns>
    /// <exception cref="InputFormatException">The scene exceeds what the records hold.</exception>
    public static DatExport Records(Scene scene)
    {
        lock (Recent)
        {
            foreach (var (s, e) in Recent)
            {
                if (ReferenceEquals(s, scene))
                {
                    return e!;
                }
            }
        }

        long t = AcPhys.Formats.Values.WireProfile.Start();
        var export = DatSceneWriter.Write(scene, "wire", "load_scene");
        AcPhys.Formats.Values.WireProfile.Stop("tool: DatSceneWriter.Write", t);
        lock (Recent)
        {
            Recent[next] = (scene, export);
            next = (next + 1) % Recent.Length;
        }

        return export;
    }

    /// <summary>Returns the scene as the records give it back.</summary>
    /// <param name="scene">A valid scene.</param>
    /// <returns>read(write(scene)), read from the very records <see cref="Records"/> sends.</returns>
    public static Scene Of(Scene scene) => Cache.GetValue(scene, s => AcPhys.Formats.Values.WireProfile.Time("tool: records read back (guess's scene)", () =>
    {
        var export = Records(s);
        var bytes = export.Records.ToDictionary(r => r.Record, r => r.Bytes);
        return DatSceneReader.Read(export.Manifest, r => bytes[r]);
    }));
}
