using System.Text.RegularExpressions;

namespace AcPhys.Cli;

/// <summary>Rewrites System.CommandLine's type-conversion errors (which name CLR types) into what a user can act on.</summary>
internal static partial class ParseErrors
{
    /// <summary>Returns <paramref name="message"/>, or a plain-words version of a "cannot parse ... as expected type" one.</summary>
    /// <param name="message">System.CommandLine's message.</param>
    /// <returns>The message to print.</returns>
    public static string Explain(string message)
    {
        var m = TypeError().Match(message);
        if (!m.Success)
        {
            return message;
        }

        string value = m.Groups["value"].Value;
        if (value.Length > 64)
        {
            value = value[..64] + "…";
        }

        string type = m.Groups["type"].Value;
        string expected = type switch
        {
            _ when type.Contains("System.Int32", StringComparison.Ordinal) => $"a whole number from {int.MinValue} to {int.MaxValue}",
            _ when type.Contains("System.Int64", StringComparison.Ordinal) => $"a whole number from {long.MinValue} to {long.MaxValue}",
            _ when type.Contains("System.UInt64", StringComparison.Ordinal) => $"a whole number from 0 to {ulong.MaxValue}",
            _ when type.Contains("System.UInt32", StringComparison.Ordinal) => $"a whole number from 0 to {uint.MaxValue}",
            _ when type.Contains("System.Double", StringComparison.Ordinal) || type.Contains("System.Single", StringComparison.Ordinal) => "a number",
            _ => "a value of another form (see --help)",
        };
        return $"{m.Groups["option"].Value}: '{value}' is not {expected}";
    }

    [GeneratedRegex(@"^Cannot parse argument '(?<value>.*)' for option '(?<option>[^']*)' as expected type '(?<type>[^']*)'", RegexOptions.Singleline)]
    private static partial Regex TypeError();
}
