using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Protocol.Client;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// <c>find_cell_walk</c> on the wire (docs/protocol.md, "Whole walks"): the request's walk fields and the answer's
/// <c>steps</c>, one write/read pair shared by the client (<see cref="ProcessAdapter"/>) and the server
/// (<see cref="Server.ProtocolServer"/>).
/// </summary>
public static class WalkWire
{
    /// <summary>The most steps one walk request may carry (bounded input; a longer walk is asked step by step).</summary>
    public const int MaxSteps = 10_000;

    /// <summary>Writes a walk's fields (the scene field aside): <c>cell</c>, <c>origin</c>, <c>current</c>, <c>body</c>, <c>steps</c>, <c>load_cells</c> when true.</summary>
    /// <param name="w">The writer, inside the request object.</param>
    /// <param name="walk">The walk.</param>
    public static void WriteFields(Utf8JsonWriter w, WalkRequest walk)
    {
        Wire.WriteCell(w, "cell", walk.StartCell);
        Wire.WriteVector(w, "origin", walk.Start);
        if (walk.Current.IsNone)
        {
            w.WriteNull("current");
        }
        else
        {
            Wire.WriteCell(w, "current", walk.Current);
        }

        Wire.WriteSpheres(w, "body", walk.Body);
        w.WriteStartArray("steps");
        foreach (var d in walk.Steps)
        {
            w.WriteStartObject();
            Wire.WriteFloat(w, "x"u8, d.X);
            Wire.WriteFloat(w, "y"u8, d.Y);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        if (walk.LoadCells)
        {
            w.WriteBoolean("load_cells", true);
        }
    }

    /// <summary>Reads a walk's fields by the same rules as single queries (float32 values, sphere list and radius rules).</summary>
    /// <param name="request">The request object.</param>
    /// <param name="scene">The scene the request names, already resolved (null for open land).</param>
    /// <returns>The walk.</returns>
    /// <exception cref="WireException">A field is missing or malformed.</exception>
    public static WalkRequest ReadFields(JsonElement request, AcPhys.Contract.Scene? scene)
    {
        var cell = Wire.ReadCell(request, "cell");
        var origin = Wire.ReadVector(request, "origin");
        var current = Wire.ReadOptionalCell(request, "current");
        var body = Wire.ReadSpheres(request, "body");
        var steps = Wire.Field(request, "steps");
        if (steps.ValueKind != JsonValueKind.Array)
        {
            throw new WireException("field \"steps\" must be an array of {x,y}");
        }

        int count = steps.GetArrayLength();
        if (count > MaxSteps)
        {
            throw new WireException(string.Create(CultureInfo.InvariantCulture, $"field \"steps\": at most {MaxSteps:N0} steps, got {count:N0}"));
        }

        var moves = new Vector2[count];
        int i = 0;
        foreach (var s in steps.EnumerateArray())
        {
            if (s.ValueKind != JsonValueKind.Object)
            {
                throw new WireException($"field \"{StepPath(i)}\" must be an object {{x,y}}, got {Wire.Show(s)}");
            }

            moves[i] = new Vector2(ReadFloatAt(s, "x", i), ReadFloatAt(s, "y", i));
            i++;
        }

        bool loadCells = request.TryGetProperty("load_cells", out var lc) && lc.ValueKind != JsonValueKind.Null && Wire.ReadBool(request, "load_cells");
        return new WalkRequest(scene, cell, origin, body, moves) { Current = current, LoadCells = loadCells };
    }

    /// <summary>Writes the answer's <c>steps</c>: one find_cell answer object per query.</summary>
    /// <param name="w">The writer, inside the answer object.</param>
    /// <param name="answers">The answers.</param>
    public static void WriteAnswer(Utf8JsonWriter w, IReadOnlyList<FindCellResult> answers)
    {
        w.WriteStartArray("steps");
        foreach (var a in answers)
        {
            w.WriteStartObject();
            Wire.WriteFindCell(w, a);
            w.WriteEndObject();
        }

        w.WriteEndArray();
    }

    /// <summary>Reads the answer's <c>steps</c>, which must hold one answer per query.</summary>
    /// <param name="answer">The answer object.</param>
    /// <param name="queries">The walk's query count.</param>
    /// <returns>The answers.</returns>
    /// <exception cref="WireException">Not one well-formed find_cell answer per query.</exception>
    public static IReadOnlyList<FindCellResult> ReadAnswer(JsonElement answer, int queries)
    {
        var steps = Wire.Field(answer, "steps");
        if (steps.ValueKind != JsonValueKind.Array)
        {
            throw new WireException("field \"steps\" must be an array of find_cell answers");
        }

        if (steps.GetArrayLength() != queries)
        {
            throw new WireException(string.Create(CultureInfo.InvariantCulture, $"field \"steps\" has {steps.GetArrayLength()} answers for a walk of {queries} queries"));
        }

        var answers = new FindCellResult[queries];
        int i = 0;
        foreach (var s in steps.EnumerateArray())
        {
            try
            {
                answers[i++] = Wire.ReadFindCell(s);
            }
            catch (WireException e)
            {
                throw new WireException(string.Create(CultureInfo.InvariantCulture, $"steps[{i - 1}]: {e.Message}"), e);
            }
        }

        return answers;
    }

    // The step's path is spelt only for a message (issue 26: per step it was a tenth of a walk request's reading).
    private static float ReadFloatAt(JsonElement obj, string name, int step)
    {
        if (Wire.TryReadFloat(obj, name, out float f))
        {
            return f; // well-formed: no exception frame, no message
        }

        try
        {
            return Wire.ReadFloat(obj, name);
        }
        catch (WireException e)
        {
            throw new WireException($"{StepPath(step)}: {e.Message}", e);
        }
    }

    private static string StepPath(int step) => string.Create(CultureInfo.InvariantCulture, $"steps[{step}]");
}
