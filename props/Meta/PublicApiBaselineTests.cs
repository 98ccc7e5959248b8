using System.Text.RegularExpressions;
using AcPhys.Props.Support;

namespace AcPhys.Props.Meta;

/// <summary>
/// Issue 42: what ports compile against cannot drift. Every packed assembly holds a public API baseline, and
/// Directory.Build.targets turns the PublicApiAnalyzers on only where the file exists, so deleting a baseline would
/// silently switch the check off: this test is the guard.
/// </summary>
public sealed partial class PublicApiBaselineTests
{
    [Fact(DisplayName = "PUBLIC-API-BASELINED: every project packaging/pack.sh packs has a PublicAPI.Shipped.txt that declares symbols, and a PublicAPI.Unshipped.txt")]
    public void EveryPackedProjectHasABaseline()
    {
        string pack = File.ReadLines(Path.Combine(RepoPaths.Root, "packaging", "pack.sh")).Single(l => l.StartsWith("for project in ", StringComparison.Ordinal));
        var projects = PackedProject().Matches(pack).Select(m => m.Groups[1].Value).Distinct().ToArray();
        Assert.True(projects.Length >= 6, $"pack.sh lists {projects.Length} projects: {string.Join(", ", projects)}");
        var missing = new List<string>();
        foreach (string project in projects)
        {
            string dir = Path.GetDirectoryName(Path.Combine(RepoPaths.Root, project))!;
            string shipped = Path.Combine(dir, "PublicAPI.Shipped.txt");
            if (!File.Exists(shipped) || !File.Exists(Path.Combine(dir, "PublicAPI.Unshipped.txt")))
            {
                missing.Add($"{project}: no PublicAPI.Shipped.txt / PublicAPI.Unshipped.txt beside it");
                continue;
            }

            // The cli is a tool, not a library: its baseline may declare nothing (it has no public types), but it must exist.
            bool declares = File.ReadLines(shipped).Any(l => l.Length > 0 && !l.StartsWith('#'));
            if (!declares && !project.StartsWith("cli/", StringComparison.Ordinal))
            {
                missing.Add($"{project}: PublicAPI.Shipped.txt declares no symbol");
            }
        }

        Assert.True(missing.Count == 0, "packed projects without a public API baseline (packaging/publicapi-baseline.sh writes them):\n" + string.Join("\n", missing));
    }

    [GeneratedRegex(@"\b([a-z]+/AcPhys\.[A-Za-z.]+\.csproj)\b")]
    private static partial Regex PackedProject();
}
