using System.Text.RegularExpressions;

namespace AcPhys.Fuzz.Targets;

/// <summary>Turns a failure message into a group signature: bracketed lists become <c>[…]</c>; numbers, hex ids and float specials <c>#</c>.</summary>
public static partial class Signatures
{
    /// <summary>Masks the variable parts of a message.</summary>
    /// <param name="message">The message.</param>
    /// <returns>The signature (at most 160 characters).</returns>
    public static string Of(string message)
    {
        string masked = Numbers().Replace(Lists().Replace(message, "[…]"), "#");
        return masked.Length <= 160 ? masked : masked[..160];
    }

    /// <summary>Returns the signature of an exception: its type and the first frame in project code.</summary>
    /// <param name="e">The exception.</param>
    /// <returns>The signature.</returns>
    public static string Of(Exception e)
    {
        string frame = (e.StackTrace ?? string.Empty)
            .Split('\n', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries)
            .FirstOrDefault(l => l.Contains("AcPhys.", StringComparison.Ordinal) && !l.Contains("AcPhys.Fuzz.", StringComparison.Ordinal))
            ?? "(no project frame)";
        int cut = frame.IndexOf(" in ", StringComparison.Ordinal);
        return e.GetType().Name + " at " + (cut > 0 ? frame[..cut] : frame).Replace("at ", string.Empty, StringComparison.Ordinal);
    }

    [GeneratedRegex(@"\[[^\[\]]*\]")]
    private static partial Regex Lists();

    [GeneratedRegex(@"0x[0-9A-Fa-f]+|[-+]?\d+(\.\d+)?([eE][-+]?\d+)?|-?Infinity|NaN")]
    private static partial Regex Numbers();
}
