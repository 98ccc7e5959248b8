using System.Text.Json.Nodes;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Core.Text;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The world-frame mode of protocol v1 (docs/protocol.md, "World frame"; issue #29): for a port that keeps one world
/// frame, every block-frame point of a request (sphere centres, <c>origin</c>, the <c>x</c>/<c>y</c> of
/// get_outside_lcoord and adjust_to_outside, each part's <c>origin</c>) is sent as world metres — x and y plus the
/// block origin of the cell the point is framed in, (192 · block x, 192 · block y), added in double — and the
/// request names that origin in <c>block_origin</c>. z, radii and every answer are unchanged.
/// </summary>
/// <remarks>
/// A float32 x plus an integer origin below 2¹⁶ is exact in double whenever |x| ≥ 2⁻¹⁴ m (or x is 0 or not finite):
/// the port gets the world value exactly and <c>(float)(X − origin)</c> gives back the tool's x bit for bit. A centre
/// the double cannot carry (0 &lt; |x| &lt; 2⁻¹⁴ m, within 61 µm of its block's own origin line) is not sent: the
/// case is not judged (<see cref="UnposableQueryException"/>), so the conversion can never fail a correct port.
/// </remarks>
public static class WorldFrame
{
    /// <summary>The handshake value of <c>frame</c> that selects this mode (the default is <c>"block"</c>).</summary>
    public const string Name = "world";

    /// <summary>Rewrites a block-frame request line into the world frame (the tool's side).</summary>
    /// <param name="request">The request, as <see cref="Wire.Line"/> wrote it.</param>
    /// <returns>The request with world coordinates and <c>block_origin</c>.</returns>
    /// <exception cref="UnposableQueryException">A coordinate cannot be carried exactly in double.</exception>
    public static string ToWorld(string request) => Rewrite(request, toWorld: true) ?? request;

    /// <summary>Rewrites a world-frame request line back into block frames, as a world-frame port's own code would (the shim behind <c>acphys serve --world-frame</c>; its planted bug is spec's fault <c>world-frame-swapped-axes</c>).</summary>
    /// <param name="request">The request line.</param>
    /// <returns>The request in block frames (unchanged when it is not a JSON object: the server's parser reports that).</returns>
    public static string ToBlock(string request) => Rewrite(request, toWorld: false) ?? request;

    /// <summary>Returns the world origin of a cell's landblock: (192 · block x, 192 · block y), exact in double.</summary>
    /// <param name="cell">Any id.</param>
    /// <returns>The origin, metres.</returns>
    public static (double X, double Y) BlockOrigin(CellId cell) => (192.0 * cell.BlockX, 192.0 * cell.BlockY);

    private static string? Rewrite(string line, bool toWorld)
    {
        JsonObject? request;
        try
        {
            request = JsonNode.Parse(line) as JsonObject;
        }
        catch (System.Text.Json.JsonException)
        {
            return null;
        }

        if (request is null || !request.TryGetPropertyValue("op", out var opNode) || opNode is not JsonValue opValue || !opValue.TryGetValue(out string? op))
        {
            return null;
        }

        void Point(JsonNode? node, JsonNode? cellNode, bool named)
        {
            if (node is not JsonObject point || cellNode is not JsonValue cv || !cv.TryGetValue(out string? text) || !CellIdText.TryParse(text, out var cell))
            {
                return; // malformed: left for the server's own parser to report
            }

            var (ox, oy) = BlockOrigin(cell);
            Coordinate(point, "x", ox, toWorld);
            Coordinate(point, "y", oy, toWorld);
            if (named && toWorld)
            {
                request["block_origin"] = new JsonArray(ox, oy);
            }
        }

        switch (op)
        {
            case "get_outside_lcoord" or "adjust_to_outside":
                Point(request, request["cell"], true);
                break;
            case "outside_cells" or "find_cell":
                foreach (var sphere in request["spheres"] as JsonArray ?? [])
                {
                    Point(sphere, request["cell"], true);
                }

                Point(request["origin"], request["cell"], true);
                break;
            case "outside_cells_parts" or "find_cell_parts_scene" or "find_cell_parts_transition":
                foreach (var part in request["parts"] as JsonArray ?? [])
                {
                    Point(part?["origin"], part?["cell"], false);
                }

                break;
            default:
                return null;
        }

        return request.ToJsonString();
    }

    // One coordinate: world = origin + x in double (exact or refused); block = (float)(world − origin).
    private static void Coordinate(JsonObject point, string name, double origin, bool toWorld)
    {
        if (point[name] is not JsonValue v || !v.TryGetValue(out double value) || !double.IsFinite(value))
        {
            return; // "NaN", "Infinity" and malformed values travel as they are
        }

        if (toWorld)
        {
            double world = origin + value;
            if (world - origin != value)
            {
                throw new UnposableQueryException($"{name} = {value:R} m in its block frame cannot be sent exactly as a world coordinate in double (world-frame mode, docs/protocol.md \"World frame\"); case not judged");
            }

            point[name] = world;
        }
        else
        {
            point[name] = (double)(float)(value - origin);
        }
    }
}
