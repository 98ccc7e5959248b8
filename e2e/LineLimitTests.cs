using System.Diagnostics;
using System.Text;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// Every line read from a protocol peer is bounded (issue 19): over the limit (1 MiB, <c>ACPHYS_MAX_LINE</c>) a clear
/// error naming the limit, never the payload echoed, never the whole line in memory.
/// </summary>
public sealed class LineLimitTests
{
    [Fact(DisplayName = "serve answers a 50 MB request line with a short error naming the limit, in bounded memory, and serves the next line")]
    public async Task ServeRefusesAHugeRequestLine()
    {
        using var process = Process.Start(Acphys.Info(["serve"], stdin: true))!;
        var peak = PeakMemory.Watch(process);
        var stdin = process.StandardInput.BaseStream;
        var writer = Task.Run(() =>
        {
            // A 50 MB op name, as the new user sent, then a valid hello.
            stdin.Write("{\"op\":\""u8);
            var chunk = Encoding.ASCII.GetBytes(new string('x', 1 << 20));
            for (int i = 0; i < 50; i++)
            {
                stdin.Write(chunk);
            }

            stdin.Write("\"}\n{\"op\":\"hello\",\"protocol\":1}\n"u8);
            stdin.Flush();
        });

        string? first = await process.StandardOutput.ReadLineAsync();
        string? second = await process.StandardOutput.ReadLineAsync();
        await writer;
        long duringMiB = PeakMemory.Now(process);
        process.StandardInput.Close();
        Assert.True(process.WaitForExit(30_000), "serve did not end at end of input");

        Assert.NotNull(first);
        Assert.Contains("longer than 1,048,576 bytes", first, StringComparison.Ordinal);
        Assert.Contains("ACPHYS_MAX_LINE", first, StringComparison.Ordinal);
        Assert.True(first.Length < 200, $"the error is {first.Length} characters long");
        Assert.StartsWith("{\"protocol\":1", second, StringComparison.Ordinal);
        long mib = Math.Max(duringMiB, peak.MiB());
        Assert.True(mib < 200, $"serve peaked at {mib} MiB for a 50 MB line");
    }

    [Fact(DisplayName = "ACPHYS_MAX_LINE sets the limit of serve: a line just over it is refused, one at it is read")]
    public void TheLimitIsConfigurable()
    {
        using var process = Process.Start(Acphys.Info(["serve"], new Dictionary<string, string> { ["ACPHYS_MAX_LINE"] = "40" }, stdin: true))!;
        string atLimit = "{\"op\":\"hello\",\"protocol\":1}".PadRight(40); // 40 bytes: read
        process.StandardInput.Write(atLimit + "\n" + atLimit + " \n");
        process.StandardInput.Close();
        string[] answers = process.StandardOutput.ReadToEnd().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.True(process.WaitForExit(30_000));
        Assert.Equal(2, answers.Length);
        Assert.StartsWith("{\"protocol\":1", answers[0], StringComparison.Ordinal);
        Assert.Contains("longer than 40 bytes", answers[1], StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A malformed ACPHYS_MAX_LINE is a usage error naming the variable")]
    public void AMalformedLimitIsAUsageError()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("garbage.sh"), "--only", "LCOORD-ROUNDTRIP", "--cases", "1"], new Dictionary<string, string> { ["ACPHYS_MAX_LINE"] = "lots" });
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("ACPHYS_MAX_LINE='lots'", run.Err, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "verify stops on a 100 MB answer line with an error naming the limit, in bounded memory")]
    public async Task VerifyRefusesAHugeAnswerLine()
    {
        using var process = Process.Start(Acphys.Info(["verify", "--impl-cmd", Acphys.Script("huge-answer.sh"), "--only", "LCOORD-ROUNDTRIP", "--cases", "1", "--timeout", "60"]))!;
        var peak = PeakMemory.Watch(process);
        var stdout = process.StandardOutput.ReadToEndAsync();
        string stderr = await process.StandardError.ReadToEndAsync();
        Assert.True(process.WaitForExit(120_000), "verify did not end");
        _ = await stdout;

        Assert.True(process.ExitCode == 2, $"exit {process.ExitCode}: {stderr}");
        Assert.Contains("answered 'hello' with a line longer than 1,048,576 bytes", stderr, StringComparison.Ordinal);
        Assert.True(stderr.Length < 2000, $"stderr is {stderr.Length} characters long");
        Assert.True(peak.MiB() < 250, $"verify peaked at {peak.MiB()} MiB for a 100 MB answer line");
    }
}
