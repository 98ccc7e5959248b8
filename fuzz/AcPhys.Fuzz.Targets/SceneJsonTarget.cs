using System.Text;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Scenes;
using AcPhys.Spec.Scenes;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>scene-json</c> parser target: bytes → <see cref="SceneJson.Read(string, string)"/>, the reader of scene files
/// (<c>acphys scene</c>, scene walks in corpus files, scenes sent over the wire). The reader may reject an input only
/// with <see cref="InputFormatException"/>; any other exception is a bug. A scene it accepts must survive
/// write → read → write unchanged (<see cref="RoundTripException"/> otherwise).
/// </summary>
public sealed class SceneJsonTarget : FuzzTarget
{
    /// <summary>Tokens of the scene format and of JSON, for afl-fuzz's dictionary.</summary>
    private static readonly string[] Tokens =
    [
        "\"blocks\"", "\"unloadedBlocks\"", "\"unloadedCells\"", "\"cells\"", "\"id\"", "\"portals\"", "\"polygons\"",
        "\"NaN\"", "\"Infinity\"", "\"-Infinity\"", "null", "true", "false", "1e39", "-0", "2147483648", "\\u0000", "\\ud800",
        "\"0x40410100\"", "\"0x4041\"", "\"0xFF\"", "[", "]", "{", "}", ":", ",",
    ];

    /// <inheritdoc/>
    public override string Name => "scene-json";

    /// <inheritdoc/>
    public override string Description => "SceneJson.Read (scene files, scenes in corpus files and requests); only InputFormatException may escape";

    /// <inheritdoc/>
    public override TargetKind Kind => TargetKind.Parser;

    /// <inheritdoc/>
    public override IReadOnlyList<string> Dictionary => Tokens;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]>
    {
        ["cottage-two-rooms"] = Scene(SceneKit.Cottage(new CottagePlan((192.0 * 0x40) + 50, (192.0 * 0x41) + 60, 0.5f, 2, 6, 5, 0x5A, BackDoor: true, Storey: false))),
        ["cottage-storey"] = Scene(SceneKit.Cottage(new CottagePlan((192.0 * 0x10) + 186, (192.0 * 0x11) + 4, 0f, 3, 4, 4, 0x03, BackDoor: false, Storey: true, LoadNeighbours: false))),
        ["dungeon"] = Scene(SceneKit.Dungeon(new DungeonPlan((192.0 * 0x20) + 150, (192.0 * 0x21) + 30, 4, 8, 1, 0x33))),
    };

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data =>
        {
            Scene scene;
            try
            {
                scene = SceneJson.Read(Encoding.UTF8.GetString(data), "fuzz");
            }
            catch (InputFormatException)
            {
                return; // a clean rejection is the reader doing its job
            }

            string text = SceneJson.Write(scene);
            string again = SceneJson.Write(SceneJson.Read(text, "rewritten"));
            if (again != text)
            {
                throw new RoundTripException($"scene-json: an accepted scene does not survive write → read → write:\n{text}\n---\n{again}");
            }
        };
    }

    private static byte[] Scene(Scene scene) => Encoding.UTF8.GetBytes(SceneJson.Write(scene));
}
