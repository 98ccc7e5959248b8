using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// What a bug of the tool looks like (issue 19 item 3): to a user one line and its own exit code (70), never a stack
/// trace; to a developer with <c>ACPHYS_DEBUG=1</c> the stack trace. The drill variable makes a command fail inside.
/// </summary>
public sealed class InternalErrorTests
{
    private const string Drill = "ACPHYS_INTERNAL_ERROR_DRILL";

    [Fact(DisplayName = "An internal error is one line on stderr and exit 70, without a stack trace")]
    public void AUserSeesOneLineAndItsOwnExitCode()
    {
        var run = Acphys.Run(["faults"], new Dictionary<string, string> { [Drill] = "faults" });
        Assert.True(run.Exit == 70, run.ToString());
        string[] lines = run.Err.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Single(lines);
        Assert.StartsWith("acphys faults: internal error: InvalidOperationException: internal error drill", lines[0], StringComparison.Ordinal);
        Assert.Contains("set ACPHYS_DEBUG=1", lines[0], StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal);
        Assert.Empty(run.Out);
    }

    [Fact(DisplayName = "With ACPHYS_DEBUG=1 an internal error shows its stack trace")]
    public void ADeveloperSeesTheStackTrace()
    {
        var run = Acphys.Run(["faults"], new Dictionary<string, string> { [Drill] = "faults", ["ACPHYS_DEBUG"] = "1" });
        Assert.True(run.Exit == 70, run.ToString());
        Assert.Contains("System.InvalidOperationException: internal error drill", run.Err, StringComparison.Ordinal);
        Assert.Contains("   at AcPhys.Cli.InternalErrorDrill.Check", run.Err, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "Bad input is still exit 2, distinct from an internal error")]
    public void BadInputIsNotAnInternalError()
    {
        var run = Acphys.Run(["replay", Path.Combine(Path.GetTempPath(), "acphys-no-such-file.json")]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.DoesNotContain("internal error", run.Err, StringComparison.Ordinal);
    }
}
