namespace AcPhys.E2E.Support;

/// <summary>Reads a verify report's lines: one by its prefix, and the seed of its replay line.</summary>
internal static class ReplayOutput
{
    /// <summary>Returns the first line of <paramref name="text"/> that starts with <paramref name="prefix"/>.</summary>
    /// <param name="text">The report.</param>
    /// <param name="prefix">The line's start.</param>
    /// <returns>The line.</returns>
    public static string Line(string text, string prefix) =>
        text.Split('\n').FirstOrDefault(l => l.StartsWith(prefix, StringComparison.Ordinal)) ?? throw new Xunit.Sdk.XunitException($"no line starting '{prefix}' in:\n{text}");

    /// <summary>Returns the <c>--seed</c> value of the report's first <c>replay     acphys verify</c> line.</summary>
    /// <param name="text">The report.</param>
    /// <returns>The seed, unquoted.</returns>
    public static string Seed(string text)
    {
        string replay = Line(text, "  replay     acphys verify");
        int at = replay.IndexOf("--seed ", StringComparison.Ordinal);
        Assert.True(at > 0, replay);
        return replay[(at + 7)..].Split(' ')[0].Trim('\'', '"');
    }
}
