using AcPhys.Xunit;

namespace ExamplePort.GateTests;

/// <summary>The PR gate of the example port: one test per invariant ID (AcPhys.Xunit).</summary>
public sealed class ExamplePortGate : GateTests<ExamplePort>
{
    /// <summary>Gets the floor: the 23 invariants the port's eight operations reach today, so an operation it stops announcing fails the gate.</summary>
    protected override int MinTested => 23;
}
