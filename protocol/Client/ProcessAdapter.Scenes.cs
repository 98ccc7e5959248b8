using System.Runtime.CompilerServices;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Client;

/// <summary>Scenes on the wire: inline, or loaded once by id (as records when negotiated), the most recent few kept.</summary>
public sealed partial class ProcessAdapter
{
    // Scenes are immutable records: serialise each once, however many steps of a walk query it.
    private static readonly ConditionalWeakTable<Scene, string> CompactScenes = [];

    private void FindCellFields(Utf8JsonWriter w, Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current)
    {
        SceneField(w, scene);

        Wire.WriteCell(w, "cell", cell);
        Wire.WriteSpheres(w, "spheres", spheres);
        if (current.IsNone)
        {
            w.WriteNull("current");
        }
        else
        {
            Wire.WriteCell(w, "current", current);
        }
    }

    private void SceneField(Utf8JsonWriter w, Scene? scene)
    {
        if (scene is null || probing)
        {
            w.WriteNull("scene"); // probing: no scene is loaded for a request that is only converted (RefuseUnposable)
        }
        else if ((Capabilities & Capability.LoadScene) != 0)
        {
            w.WriteString("scene_id", SceneId(scene));
        }
        else
        {
            WriteScene(w, scene);
        }
    }

    // The scene as its compact JSON, serialised once per scene instance.
    private static void WriteScene(Utf8JsonWriter w, Scene scene)
    {
        w.WritePropertyName("scene");
        w.WriteRawValue(CompactScenes.GetValue(scene, SceneJson.WriteCompact), skipInputValidation: true);
    }

    // load_scene once per scene: the most recent few stay loaded (a walk, its translated copy, a shrink step's
    // neighbours), the oldest is unloaded to make room. To a pipelining child the tool chooses the id (docs/protocol.md,
    // "Pipelining"), so a find_cell can name a scene whose load is still in flight.
    private string SceneId(Scene scene)
    {
        lock (loaded)
        {
            int at = loaded.FindIndex(e => ReferenceEquals(e.Scene, scene));
            if (at >= 0)
            {
                var hit = loaded[at];
                loaded.RemoveAt(at);
                loaded.Add(hit);
                return hit.Id;
            }

            if (loaded.Count == KeptScenes)
            {
                string old = loaded[0].Id;
                loaded.RemoveAt(0);
                Transport("unload_scene", Answers.Ok, w => w.WriteString("scene_id", old), Answers.Ok.Read, true, null, old);
            }

            string? chosen = Pipelines ? "t" + (++chosenIds).ToString(System.Globalization.CultureInfo.InvariantCulture) : null;
            string id = Transport(
                "load_scene",
                Answers.SceneId,
                w =>
                {
                    if (chosen is not null)
                    {
                        w.WriteString("scene_id", chosen);
                    }

                    if ((Capabilities & Capability.DatRecords) != 0)
                    {
                        DatWire.WriteScene(w, "dat", scene);
                    }
                    else
                    {
                        WriteScene(w, scene);
                    }
                },
                a => Answers.SceneId.Read(a) is var answered && (chosen is null || answered == chosen)
                    ? answered
                    : throw new WireException($"load_scene answered scene_id \"{Wire.Brief(answered, 40)}\" for the id \"{chosen}\" the tool chose (a pipelining implementation keeps the client's id)"),
                chosen ?? string.Empty,
                chosen,
                null);
            loaded.Add((scene, id));
            return id;
        }
    }
}
