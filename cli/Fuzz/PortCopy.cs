using System.Globalization;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// The instrumented copy of an <c>--impl</c> port that the harness loads under afl-fuzz: the adapter's folder copied into
/// the campaign (<see cref="FuzzSettings.PortDir"/>; the port's build output is never written to), and in it the
/// adapter's assembly and the port's own assemblies instrumented with SharpFuzz, so afl-fuzz is guided by the port's
/// branches. The copy is made again only when the port's files or the chosen assemblies changed (a stamp), so the
/// same port keeps the same block ids and a resumed queue stays meaningful.
/// </summary>
internal static partial class PortCopy
{
    private const string StampFile = ".acphys-port-stamp";
    private const string ProbesFile = ".acphys-port-probes";

    /// <summary>
    /// Chooses the assemblies to instrument: the names given (<c>--instrument</c>), else the adapter's assembly and every
    /// assembly its .deps.json lists as a project (the port's own code), never the suite's AcPhys.* (they load from the
    /// tool, so a copy's probes would never run), packages or the framework.
    /// </summary>
    /// <param name="adapter">The adapter assembly.</param>
    /// <param name="named">The <c>--instrument</c> names (with or without .dll), or empty.</param>
    /// <returns>The file names, in the adapter's folder.</returns>
    /// <exception cref="UsageException">A named assembly is not in the adapter's folder, or is one of the suite's.</exception>
    public static IReadOnlyList<string> Choose(string adapter, IReadOnlyList<string> named)
    {
        string dir = Path.GetDirectoryName(adapter)!;
        if (named.Count > 0)
        {
            var files = named.Select(n => n.EndsWith(".dll", StringComparison.OrdinalIgnoreCase) ? n : n + ".dll").Distinct(StringComparer.Ordinal).ToList();
            foreach (string f in files)
            {
                if (f.StartsWith("AcPhys.", StringComparison.OrdinalIgnoreCase))
                {
                    throw new UsageException($"--instrument {f}: the suite's assemblies load from the tool, not from the port's folder, so a copy would never run");
                }

                if (Path.GetFileName(f) != f || !File.Exists(Path.Combine(dir, f)))
                {
                    throw new UsageException($"--instrument {AcPhys.Formats.Values.InputQuote.Line(f, 80)}: no such assembly beside the adapter in {dir}");
                }
            }

            return files;
        }

        var chosen = new List<string> { Path.GetFileName(adapter) };
        string deps = Path.ChangeExtension(adapter, ".deps.json");
        if (File.Exists(deps))
        {
            try
            {
                using var doc = JsonDocument.Parse(File.ReadAllBytes(deps));
                if (doc.RootElement.TryGetProperty("libraries", out var libraries) && libraries.ValueKind == JsonValueKind.Object)
                {
                    foreach (var lib in libraries.EnumerateObject())
                    {
                        string name = lib.Name.Split('/')[0] + ".dll";
                        bool project = lib.Value.ValueKind == JsonValueKind.Object && lib.Value.TryGetProperty("type", out var type) && type.ValueKind == JsonValueKind.String && type.GetString() == "project";
                        if (project && !name.StartsWith("AcPhys.", StringComparison.OrdinalIgnoreCase) && !chosen.Contains(name) && File.Exists(Path.Combine(dir, name)))
                        {
                            chosen.Add(name);
                        }
                    }
                }
            }
            catch (JsonException)
            {
                // an unreadable deps.json: the adapter's assembly alone
            }
        }

        return chosen;
    }

    /// <summary>Makes (or reuses) the instrumented copy; returns what the summary says about it.</summary>
    /// <param name="s">The settings (the harness and instrumenter built).</param>
    /// <param name="say">Progress sink.</param>
    /// <param name="stop">Cancelled by Ctrl-C / SIGTERM.</param>
    /// <returns>The instrumented assemblies and their probes (instrumented blocks).</returns>
    public static (IReadOnlyList<string> Assemblies, int Probes) Ensure(FuzzSettings s, Action<string> say, CancellationToken stop)
    {
        string adapter = s.Port.AssemblyPath!;
        string source = Path.GetDirectoryName(adapter)!;
        var chosen = Choose(adapter, s.Instrument);
        string stamp = Stamp(source, chosen);
        string stampPath = Path.Combine(s.PortDir, StampFile);
        string probesPath = Path.Combine(s.PortDir, ProbesFile);
        if (File.Exists(stampPath) && File.ReadAllText(stampPath) == stamp && File.Exists(probesPath) && File.Exists(s.PortAssembly))
        {
            say($"port: reusing the instrumented copy in {s.PortDir}");
            return (chosen, int.Parse(File.ReadAllText(probesPath), CultureInfo.InvariantCulture));
        }

        if (Directory.Exists(s.PortDir))
        {
            Directory.Delete(s.PortDir, recursive: true);
        }

        Copy(source, s.PortDir);
        say($"port: copied {source} into {s.PortDir}; instrumenting {string.Join(", ", chosen)}");
        string output = HarnessBuild.Instrument(s, [.. chosen.Select(f => Path.Combine(s.PortDir, f))], Path.Combine(s.LogDir, "instrument-port.log"), stop);
        int probes = ProbeCount().Matches(output).Sum(m => int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture));
        foreach (string line in output.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            say("  " + line);
        }

        AcPhys.Formats.Corpus.AtomicFile.WriteAllText(probesPath, probes.ToString(CultureInfo.InvariantCulture));
        AcPhys.Formats.Corpus.AtomicFile.WriteAllText(stampPath, stamp); // last: a killed copy is made again next time
        return (chosen, probes);
    }

    // The port's files (names, sizes, contents) and the chosen assemblies.
    private static string Stamp(string source, IReadOnlyList<string> chosen)
    {
        using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        foreach (string f in Directory.EnumerateFiles(source, "*", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
        {
            hash.AppendData(Encoding.UTF8.GetBytes(Path.GetRelativePath(source, f) + "\n"));
            hash.AppendData(File.ReadAllBytes(f));
        }

        hash.AppendData(Encoding.UTF8.GetBytes(string.Join('\n', chosen)));
        return Convert.ToHexStringLower(hash.GetHashAndReset());
    }

    private static void Copy(string from, string to)
    {
        foreach (string f in Directory.EnumerateFiles(from, "*", SearchOption.AllDirectories))
        {
            string target = Path.Combine(to, Path.GetRelativePath(from, f));
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Copy(f, target, overwrite: true);
        }
    }

    [GeneratedRegex(@", (\d+) probes")]
    private static partial Regex ProbeCount();
}
