namespace AcPhys.Spec.Invariants;

/// <summary>Whether an invariant states what retail does or a rule beyond retail that protects a port.</summary>
public enum Scope
{
    /// <summary>Retail's behaviour satisfies it (a retail-exact port passes); it cites the facts section it rests on.</summary>
    Retail,

    /// <summary>A rule beyond retail that protects a port; a retail-exact port can fail it.</summary>
    Hardening,
}
