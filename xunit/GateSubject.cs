using AcPhys.Spec.Adapters;

namespace AcPhys.Xunit;

/// <summary>One adapter instance per adapter type for the whole test run, as <c>acphys verify</c> loads one.</summary>
/// <typeparam name="TAdapter">The adapter.</typeparam>
internal static class GateSubject<TAdapter>
    where TAdapter : ICellPhysics, new()
{
    private static readonly Lazy<TAdapter> Instance = new(() => new TAdapter());

    /// <summary>Gets the adapter.</summary>
    public static TAdapter Adapter => Instance.Value;
}
