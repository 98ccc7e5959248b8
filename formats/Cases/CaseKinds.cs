namespace AcPhys.Formats.Cases;

/// <summary>
/// The one switch over <see cref="CaseKind"/>: code that needs a value per kind names one for every kind here, so a new
/// kind adds a parameter and every such place stops compiling until it names the new kind's value.
/// </summary>
public static class CaseKinds
{
    /// <summary>Returns the value given for a kind.</summary>
    /// <typeparam name="T">The value type.</typeparam>
    /// <param name="kind">The kind.</param>
    /// <param name="land">For <see cref="CaseKind.Land"/>.</param>
    /// <param name="query">For <see cref="CaseKind.Query"/>.</param>
    /// <param name="walk">For <see cref="CaseKind.Walk"/>.</param>
    /// <param name="sceneWalk">For <see cref="CaseKind.SceneWalk"/>.</param>
    /// <param name="parts">For <see cref="CaseKind.Parts"/>.</param>
    /// <returns>The value of the kind.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="kind"/> is not a named kind (a cast integer).</exception>
    public static T Pick<T>(this CaseKind kind, T land, T query, T walk, T sceneWalk, T parts) => kind switch
    {
        CaseKind.Land => land,
        CaseKind.Query => query,
        CaseKind.Walk => walk,
        CaseKind.SceneWalk => sceneWalk,
        CaseKind.Parts => parts,
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a case kind"),
    };
}
