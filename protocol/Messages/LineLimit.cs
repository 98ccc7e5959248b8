using System.Globalization;
using AcPhys.Protocol.Child;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The per-line size limit of protocol v1 in this tool: <see cref="BoundedLineReader.DefaultMaxBytes"/> (1 MiB), or
/// the number of bytes in the environment variable <see cref="Variable"/>.
/// </summary>
public static class LineLimit
{
    /// <summary>The environment variable that overrides the limit (bytes, 1 to 1 GiB).</summary>
    public const string Variable = "ACPHYS_MAX_LINE";

    /// <summary>Reads the limit from the environment.</summary>
    /// <param name="problem">What is wrong with the variable's value, or null.</param>
    /// <returns>The limit in bytes (the default when the variable is unset or malformed).</returns>
    public static int FromEnvironment(out string? problem)
    {
        problem = null;
        string? text = Environment.GetEnvironmentVariable(Variable);
        if (string.IsNullOrEmpty(text))
        {
            return BoundedLineReader.DefaultMaxBytes;
        }

        if (int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int bytes) && bytes is >= 1 and <= 1 << 30)
        {
            return bytes;
        }

        problem = $"{Variable}='{AcPhys.Formats.Values.InputQuote.Brief(text)}': expected a number of bytes, 1 to 1073741824";
        return BoundedLineReader.DefaultMaxBytes;
    }
}
