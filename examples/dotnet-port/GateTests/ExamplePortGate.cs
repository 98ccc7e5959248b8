using AcPhys.Xunit;

namespace ExamplePort.GateTests;

/// <summary>The PR gate of the example port: one test per invariant ID (AcPhys.Xunit).</summary>
public sealed class ExamplePortGate : GateTests<ExamplePort>
{
}
