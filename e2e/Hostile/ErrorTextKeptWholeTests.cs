using AcPhys.E2E.Support;

namespace AcPhys.E2E.Hostile;

/// <summary>
/// Issue #29 item 8: an implementation's error text (a port's crash with its stack) is a finding a maintainer must
/// read whole — kept whole in the failure file, the JUnit report and the markdown summary, cut only on the console.
/// </summary>
public sealed class ErrorTextKeptWholeTests
{
    private const int Frames = 60;

    [Fact]
    public void APortsStackTraceIsKeptWholeInEveryReportButTheConsoleLine()
    {
        // 60 frames, about 4,500 characters: far past every console cut, and each frame a distinct line number.
        string stack = "System.NullReferenceException: Object reference not set\\n"
            + string.Concat(Enumerable.Range(0, Frames).Select(i => $"   at Port.Cells.Frame{i}.Walk(Int32 depth) in /src/port/Cells.cs:line {1000 + i}\\n"))
            + "END-OF-STACK";
        string impl = HostileFiles.Script($$"""
            read l
            printf '%s\n' '{"protocol":1,"name":"stacky","ops":["blockid_to_lcoord","gid_to_lcoord","lcoord_to_gid","inbound_valid_cellid","get_outside_lcoord","adjust_to_outside"]}'
            while read l; do printf '%s\n' '{"error":"{{stack}}"}'; done
            """);
        string dir = HostileFiles.Temp();
        string junit = Path.Combine(dir, "j.xml"), markdown = Path.Combine(dir, "m.md"), failures = Path.Combine(dir, "failures");
        var run = Acphys.Run(
            ["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--max-classes", "1", "--junit", junit, "--markdown", markdown],
            new Dictionary<string, string> { ["ACPHYS_FAILURES"] = failures });
        Assert.True(run.Exit == 1, run.ToString());
        string failureFile = Assert.Single(Directory.GetFiles(failures, "ADJUST-RANGE-*.json"));
        foreach (var (name, text) in new[] { ("failure file", File.ReadAllText(failureFile)), ("JUnit", File.ReadAllText(junit)), ("markdown", File.ReadAllText(markdown)) })
        {
            Assert.True(Enumerable.Range(0, Frames).All(i => text.Contains($"Cells.cs:line {1000 + i}", StringComparison.Ordinal)), $"{name} lost frames of the port's stack:\n{text}");
            Assert.Contains("END-OF-STACK", text, StringComparison.Ordinal);
        }

        Assert.Contains("Cells.cs:line 1000", run.Out, StringComparison.Ordinal); // the console names the error …
        Assert.DoesNotContain("END-OF-STACK", run.Out, StringComparison.Ordinal); // … and cuts it
    }
}
