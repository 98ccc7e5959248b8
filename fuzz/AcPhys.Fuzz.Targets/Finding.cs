using AcPhys.Formats.Cases;

namespace AcPhys.Fuzz.Targets;

/// <summary>What one crashing input does when it is run again outside afl-fuzz.</summary>
/// <param name="Key">The broken invariant's ID, or the exception's type name for anything else.</param>
/// <param name="Signature">The failure with its numbers masked: inputs with the same key and signature are one group.</param>
/// <param name="Message">The full message of the failure.</param>
/// <param name="Case">The decoded case (a LandCase or Walk) for physics targets, else null.</param>
public sealed record Finding(string Key, string Signature, string Message, AnyCase? Case)
{
    /// <summary>Gets a value indicating whether the finding is a broken invariant (not a stray exception).</summary>
    public bool IsViolation => Case is not null;
}
