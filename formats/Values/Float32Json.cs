using System.Globalization;
using System.Text.Json;

namespace AcPhys.Formats.Values;

/// <summary>
/// A float32 written in JSON, as every reader of the project takes it (corpus files, scene files, protocol requests and
/// answers; issue 19 "one validator"): a JSON number rounded once to float32, which must stay inside the float32 range,
/// or one of the strings <c>"NaN"</c>, <c>"Infinity"</c>, <c>"-Infinity"</c> where the format allows non-finite values.
/// </summary>
internal static class Float32Json
{
    /// <summary>The problem text of a JSON number outside the float32 range (e.g. <c>1e39</c>).</summary>
    public const string Overflow = "number overflows float32";

    private const string InfinityHint = " (write \"Infinity\" if that is meant)";

    /// <summary>Reads a float32 value.</summary>
    /// <param name="e">The JSON value.</param>
    /// <param name="nonFiniteNames">True when the strings "NaN", "Infinity", "-Infinity" are allowed (corpus and protocol), false where only numbers are (scene files).</param>
    /// <param name="value">The value read.</param>
    /// <param name="problem">What is wrong, without a location (the caller adds its path), or null.</param>
    /// <returns>True when <paramref name="value"/> holds a value.</returns>
    public static bool TryRead(JsonElement e, bool nonFiniteNames, out float value, out string? problem)
    {
        value = 0;
        problem = null;
        switch (e.ValueKind)
        {
            case JsonValueKind.Number:
                // Parsed straight to float32 (one rounding), so the shortest round-trip text of a float32 reads back as its bits.
                // Read from the number's own UTF-8 text in the document (no string per number: issue 26).
                value = float.Parse(System.Runtime.InteropServices.JsonMarshal.GetRawUtf8Value(e), NumberStyles.Float, CultureInfo.InvariantCulture);
                if (!float.IsFinite(value))
                {
                    problem = nonFiniteNames ? Overflow + InfinityHint : Overflow;
                    return false;
                }

                return true;
            case JsonValueKind.String when nonFiniteNames:
                string? text = InputQuote.TryText(e);
                switch (text)
                {
                    case "NaN":
                        value = float.NaN;
                        return true;
                    case "Infinity":
                        value = float.PositiveInfinity;
                        return true;
                    case "-Infinity":
                        value = float.NegativeInfinity;
                        return true;
                }

                break;
        }

        problem = (nonFiniteNames ? "expected a number or \"NaN\"/\"Infinity\"/\"-Infinity\", got " : "expected a number, got ") + InputQuote.Json(e);
        return false;
    }
}
