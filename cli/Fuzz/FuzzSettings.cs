using AcPhys.Cli.Impl;
using AcPhys.Fuzz.Targets;

namespace AcPhys.Cli.Fuzz;

/// <summary>What one <c>acphys fuzz</c> campaign does.</summary>
/// <param name="Root">The checkout.</param>
/// <param name="Target">The fuzz target.</param>
/// <param name="Fault">The planted fault, or null for the correct core.</param>
/// <param name="Seconds">How long afl-fuzz fuzzes (afl-fuzz -V).</param>
/// <param name="Jobs">afl-fuzz instances: one -M main and Jobs − 1 -S secondaries on one sync folder.</param>
/// <param name="TimeoutMs">afl-fuzz -t.</param>
/// <param name="CampaignDir">The campaign folder (build-independent; kept between runs so the next run resumes).</param>
/// <param name="RegressionsDir">Where triage writes minimised regressions.</param>
/// <param name="SeedCorpusDir">The target's growing seed corpus (corpus/fuzz/TARGET).</param>
internal sealed record FuzzSettings(
    string Root,
    FuzzTarget Target,
    string? Fault,
    int Seconds,
    int Jobs,
    int TimeoutMs,
    string CampaignDir,
    string RegressionsDir,
    string SeedCorpusDir)
{
    private readonly string? buildDir;

    /// <summary>Gets the port under test (<c>--impl</c> / <c>--impl-cmd</c>), or <see cref="ImplementationChoice.Reference"/> for the bundled reference.</summary>
    public ImplementationChoice Port { get; init; } = ImplementationChoice.Reference;

    /// <summary>Gets the assemblies of an <c>--impl</c> port to instrument (file names in the adapter's folder); empty: the default (<see cref="PortCopy"/>).</summary>
    public IReadOnlyList<string> Instrument { get; init; } = [];

    /// <summary>Gets the most one case of an in-process port may take outside afl-fuzz (seeds, triage, minimising; a hang's replay child): 5× afl-fuzz's -t, at least 5 s.</summary>
    public TimeSpan PortCaseLimit => TimeSpan.FromMilliseconds(Math.Max(5000, 5L * TimeoutMs));

    /// <summary>Gets the folder holding the instrumented copy of an <c>--impl</c> port (inside the campaign folder, refreshed when the port changes).</summary>
    public string PortDir => Path.Combine(CampaignDir, "port");

    /// <summary>Gets the copy of the adapter assembly the harness loads under afl-fuzz.</summary>
    public string PortAssembly => Path.Combine(PortDir, Path.GetFileName(Port.AssemblyPath ?? "none.dll"));

    /// <summary>Gets a value indicating whether the harness build instruments the suite's own assemblies (not for an <c>--impl</c> port: afl is guided by the port's branches alone).</summary>
    public bool InstrumentsOurs => Port.AssemblyPath is null;

    /// <summary>Gets how reports name the implementation under test.</summary>
    public string Subject => Port.Command is { } c ? "--impl-cmd " + AcPhys.Formats.Values.InputQuote.Line(c, 80) : Port.AssemblyPath is { } a ? "--impl " + a : Fault is null ? "correct core" : "fault " + Fault;

    /// <summary>Gets a value indicating whether only the summary is printed (CI).</summary>
    public bool Quiet { get; init; }

    /// <summary>Gets a value indicating whether the campaign's previous queue and findings are wiped first.</summary>
    public bool Fresh { get; init; }

    /// <summary>Gets a value indicating whether the campaign stops at the first crash (time-to-first-crash measurements).</summary>
    public bool UntilCrash { get; init; }

    /// <summary>Gets a value indicating whether an existing instrumented build is reused as it is.</summary>
    public bool NoBuild { get; init; }

    /// <summary>Gets a value indicating whether afl-fuzz is skipped: only triage (and seed-corpus growth) of what the sync folder holds.</summary>
    public bool TriageOnly { get; init; }

    /// <summary>Gets the sync folder (afl-fuzz -o).</summary>
    public string SyncDir => Path.Combine(CampaignDir, "sync");

    /// <summary>Gets the folder of logs.</summary>
    public string LogDir => Path.Combine(CampaignDir, "logs");

    /// <summary>Gets the instrumented build (shared by campaigns: <c>.fuzz/build</c> unless <c>--build-dir</c> names another).</summary>
    public string BuildDir
    {
        get => buildDir ?? Path.Combine(Root, ".fuzz", "build");
        init => buildDir = value;
    }

    /// <summary>Gets the harness executable.</summary>
    public string Harness => Path.Combine(BuildDir, "harness", "AcPhys.Fuzz");

    /// <summary>Gets the name of an instance: main, sec1, sec2, …</summary>
    /// <param name="i">Index.</param>
    /// <returns>The name.</returns>
    public static string InstanceName(int i) => i == 0 ? "main" : $"sec{i}";
}
