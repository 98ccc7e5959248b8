using System.Globalization;
using AcPhys.Formats.Values;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>
/// The tool's <c>ACPHYS_*</c> settings, read from the environment once and validated (issue 42): the one place of the
/// product that reads them. The cli, the fuzz harness and AcPhys.Xunit take <see cref="Process"/> at start and pass
/// it down; nothing below them reads the environment. A malformed value is not guessed at: its typed value is the
/// default and <see cref="Problem"/> says what is wrong, so the user of the value reports it as today (the cli: exit 2;
/// the gate as xunit tests: a failing test) — and only when the value is used, so a stray variable does not stop a
/// command that never reads it.
/// </summary>
public sealed class ToolEnvironment
{
    /// <summary>The profile (<c>pr</c>, <c>nightly</c>, <c>mutation</c>); a command's <c>--profile</c> wins.</summary>
    public const string ProfileVariable = "ACPHYS_PROFILE";

    /// <summary>A seed (<c>seed,gamma[,size]</c>) replaying every invariant of the gate as xunit tests.</summary>
    public const string SeedVariable = "ACPHYS_SEED";

    /// <summary>The folder shrunk failing cases are written to (default <c>artifacts/failures</c>).</summary>
    public const string FailuresVariable = "ACPHYS_FAILURES";

    /// <summary>How replay lines invoke the tool (the <c>./acphys</c> wrapper sets its own path; default <c>acphys</c>).</summary>
    public const string CommandVariable = "ACPHYS_COMMAND";

    /// <summary>The fewest invariants the gate as xunit tests must test (AcPhys.Xunit's <c>GateFloor</c>).</summary>
    public const string MinTestedVariable = "ACPHYS_MIN_TESTED";

    /// <summary>The most bytes of one protocol v1 line (1 to 1 GiB; default the protocol's 1 MiB).</summary>
    public const string MaxLineVariable = "ACPHYS_MAX_LINE";

    /// <summary>Seconds between two progress lines in a log (0.1 to 86,400; default 30; a malformed value is the default, as ever).</summary>
    public const string ProgressSecondsVariable = "ACPHYS_PROGRESS_SECONDS";

    /// <summary>The width of redirected output (more than 20 columns; a malformed value is the default width, as ever).</summary>
    public const string WidthVariable = "ACPHYS_WIDTH";

    /// <summary><c>1</c> or <c>true</c>: an internal error prints its stack trace.</summary>
    public const string DebugVariable = "ACPHYS_DEBUG";

    /// <summary>A command that fails at once with an internal error (a drill of that path).</summary>
    public const string InternalErrorDrillVariable = "ACPHYS_INTERNAL_ERROR_DRILL";

    /// <summary><c>1</c>: the served path's stopwatch breakdown is printed at exit (docs/protocol.md, "Speed").</summary>
    public const string WireProfileVariable = "ACPHYS_WIRE_PROFILE";

    /// <summary>The fuzz harness's planted fault (unset or empty: the reference).</summary>
    public const string FaultVariable = "ACPHYS_FAULT";

    /// <summary>The fuzz harness's target when the command line names none.</summary>
    public const string FuzzTargetVariable = "ACPHYS_FUZZ_TARGET";

    /// <summary>The fuzz harness's adapter assembly (a port in process).</summary>
    public const string ImplVariable = "ACPHYS_IMPL";

    /// <summary>The fuzz harness's protocol v1 command line (a port in a child process).</summary>
    public const string ImplCommandVariable = "ACPHYS_IMPL_CMD";

    /// <summary>The fuzz harness's per-answer timeout of the child, seconds (0.1 to 3600).</summary>
    public const string ImplTimeoutVariable = "ACPHYS_IMPL_TIMEOUT";

    /// <summary>The fuzz harness's warm-up of an <c>--impl-cmd</c> child before afl-fuzz's clock, milliseconds (0 to 60000; 0: none).</summary>
    public const string FuzzWarmupVariable = "ACPHYS_FUZZ_WARMUP_MS";

    /// <summary>The warm-up budget when <see cref="FuzzWarmupVariable"/> is unset, milliseconds.</summary>
    public const int DefaultFuzzWarmupMs = 3000;

    private static readonly Lazy<ToolEnvironment> Read = new(() => new ToolEnvironment(Environment.GetEnvironmentVariable));

    private readonly Dictionary<string, string> problems = new(StringComparer.Ordinal);

