using System.Text.RegularExpressions;
using System.Xml.Linq;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The header of a walk picture is honest (issue 19): it names every invariant the walk breaks (as replay reports them),
/// not only those of the first violating step, and long lines wrap instead of being cut with "…".
/// </summary>
public sealed partial class WalkPictureHeaderTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact(DisplayName = "render's header names every invariant replay reports violated, and cuts no line")]
    public void TheHeaderNamesEveryBrokenInvariantAndWraps()
    {
        string file = Path.Combine(RepoPaths.Root, "docs", "examples", "clamp-106.walk.json");
        var replay = Acphys.Run(["replay", file, "--fault", "clamp-106"]);
        var broken = Violated().Matches(replay.Out).Select(m => m.Groups[1].Value).ToHashSet(StringComparer.Ordinal);
        Assert.True(broken.Count >= 2, replay.ToString()); // the example breaks more than the one its title names

        string svg = Path.Combine(Path.GetTempPath(), $"acphys-header-{Environment.ProcessId}.svg");
        var render = Acphys.Run(["render", file, "--fault", "clamp-106", "-o", svg]);
        Assert.True(render.Exit == 0, render.ToString());
        var texts = XDocument.Load(svg).Descendants(Svg + "text").ToList();
        File.Delete(svg);

        string headline = string.Join(' ', texts.Where(t => (string?)t.Attribute("class") == "headline").Select(t => t.Value));
        foreach (string id in broken)
        {
            Assert.Contains(id, headline, StringComparison.Ordinal);
        }

        string title = string.Join(' ', texts.Where(t => (string?)t.Attribute("class") == "title").Select(t => t.Value));
        Assert.Contains("current stays 0xB0F10001", title, StringComparison.Ordinal); // the end of the file's title, once cut
        Assert.DoesNotContain(texts, t => t.Value.Contains('…', StringComparison.Ordinal));
    }

    [GeneratedRegex(@"VIOLATED ([A-Z0-9-]+):")]
    private static partial Regex Violated();
}
