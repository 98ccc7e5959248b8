namespace AcPhys.Props.Coverage;

/// <summary>
/// One rule of ../shared/spec/retail-cell-physics-facts.md in the facts-coverage matrix (docs/facts-coverage.md): the
/// generated class that reaches it, what breaks it (a planted fault, or a documented deviation served while announcing
/// retail) and the invariant that judges the broken reference on that class; or why no generated case can reach it.
/// </summary>
/// <param name="Facts">The facts section, step, pitfall or §7 item.</param>
/// <param name="Rule">The rule in a few words.</param>
/// <param name="Class">The case class (a domain tag, <c>./acphys verify --classes</c>) whose cases reach it, or null when out of reach.</param>
/// <param name="Breaker"><c>fault:ID</c>, <c>deviation:NAME</c> (FidelityNames, or <c>current-first</c>), or null when no planted fault breaks this rule alone yet.</param>
/// <param name="Judge">The invariant that must judge the broken reference violated on a case of the class.</param>
/// <param name="OutOfReach">Why no generated case can depend on the rule, or null.</param>
internal sealed record FactsRule(string Facts, string Rule, string? Class, string? Breaker, string? Judge, string? OutOfReach = null);
