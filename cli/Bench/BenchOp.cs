namespace AcPhys.Cli.Bench;

/// <summary>One timed operation: a name, the arithmetic mode, whether it is a hot path (must not allocate), and a loop body.</summary>
/// <param name="Group">LandDefs, outdoor set or find_cell_list.</param>
/// <param name="Name">What one iteration does.</param>
/// <param name="Mode">float32 (retail) or double (reference).</param>
/// <param name="Hot">True when it must be 0 B/op.</param>
/// <param name="Loop">Runs the operation n times and returns a checksum (so the JIT cannot drop the work).</param>
internal sealed record BenchOp(string Group, string Name, string Mode, bool Hot, Func<int, long> Loop);
