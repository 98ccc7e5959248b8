using System.Numerics;
using System.Text.Json;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Values;

namespace AcPhys.Formats.Capture;

/// <summary>
/// The body headers of a capture: <c># radius: r</c> (one sphere at the position) and <c># body: [{"x","y","z","r"}, …]</c>
/// (several spheres as protocol v1 writes a walk's <c>body</c>: offsets from the position and radii; sphere 0 decides the pick).
/// </summary>
internal static class CaptureBodyHeader
{
    /// <summary>Parses a <c># radius:</c> value.</summary>
    /// <param name="value">The text after the colon.</param>
    /// <param name="problem">What is wrong, or null.</param>
    /// <returns>The body.</returns>
    public static IReadOnlyList<BodySphere> Radius(ReadOnlySpan<byte> value, out string? problem)
    {
        if (!CaptureText.TryNumber(value, out double r, out _))
        {
            problem = $"# radius: expected {CaptureText.NumberExpected}, got \"{CaptureText.Quote(value)}\"";
            return [];
        }

        problem = SphereRadius.Problem((float)r) is { } p ? "# radius: " + p : null;
        return [new BodySphere(Vector3.Zero, (float)r)];
    }

    /// <summary>Parses a <c># body:</c> value.</summary>
    /// <param name="value">The text after the colon: a JSON array of spheres.</param>
    /// <param name="problem">What is wrong, or null.</param>
    /// <returns>The body.</returns>
    public static IReadOnlyList<BodySphere> Body(ReadOnlySpan<byte> value, out string? problem)
    {
        try
        {
            using var doc = JsonDocument.Parse(value.ToArray(), new JsonDocumentOptions { MaxDepth = 4 });
            var root = doc.RootElement;
            if (root.ValueKind != JsonValueKind.Array)
            {
                problem = "# body: expected a JSON array of spheres [{\"x\":0,\"y\":0,\"z\":0.48,\"r\":0.48}, ...]";
                return [];
            }

            if (SphereList.Problem(root.GetArrayLength(), 1) is { } count)
            {
                problem = "# body: " + count;
                return [];
            }

            var body = new List<BodySphere>();
            foreach (var s in root.EnumerateArray())
            {
                string at = $"# body[{body.Count}]";
                if (s.ValueKind != JsonValueKind.Object || !Number(s, "x", out float x) || !Number(s, "y", out float y) || !Number(s, "z", out float z) || !Number(s, "r", out float r))
                {
                    problem = at + ": expected {\"x\", \"y\", \"z\", \"r\"}, finite numbers";
                    return [];
                }

                if (SphereRadius.Problem(r) is { } bad)
                {
                    problem = at + ".r: " + bad;
                    return [];
                }

                body.Add(new BodySphere(new Vector3(x, y, z), r));
            }

            problem = null;
            return body;
        }
        catch (JsonException e)
        {
            problem = "# body: not valid JSON: " + e.Message;
            return [];
        }
    }

    private static bool Number(JsonElement e, string name, out float v)
    {
        v = 0;
        return e.TryGetProperty(name, out var p) && p.ValueKind == JsonValueKind.Number && p.TryGetDouble(out double d)
            && float.IsFinite(v = (float)d);
    }
}
