namespace AcPhys.Xunit;

/// <summary>What one gate test found.</summary>
/// <param name="NotTested">Why the invariant could not be judged (the test is skipped with it), or null.</param>
/// <param name="Failure">The finding as <c>acphys verify</c> prints it, or null when the invariant held.</param>
public sealed record GateVerdict(string? NotTested, string? Failure);
