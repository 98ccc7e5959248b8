using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Cli.Render;

/// <summary>
/// One colour per cell for a scene drawing: env cells (indoor) from a blue–purple palette in scene order, land cells
/// (outdoor) from a green–olive palette in order of first use, grey for no cell. Portal colours are kept out of both.
/// </summary>
internal sealed class CellColours
{
    /// <summary>Exit portals (to the outside).</summary>
    public const string Exit = "#e67e00";

    /// <summary>Portals between two loaded env cells.</summary>
    public const string Inter = "#00897b";

    /// <summary>Portals into a cell that is not loaded (load hints).</summary>
    public const string Hint = "#888888";

    /// <summary>No containing cell.</summary>
    public const string None = "#999999";

    private static readonly string[] Indoor = ["#3366cc", "#9933cc", "#cc3399", "#0099c6", "#316395", "#994499", "#5574a6", "#dd4477"];
    private static readonly string[] Outdoor = ["#2e8b57", "#6b8e23", "#8b8b00", "#228b22", "#556b2f", "#3cb371"];
    private readonly Dictionary<CellId, string> map = [];
    private int land;

    /// <summary>Initializes a new instance with the scene's env cells coloured in order.</summary>
    /// <param name="scene">The scene.</param>
    public CellColours(Scene scene)
    {
        for (int i = 0; i < scene.Cells.Count; i++)
        {
            map[scene.Cells[i].Id] = Indoor[i % Indoor.Length];
        }
    }

    /// <summary>Returns a cell's colour, giving a land cell the next outdoor colour on first use.</summary>
    /// <param name="id">The cell.</param>
    /// <returns>The colour.</returns>
    public string Of(CellId id)
    {
        if (id.IsNone)
        {
            return None;
        }

        if (!map.TryGetValue(id, out var colour))
        {
            colour = id.IsLand ? Outdoor[land++ % Outdoor.Length] : Indoor[map.Count % Indoor.Length];
            map[id] = colour;
        }

        return colour;
    }
}
