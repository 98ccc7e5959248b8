using AcPhys.Contract;

namespace AcPhys.Spec.Running;

/// <summary>
/// How many threads a catalogue run spreads its invariants over, and what each extra thread asks (issue 51: the pr gate
/// ran its invariants one after another on one of two cores). Every invariant's seed comes from its ID, never from the
/// order it runs in, so its result does not depend on the thread; the results are reported in catalogue order.
/// </summary>
/// <param name="Count">Threads, the caller's included; 1 runs the invariants one after another on the caller's thread.</param>
/// <param name="Instance">
/// Returns the implementation one extra thread asks for all its invariants: the caller's own instance when that is
/// stateless (the reference: its scratch array is per thread), else a fresh instance in the same mode (a planted fault
/// keeps a scratch array per instance). An implementation whose answers depend on the calls before them must run with 1.
/// </param>
internal sealed record CatalogueWorkers(int Count, Func<ICellPhysics>? Instance)
{
    /// <summary>Gets one thread: the sequential run.</summary>
    public static CatalogueWorkers One { get; } = new(1, null);

    /// <summary>Gets the thread count <c>auto</c> means: one per processor.</summary>
    public static int Auto => Math.Max(1, Environment.ProcessorCount);
}
