using System.Globalization;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Protocol.Client;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// <c>find_cell_parts_walk</c> on the wire (docs/protocol.md, "Whole parts walks"): the request's <c>steps</c>, one
/// <c>{"parts": [...]}</c> per query in walk order, and <c>load_cells</c> for the transition kind; the scene travels as
/// <c>find_cell_parts_scene</c>'s does and the answer is <c>find_cell_walk</c>'s (<see cref="WalkWire.WriteAnswer"/>).
/// One write/read pair shared by the client (<see cref="ProcessAdapter"/>) and the server (<see cref="Server.ProtocolServer"/>).
/// </summary>
internal static class PartsWalkWire
{
    /// <summary>Writes the walk's fields (the scene field aside).</summary>
    /// <param name="w">The writer, inside the request object.</param>
    /// <param name="queries">The parts queries, in order.</param>
    /// <param name="loadCells">True for the transition kind (written only when true).</param>
    public static void WriteFields(Utf8JsonWriter w, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells)
    {
        w.WriteStartArray("steps");
        foreach (var parts in queries)
        {
            w.WriteStartObject();
            PartWire.WriteParts(w, "parts", parts);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        if (loadCells)
        {
            w.WriteBoolean("load_cells", true);
        }
    }

    /// <summary>Reads the walk's fields by the rules of one parts query (the part count and bounds of <c>outside_cells_parts</c>).</summary>
    /// <param name="request">The request object.</param>
    /// <param name="loadCells">True for the transition kind.</param>
    /// <returns>The parts queries, in order.</returns>
    /// <exception cref="WireException">A field is missing or malformed, or there are more than <see cref="WalkWire.MaxSteps"/> steps.</exception>
    public static IReadOnlyList<IReadOnlyList<Part>> ReadFields(JsonElement request, out bool loadCells)
    {
        var steps = Wire.Field(request, "steps");
        if (steps.ValueKind != JsonValueKind.Array)
        {
            throw new WireException("field \"steps\" must be an array of {\"parts\": [...]}");
        }

        int count = steps.GetArrayLength();
        if (count > WalkWire.MaxSteps)
        {
            throw new WireException(string.Create(CultureInfo.InvariantCulture, $"field \"steps\": at most {WalkWire.MaxSteps:N0} steps, got {count:N0}"));
        }

        var queries = new IReadOnlyList<Part>[count];
        int i = 0;
        foreach (var s in steps.EnumerateArray())
        {
            if (s.ValueKind != JsonValueKind.Object)
            {
                throw new WireException(string.Create(CultureInfo.InvariantCulture, $"field \"steps[{i}]\" must be an object {{\"parts\": [...]}}, got {Wire.Show(s)}"));
            }

            try
            {
                queries[i] = PartWire.ReadParts(s, "parts");
            }
            catch (WireException e)
            {
                throw new WireException(string.Create(CultureInfo.InvariantCulture, $"steps[{i}]: {e.Message}"), e);
            }

            i++;
        }

        loadCells = request.TryGetProperty("load_cells", out var lc) && lc.ValueKind != JsonValueKind.Null && Wire.ReadBool(request, "load_cells");
        return queries;
    }
}
