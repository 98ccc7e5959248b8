using Xunit.Sdk;

namespace AcPhys.Xunit;

/// <summary>A gate test's failure: its message is the finding as <c>acphys verify</c> prints it, and nothing else (no assertion preamble).</summary>
/// <param name="finding">The finding's text.</param>
public sealed class GateFailure(string finding) : XunitException(finding), IAssertionException;
