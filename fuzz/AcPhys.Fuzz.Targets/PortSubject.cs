using AcPhys.Contract;
using AcPhys.Protocol.Client;
using AcPhys.Protocol.Messages;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Running;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// A port as a fuzz <see cref="Subject"/>, the same way for the harness (from its environment) and for
/// <c>acphys fuzz</c>'s seeds and triage: an <c>--impl</c> assembly through the gate's loader
/// (<see cref="AdapterAssembly"/>), or an <c>--impl-cmd</c> child through the gate's <see cref="ProcessAdapter"/>
/// (timeout, line limit, process group, hostile answers all as in <c>acphys verify</c>).
/// </summary>
public static class PortSubject
{
    /// <summary>The harness's variable naming an adapter assembly (an instrumented copy, under afl-fuzz).</summary>
    public const string ImplVariable = ToolEnvironment.ImplVariable;

    /// <summary>The harness's variable holding a protocol v1 command line.</summary>
    public const string CommandVariable = ToolEnvironment.ImplCommandVariable;

    /// <summary>The harness's variable holding the per-answer timeout of the child, in seconds.</summary>
    public const string TimeoutVariable = ToolEnvironment.ImplTimeoutVariable;

    /// <summary>Returns an in-process port: a new adapter instance wherever the reference would get a fresh one.</summary>
    /// <param name="path">The adapter assembly.</param>
    /// <param name="opening">Called before each new instance is made (one per case): acphys's watch on a port that hangs outside afl-fuzz.</param>
    /// <returns>The subject.</returns>
    /// <exception cref="AdapterLoadException">The assembly holds no usable adapter.</exception>
    public static Subject InProcess(string path, Action? opening = null)
    {
        var assembly = AdapterAssembly.Load(path);
        var first = assembly.Create();
        string label = $"--impl {Path.GetFileName(path)} ({AcPhys.Formats.Values.InputQuote.Line(first.Name ?? assembly.TypeName, 60)})";
        return opening is null
            ? Subject.External(label, assembly.Create, freshEach: true)
            : Subject.External(label, () => { opening(); return assembly.Create(); }, freshEach: true);
    }

    /// <summary>Returns a port over protocol v1: one child, started at first use and again after it failed.</summary>
    /// <param name="commandLine">The command line.</param>
    /// <param name="timeout">The most one answer may take.</param>
    /// <param name="maxLineBytes">The most bytes of one answer line.</param>
    /// <param name="stderrSink">Where the child's stderr lines go (null: kept for messages only).</param>
    /// <returns>The subject.</returns>
    public static Subject Served(string commandLine, TimeSpan timeout, int maxLineBytes, Action<string>? stderrSink) =>
        Subject.External(
            "--impl-cmd " + AcPhys.Formats.Values.InputQuote.Line(commandLine, 80),
            () => ProcessAdapter.Start(commandLine, new ProcessAdapterOptions { Timeout = timeout, MaxLineBytes = maxLineBytes, StderrSink = stderrSink }),
            freshEach: false);

    /// <summary>Reads the harness's settings (its environment, read once): a port, or null for the reference (and its planted faults).</summary>
    /// <param name="settings">The settings.</param>
    /// <returns>The subject, or null.</returns>
    /// <exception cref="ArgumentException">Both variables are set, or the timeout or line limit is malformed.</exception>
    /// <exception cref="AdapterLoadException">The assembly holds no usable adapter.</exception>
    public static Subject? FromEnvironment(ToolEnvironment settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        string? dll = settings.Impl;
        string? cmd = settings.ImplCommand;
        if (dll is not null && cmd is not null)
        {
            throw new ArgumentException($"{ImplVariable} and {CommandVariable} exclude each other");
        }

        if (dll is not null)
        {
            return InProcess(dll);
        }

        if (cmd is null)
        {
            return null;
        }

        if ((settings.Problem(TimeoutVariable) ?? settings.Problem(ToolEnvironment.MaxLineVariable)) is { } problem)
        {
            throw new ArgumentException(problem);
        }

        return Served(cmd, settings.ImplTimeout ?? ProcessAdapterOptions.DefaultTimeout, LineLimit.OrDefault(settings.MaxLineBytes), null);
    }

    /// <summary>Says why a target cannot fuzz a port (a parser target, or none of its invariants testable for it), or null.</summary>
    /// <param name="target">The target.</param>
    /// <param name="subject">The subject.</param>
    /// <returns>The reason, or null.</returns>
    /// <exception cref="AdapterFailureException">A child could not be started.</exception>
    public static string? Refusal(FuzzTarget target, Subject subject)
    {
        ArgumentNullException.ThrowIfNull(target);
        ArgumentNullException.ThrowIfNull(subject);
        if (!subject.IsExternal)
        {
            return null;
        }

        return target.WhyNotFuzzable(subject.Shared());
    }
}
