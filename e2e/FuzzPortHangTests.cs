using System.Diagnostics;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// <c>acphys fuzz --impl</c> when the in-process port hangs outside afl-fuzz (issue 40): seeds, triage and minimising
/// run the port in acphys, where a thread that never returns cannot be stopped. Each case is bounded by the campaign's
/// limit (5× <c>--timeout-ms</c>, at least 5 s): a hang is HANG, exit 6, never a hung acphys.
/// </summary>
public sealed class FuzzPortHangTests : IDisposable
{
    private const string HangInput = "0001ac2b4a"; // land: mode 0, cell 0x4A2BAC01 (the example port's hang bug), the rest zero

    private readonly string work = Path.Combine(Path.GetTempPath(), "acphys-fuzz-hang-" + Guid.NewGuid().ToString("N"));

    [Fact(DisplayName = "fuzz --impl: a seed that hangs the in-process port stops the campaign with HANG and exit 6 within the limit, naming the seed and the limit; it is written to hangs/ with its replay line, and no acphys is left behind")]
    public async Task SeedThatHangsThePortIsAHangNotAHungCampaign()
    {
        // A checkout of its own (what RepoRoot looks for) whose land seed corpus holds the input the port hangs on.
        string checkout = Path.Combine(work, "checkout");
        Directory.CreateDirectory(Path.Combine(checkout, "fuzz"));
        File.WriteAllText(Path.Combine(checkout, "AcPhysVerify.sln"), string.Empty);
        string seeds = Path.Combine(checkout, "corpus", "fuzz", "land");
        Directory.CreateDirectory(seeds);
        File.WriteAllBytes(Path.Combine(seeds, "hangs-the-port"), Convert.FromHexString(HangInput));
        string regressions = Path.Combine(work, "regressions");
        Directory.CreateDirectory(Path.Combine(work, "campaign", "sync", "main", "crashes")); // a campaign with nothing to triage: only the seeds run the port

        var info = Acphys.Info(
            ["fuzz", "--target", "land", "--impl", GateTestRun.ExamplePortDll, "--triage-only", "--campaign", Path.Combine(work, "campaign"), "--regressions", regressions, "--quiet"],
            new Dictionary<string, string> { ["ACPHYS_PORT_BUG"] = "hang" });
        info.WorkingDirectory = checkout;
        var stopwatch = Stopwatch.StartNew();
        using var process = Process.Start(info)!;
        var stdout = process.StandardOutput.ReadToEndAsync();
        var stderr = process.StandardError.ReadToEndAsync();
        using (var limit = new CancellationTokenSource(TimeSpan.FromSeconds(50)))
        {
            try
            {
                await process.WaitForExitAsync(limit.Token);
            }
            catch (OperationCanceledException)
            {
                process.Kill(entireProcessTree: true);
                Assert.Fail("acphys fuzz hung on a seed that hangs the port (killed after 50 s)");
            }
        }

        var run = new Run(process.ExitCode, await stdout, await stderr, stopwatch.Elapsed);
        Assert.True(run.Exit == 6, run.ToString());
        Assert.Contains("HANG: the port did not return within 5 s on seed corpus/fuzz/land/hangs-the-port", run.Err, StringComparison.Ordinal);
        string file = Assert.Single(Directory.GetFiles(Path.Combine(regressions, "hangs"), "land-HANG-*.json"));
        Assert.Contains($"replay: acphys replay {file} --impl {GateTestRun.ExamplePortDll}", run.Out, StringComparison.Ordinal);
        Assert.Contains("did not return from inbound_valid_cellid", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain(OtherProcesses(), cmd => cmd.Contains(work, StringComparison.Ordinal)); // the replay child is gone too
    }

    public void Dispose()
    {
        if (Directory.Exists(work))
        {
            Directory.Delete(work, recursive: true);
        }
    }

    // The command lines of the machine's processes but this one.
    private static List<string> OtherProcesses()
    {
        var lines = new List<string>();
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (int.TryParse(Path.GetFileName(dir), out int pid) && pid != Environment.ProcessId)
            {
                try
                {
                    lines.Add(File.ReadAllText(Path.Combine(dir, "cmdline")).Replace('\0', ' '));
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    // the process ended meanwhile
                }
            }
        }

        return lines;
    }
}
