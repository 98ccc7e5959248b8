using AcPhys.Contract;
using AcPhys.Spec.Faults;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The implementation a physics campaign fuzzes: the reference, the reference with a planted fault, or a port (an
/// <c>--impl</c> assembly in process or an <c>--impl-cmd</c> child over protocol v1). A port's campaign is judged by the
/// gate's oracle (the catalogue through <see cref="AcPhys.Spec.Judging.Judges"/>: conformance in the modes the port
/// declares, invariants needing ops it lacks not tested) and its findings must hold on the reference.
/// </summary>
public sealed class Subject : IDisposable
{
    private readonly Func<ICellPhysics> open;
    private readonly bool freshEach;
    private ICellPhysics? shared;

    private Subject(string label, string? fault, bool external, Func<ICellPhysics> open, bool freshEach)
    {
        Label = label;
        Fault = fault;
        IsExternal = external;
        this.open = open;
        this.freshEach = freshEach;
    }

    /// <summary>Gets the correct core.</summary>
    public static Subject Reference { get; } = new("correct core", null, false, () => ReferenceAdapter.Instance, false);

    /// <summary>Gets how a report names it: "correct core", "fault F", or the port's label.</summary>
    public string Label { get; }

    /// <summary>Gets the planted fault, or null.</summary>
    public string? Fault { get; }

    /// <summary>Gets a value indicating whether this is a port (not the bundled reference, with or without a fault).</summary>
    public bool IsExternal { get; }

    /// <summary>Returns the reference, or the reference with a planted fault.</summary>
    /// <param name="fault">The fault id, or null.</param>
    /// <returns>The subject.</returns>
    /// <exception cref="ArgumentException">Unknown fault.</exception>
    public static Subject Of(string? fault)
    {
        if (fault is null)
        {
            return Reference;
        }

        _ = PlantedFaults.Create(fault); // an unknown fault is rejected now, not at the first input
        return new Subject("fault " + fault, fault, false, () => PlantedFaults.Create(fault), true);
    }

    /// <summary>Returns a port.</summary>
    /// <param name="label">How reports name it.</param>
    /// <param name="open">Opens it (a new adapter instance, or a new child process).</param>
    /// <param name="freshEach">Whether <see cref="Fresh"/> may open a new one (cheap in process); false for a child, which lives for the campaign.</param>
    /// <returns>The subject.</returns>
    public static Subject External(string label, Func<ICellPhysics> open, bool freshEach) => new(label, null, true, open, freshEach);

    /// <summary>Returns the long-lived implementation, opening it on first use (again after <see cref="Discard"/>).</summary>
    /// <returns>The implementation.</returns>
    public ICellPhysics Shared() => shared ??= open();

    /// <summary>
    /// Returns an implementation with no earlier input's state: a new one where that is cheap (the reference with a
    /// fault, an in-process adapter), else the long-lived one (a child process: one per campaign, restarted by
    /// <see cref="Discard"/> after it failed).
    /// </summary>
    /// <returns>The implementation.</returns>
    public ICellPhysics Fresh() => freshEach ? open() : Shared();

    /// <summary>Drops the long-lived implementation (a child that crashed, hung or answered garbage is ended); the next use opens a new one.</summary>
    public void Discard()
    {
        var old = shared;
        shared = null;
        (old as IDisposable)?.Dispose();
    }

    /// <inheritdoc/>
    public void Dispose() => Discard();
}
