namespace AcPhys.Cli;

/// <summary>Finds the known word a mistyped one was probably meant to be.</summary>
internal static class Suggest
{
    /// <summary>Returns the candidate closest to <paramref name="word"/> within two edits, or null.</summary>
    /// <param name="word">What was typed.</param>
    /// <param name="candidates">The known words.</param>
    /// <returns>The suggestion, or null.</returns>
    public static string? Closest(string? word, IEnumerable<string> candidates)
    {
        if (string.IsNullOrEmpty(word) || word.StartsWith('-'))
        {
            return null;
        }

        return candidates
            .Select(c => (Word: c, Distance: Distance(word.ToLowerInvariant(), c)))
            .Where(c => c.Distance <= 2)
            .OrderBy(c => c.Distance)
            .Select(c => c.Word)
            .FirstOrDefault();
    }

    private static int Distance(string a, string b)
    {
        var row = Enumerable.Range(0, b.Length + 1).ToArray();
        for (int i = 1; i <= a.Length; i++)
        {
            int diagonal = row[0];
            row[0] = i;
            for (int j = 1; j <= b.Length; j++)
            {
                int above = row[j];
                row[j] = Math.Min(Math.Min(row[j] + 1, row[j - 1] + 1), diagonal + (a[i - 1] == b[j - 1] ? 0 : 1));
                diagonal = above;
            }
        }

        return row[b.Length];
    }
}
