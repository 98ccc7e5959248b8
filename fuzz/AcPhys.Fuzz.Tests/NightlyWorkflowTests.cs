using System.Text.RegularExpressions;
using AcPhys.Fuzz.Targets;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>The nightly fuzz workflow runs a campaign for every physics and parser target the registry knows.</summary>
public sealed partial class NightlyWorkflowTests
{
    [Fact]
    public void Nightly_matrix_lists_every_physics_and_parser_target_once()
    {
        string yaml = File.ReadAllText(Path.Combine(RepoPaths.Root, ".github", "workflows", "nightly-fuzz.yml"));
        var listed = MatrixRow().Matches(yaml).Select(m => m.Groups[1].Value).ToList();
        var expected = FuzzTargets.All.Where(t => t.Kind != TargetKind.Smoke).Select(t => t.Name).Order().ToList();

        Assert.Equal(expected, listed.Order().ToList());
        Assert.Contains("serve-request", listed);
        Assert.Contains("scene-json", listed);
    }

    [GeneratedRegex(@"-\s*\{\s*target:\s*([a-z-]+)\s*,\s*jobs:\s*\d+\s*\}")]
    private static partial Regex MatrixRow();
}
