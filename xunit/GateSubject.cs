using System.Collections.Concurrent;
using AcPhys.Contract;

namespace AcPhys.Xunit;

/// <summary>One adapter instance per adapter type for the whole test run, as <c>acphys verify</c> loads one, and its verdicts.</summary>
/// <typeparam name="TAdapter">The adapter.</typeparam>
internal static class GateSubject<TAdapter>
    where TAdapter : ICellPhysics, new()
{
    private static readonly Lazy<TAdapter> Instance = new(() => new TAdapter());

    // One run per invariant per test run: the floor test counts the verdicts the rows reached (or reaches them first).
    private static readonly ConcurrentDictionary<string, Lazy<GateVerdict>> Verdicts = new(StringComparer.Ordinal);

    /// <summary>Gets the adapter.</summary>
    public static TAdapter Adapter => Instance.Value;

    /// <summary>Gets the verdict of one invariant on the adapter, run once (<see cref="Gate.Check"/>).</summary>
    /// <param name="invariant">The invariant ID.</param>
    /// <returns>The verdict.</returns>
    public static GateVerdict Verdict(string invariant) => Verdicts.GetOrAdd(invariant, id => new Lazy<GateVerdict>(() => Gate.Check(Adapter, id))).Value;
}
