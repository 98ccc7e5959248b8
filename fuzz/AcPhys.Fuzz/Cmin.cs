using System.Security.Cryptography;
using AcPhys.Formats.Corpus;

namespace AcPhys.Fuzz;

/// <summary>
/// afl-cmin's job, done in the instrumented harness itself: the coverage of each input is its set of AFL tuples
/// (edge, hit-count bucket); the inputs already in the seed folder are kept, and a candidate is added, smallest first,
/// only when it covers a tuple nothing kept covers. So the folder only grows, and only with inputs that add coverage.
/// </summary>
internal static class Cmin
{

    /// <summary>Merges candidate inputs into a seed folder.</summary>
    /// <param name="test">The test (correct core).</param>
    /// <param name="seedDir">The seed folder (created; kept files are never removed).</param>
    /// <param name="candidateDirs">Folders of candidate inputs (an afl queue, ...).</param>
    /// <param name="log">Where to report.</param>
    /// <returns>The number of files added.</returns>
    public static int Run(Action<ReadOnlySpan<byte>> test, string seedDir, IEnumerable<string> candidateDirs, TextWriter log)
    {
        Directory.CreateDirectory(seedDir);
        var kept = Files(seedDir).ToList();
        var candidates = candidateDirs.Where(Directory.Exists).SelectMany(Files)
            .Select(f => (Path: f, Data: File.ReadAllBytes(f)))
            .OrderBy(c => c.Data.Length).ThenBy(c => c.Path, StringComparer.Ordinal)
            .ToList();

        if (kept.Count + candidates.Count > 0)
        {
            Tuples(test, kept.Count > 0 ? File.ReadAllBytes(kept[0]) : candidates[0].Data); // warm-up: static constructors
        }

        var covered = new HashSet<int>();
        var hashes = new HashSet<string>(StringComparer.Ordinal);
        foreach (var f in kept)
        {
            byte[] data = File.ReadAllBytes(f);
            hashes.Add(Hash(data));
            covered.UnionWith(Tuples(test, data).Tuples);
        }

        int before = covered.Count, added = 0, crashing = 0;
        foreach (var (path, data) in candidates)
        {
            string hash = Hash(data);
            if (!hashes.Add(hash))
            {
                continue;
            }

            var (tuples, crashed) = Tuples(test, data);
            if (crashed)
            {
                crashing++;
                continue; // a seed must pass on the correct core
            }

            if (tuples.Any(t => !covered.Contains(t)))
            {
                covered.UnionWith(tuples);
                AtomicFile.WriteAllBytes(Path.Combine(seedDir, hash), data);
                added++;
            }
        }

        log.WriteLine($"cmin: {kept.Count} kept + {candidates.Count} candidate(s) ({crashing} crashing, skipped) -> {added} added; tuples {before} -> {covered.Count}; {seedDir}");
        return added;
    }

    private static IEnumerable<string> Files(string dir) =>
        Directory.EnumerateFiles(dir).Where(f => !Path.GetFileName(f).StartsWith('.')).Order(StringComparer.Ordinal);

    private static string Hash(byte[] data) => Convert.ToHexStringLower(SHA256.HashData(data))[..16];

    private static (List<int> Tuples, bool Crashed) Tuples(Action<ReadOnlySpan<byte>> test, byte[] data)
    {
        PrivateMap.Reset();
        bool crashed = false;
        try
        {
            test(data);
        }
#pragma warning disable CA1031 // A crashing candidate is skipped, whatever it throws.
        catch (Exception)
#pragma warning restore CA1031
        {
            crashed = true;
        }

        var tuples = new List<int>();
        var map = PrivateMap.Current;
        for (int i = 0; i < map.Length; i++)
        {
            if (map[i] != 0)
            {
                tuples.Add((i << 4) | Bucket(map[i]));
            }
        }

        return (tuples, crashed);
    }

    // AFL's hit-count classes: 1, 2, 3, 4-7, 8-15, 16-31, 32-127, 128+.
    private static int Bucket(byte count) => count switch
    {
        1 => 0,
        2 => 1,
        3 => 2,
        < 8 => 3,
        < 16 => 4,
        < 32 => 5,
        < 128 => 6,
        _ => 7,
    };
}
