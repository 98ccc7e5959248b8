using System.Text.RegularExpressions;
using AcPhys.Props.Support;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Meta;

/// <summary>
/// The tool's settings (issue 42, docs/architecture.md "Settings"): every <c>ACPHYS_*</c> variable the product reads is
/// read in spec's <see cref="ToolEnvironment"/>, once, and validated there.
/// </summary>
public sealed partial class SettingsTests
{
    // The product's projects (tests, examples and benchmarks excluded: a test may set up its own environment, an example
    // port has its own switches).
    private static readonly string[] Product = ["core", "contract", "formats", "protocol", "spec", "studies", "xunit", "cli", "fuzz/AcPhys.Fuzz", "fuzz/AcPhys.Fuzz.Targets"];

    [Fact(DisplayName = "SETTINGS-READ-ONCE: no product file but spec/Running/ToolEnvironment.cs reads an ACPHYS_ variable from the environment")]
    public void OnlyToolEnvironmentReadsTheVariables()
    {
        var readers = Product
            .SelectMany(p => Directory.EnumerateFiles(Path.Combine(RepoPaths.Root, p), "*.cs", SearchOption.AllDirectories))
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal)
                && !f.Contains($"{Path.DirectorySeparatorChar}bin{Path.DirectorySeparatorChar}", StringComparison.Ordinal))
            .Where(f => Path.GetFileName(f) != "ToolEnvironment.cs" && EnvironmentRead().IsMatch(File.ReadAllText(f)))
            .Select(f => Path.GetRelativePath(RepoPaths.Root, f))
            .ToList();
        Assert.True(readers.Count == 0, "reads an environment variable itself (take ToolEnvironment instead): " + string.Join(", ", readers));
    }

    [Fact(DisplayName = "SETTINGS-DEFAULTS: with nothing set every setting has its default and no variable has a problem")]
    public void NothingSetGivesTheDefaults()
    {
        var s = ToolEnvironment.From(new Dictionary<string, string>());
        Assert.Null(s.ProfileName);
        Assert.Null(s.Profile);
        Assert.Null(s.Seed);
        Assert.Null(s.FailureFolder);
        Assert.Equal("acphys", s.Command);
        Assert.Null(s.MaxLineBytes);
        Assert.Equal(TimeSpan.FromSeconds(30), s.ProgressInterval);
        Assert.Null(s.Width);
        Assert.False(s.Debug);
        Assert.False(s.WireProfile);
        Assert.Null(s.ImplTimeout);
        Assert.All(Variables, v => Assert.Null(s.Problem(v)));
    }

    [Fact(DisplayName = "SETTINGS-PARSED: well-formed values are taken as they are meant (profile, seed, numbers, switches)")]
    public void WellFormedValuesAreTaken()
    {
        var s = ToolEnvironment.From(new Dictionary<string, string>
        {
            [ToolEnvironment.ProfileVariable] = "nightly",
            [ToolEnvironment.SeedVariable] = "12,35",
            [ToolEnvironment.MaxLineVariable] = "4096",
            [ToolEnvironment.MinTestedVariable] = "3",
            [ToolEnvironment.ProgressSecondsVariable] = "1.5",
            [ToolEnvironment.WidthVariable] = "200",
            [ToolEnvironment.DebugVariable] = "true",
            [ToolEnvironment.WireProfileVariable] = "1",
            [ToolEnvironment.ImplTimeoutVariable] = "2.5",
            [ToolEnvironment.CommandVariable] = "./acphys",
            [ToolEnvironment.FailuresVariable] = "out/f",
        });
        Assert.Equal("nightly", s.Profile?.Name);
        Assert.True(Seed.TryParse("12,35", out var seed));
        Assert.Equal(seed, s.Seed);
        Assert.Equal(4096, s.MaxLineBytes);
        Assert.Equal(3, s.MinTested);
        Assert.Equal(TimeSpan.FromSeconds(1.5), s.ProgressInterval);
        Assert.Equal(200, s.Width);
        Assert.True(s.Debug && s.WireProfile);
        Assert.Equal(TimeSpan.FromSeconds(2.5), s.ImplTimeout);
        Assert.Equal(("./acphys", "out/f"), (s.Command, s.FailureFolder));
        Assert.All(Variables, v => Assert.Null(s.Problem(v)));
    }

    [Theory(DisplayName = "SETTINGS-VALIDATED: a malformed value is not guessed at: its setting is the default and the problem names the variable and the value")]
    [InlineData(ToolEnvironment.ProfileVariable, "weekly", "ACPHYS_PROFILE='weekly' is not a profile (pr, nightly)")]
    [InlineData(ToolEnvironment.SeedVariable, "12", "ACPHYS_SEED='12' is not seed,gamma[,size]")]
    [InlineData(ToolEnvironment.MaxLineVariable, "0", "ACPHYS_MAX_LINE='0': expected a number of bytes, 1 to 1073741824")]
    [InlineData(ToolEnvironment.MaxLineVariable, "1e3", "ACPHYS_MAX_LINE='1e3': expected a number of bytes, 1 to 1073741824")]
    [InlineData(ToolEnvironment.MinTestedVariable, "0", "ACPHYS_MIN_TESTED='0' must be a whole number from 1 to")]
    [InlineData(ToolEnvironment.ImplTimeoutVariable, "forever", "ACPHYS_IMPL_TIMEOUT: expected seconds from 0.1 to 3600, got 'forever'")]
    public void MalformedValueIsAProblem(string variable, string value, string problem)
    {
        var s = ToolEnvironment.From(new Dictionary<string, string> { [variable] = value });
        Assert.StartsWith(problem, s.Problem(variable), StringComparison.Ordinal);
        Assert.Null(s.Profile);
        Assert.Null(s.Seed);
        Assert.Null(s.MaxLineBytes);
        Assert.Null(s.MinTested);
        Assert.Null(s.ImplTimeout);
        Assert.All(Variables.Where(v => v != variable), v => Assert.Null(s.Problem(v)));
    }

    private static string[] Variables =>
    [
        ToolEnvironment.ProfileVariable, ToolEnvironment.SeedVariable, ToolEnvironment.MaxLineVariable, ToolEnvironment.MinTestedVariable,
        ToolEnvironment.ImplTimeoutVariable, ToolEnvironment.ProgressSecondsVariable, ToolEnvironment.WidthVariable,
    ];

    [GeneratedRegex(@"GetEnvironmentVariable\s*\((""ACPHYS_|[A-Za-z]*Variable\b)")]
    private static partial Regex EnvironmentRead();
}
