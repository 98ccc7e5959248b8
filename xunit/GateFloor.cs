using AcPhys.Spec.Running;

namespace AcPhys.Xunit;

/// <summary>
/// The fewest invariants a port's gate must test to pass, as <c>acphys verify --min-tested</c>: a port that stops
/// announcing an operation turns invariants into NOT TESTED (skipped rows), which would otherwise still pass.
/// </summary>
public static class GateFloor
{
    /// <summary>The environment variable that sets the floor for a run (it wins over the class's own).</summary>
    public const string Variable = ToolEnvironment.MinTestedVariable;

    /// <summary>Gets the floor <see cref="Variable"/> sets, or null when it is unset.</summary>
    /// <returns>The floor, or null.</returns>
    /// <exception cref="InvalidOperationException">The value is not a whole number from 1 to the catalogue's size.</exception>
    public static int? FromEnvironment() =>
        ToolEnvironment.Process.Problem(Variable) is { } problem ? throw new InvalidOperationException(problem) : ToolEnvironment.Process.MinTested;
}