    private ToolEnvironment(Func<string, string?> variable)
    {
        string? Text(string name) => variable(name) is { Length: > 0 } text ? text : null;

        ProfileName = Text(ProfileVariable);
        if (ProfileName is not null)
        {
            Profile = AcPhys.Spec.Running.Profile.Find(ProfileName);
            Note(Profile is null, ProfileVariable, $"{ProfileVariable}='{ProfileName}' is not a profile (pr, nightly)");
        }

        if (Text(SeedVariable) is { } seed)
        {
            Note(!AcPhys.Spec.Running.Seed.TryParse(seed, out var parsed), SeedVariable, $"{SeedVariable}='{seed}' is not seed,gamma[,size]");
            Seed = problems.ContainsKey(SeedVariable) ? null : parsed;
        }

        FailureFolder = Text(FailuresVariable);
        Command = Text(CommandVariable) ?? "acphys";
        if (Text(MinTestedVariable) is { } floor)
        {
            bool ok = int.TryParse(floor, out int n) && n >= 1 && n <= InvariantCatalogue.All.Count;
            Note(!ok, MinTestedVariable, $"{MinTestedVariable}='{floor}' must be a whole number from 1 to {InvariantCatalogue.All.Count} (the catalogue's invariants)");
            MinTested = ok ? n : null;
        }

        if (Text(MaxLineVariable) is { } line)
        {
            bool ok = int.TryParse(line, NumberStyles.None, CultureInfo.InvariantCulture, out int bytes) && bytes is >= 1 and <= 1 << 30;
            Note(!ok, MaxLineVariable, $"{MaxLineVariable}='{InputQuote.Brief(line)}': expected a number of bytes, 1 to 1073741824");
            MaxLineBytes = ok ? bytes : null;
        }

        ProgressInterval = double.TryParse(Text(ProgressSecondsVariable), NumberStyles.Float, CultureInfo.InvariantCulture, out double s) && s is >= 0.1 and <= 86_400
            ? TimeSpan.FromSeconds(s)
            : TimeSpan.FromSeconds(30);
        Width = int.TryParse(Text(WidthVariable), out int w) && w > 20 ? w : null;
        Debug = Text(DebugVariable) is "1" or "true";
        InternalErrorDrill = Text(InternalErrorDrillVariable);
        WireProfile = Text(WireProfileVariable) == "1";
        Fault = Text(FaultVariable);
        FuzzTarget = Text(FuzzTargetVariable);
        Impl = Text(ImplVariable);
        ImplCommand = Text(ImplCommandVariable);
        if (Text(ImplTimeoutVariable) is { } timeout)
        {
            bool ok = double.TryParse(timeout, NumberStyles.Float, CultureInfo.InvariantCulture, out double t) && t is >= 0.1 and <= 3600;
            Note(!ok, ImplTimeoutVariable, $"{ImplTimeoutVariable}: expected seconds from 0.1 to 3600, got '{InputQuote.Line(timeout, 40)}'");
            ImplTimeout = ok ? TimeSpan.FromSeconds(t) : null;
        }

        FuzzWarmup = TimeSpan.FromMilliseconds(DefaultFuzzWarmupMs);
        if (Text(FuzzWarmupVariable) is { } warmup)
        {
            bool ok = int.TryParse(warmup, NumberStyles.None, CultureInfo.InvariantCulture, out int ms) && ms <= 60_000;
            Note(!ok, FuzzWarmupVariable, $"{FuzzWarmupVariable}: expected milliseconds from 0 to 60000, got '{InputQuote.Line(warmup, 40)}'");
            FuzzWarmup = ok ? TimeSpan.FromMilliseconds(ms) : null;
        }
    }

    /// <summary>Gets the settings of this process, read from its environment at first use (once).</summary>
    public static ToolEnvironment Process => Read.Value;

    /// <summary>Gets the profile name as set, or null when unset (validated by the command that takes it: a <c>--profile</c> wins).</summary>
    public string? ProfileName { get; }

    /// <summary>Gets the profile named, or null when unset or unknown (then <see cref="Problem"/> says so).</summary>
    public Profile? Profile { get; }

    /// <summary>Gets the fixed seed, or null when unset or malformed.</summary>
    public Seed? Seed { get; }

    /// <summary>Gets the failure folder as set, or null when unset.</summary>
    public string? FailureFolder { get; }

    /// <summary>Gets how replay lines invoke the tool.</summary>
    public string Command { get; }

    /// <summary>Gets the gate's floor of tested invariants, or null when unset or malformed.</summary>
    public int? MinTested { get; }

    /// <summary>Gets the protocol line limit in bytes, or null when unset or malformed (the protocol's default then).</summary>
    public int? MaxLineBytes { get; }

    /// <summary>Gets the interval between two progress lines of a log.</summary>
    public TimeSpan ProgressInterval { get; }

    /// <summary>Gets the width of redirected output, or null for the default.</summary>
    public int? Width { get; }

    /// <summary>Gets a value indicating whether an internal error prints its stack trace.</summary>
    public bool Debug { get; }

    /// <summary>Gets the command the internal-error drill fails, or null.</summary>
    public string? InternalErrorDrill { get; }

    /// <summary>Gets a value indicating whether the served path's stopwatch breakdown is on.</summary>
    public bool WireProfile { get; }

    /// <summary>Gets the fuzz harness's planted fault, or null for the reference.</summary>
    public string? Fault { get; }

    /// <summary>Gets the fuzz harness's target, or null.</summary>
    public string? FuzzTarget { get; }

    /// <summary>Gets the fuzz harness's adapter assembly, or null.</summary>
    public string? Impl { get; }

    /// <summary>Gets the fuzz harness's protocol v1 command line, or null.</summary>
    public string? ImplCommand { get; }

    /// <summary>Gets the fuzz harness's per-answer timeout, or null when unset or malformed.</summary>
    public TimeSpan? ImplTimeout { get; }

    /// <summary>Gets the fuzz harness's warm-up budget of an <c>--impl-cmd</c> child (the default when unset), or null when malformed.</summary>
    public TimeSpan? FuzzWarmup { get; }

    /// <summary>Returns the settings a set of variables gives (tests; a variable absent from the map is unset).</summary>
    /// <param name="variables">Name → value.</param>
    /// <returns>The settings.</returns>
    public static ToolEnvironment From(IReadOnlyDictionary<string, string> variables)
    {
        ArgumentNullException.ThrowIfNull(variables);
        return new ToolEnvironment(name => variables.TryGetValue(name, out string? value) ? value : null);
    }

    /// <summary>Says what is wrong with a variable's value, or null when it is unset or well-formed.</summary>
    /// <param name="variable">One of this type's <c>*Variable</c> names.</param>
    /// <returns>The problem, naming the variable and its value, or null.</returns>
    public string? Problem(string variable) => problems.GetValueOrDefault(variable);

    private void Note(bool bad, string variable, string problem)
    {
        if (bad)
        {
            problems[variable] = problem;
        }
    }
}
