namespace AcPhys.Fuzz.Targets;

/// <summary>What a target exercises, and so what a crash of it means.</summary>
public enum TargetKind
{
    /// <summary>Bytes → a bounded, valid case → the invariant catalogue; a crash is a broken invariant (an <c>InvariantViolationException</c>).</summary>
    Physics,

    /// <summary>Bytes → one of the project's readers; a crash is any exception other than <c>InputFormatException</c>.</summary>
    Parser,

    /// <summary>A pipeline check with a known answer (the toy targets).</summary>
    Smoke,
}
