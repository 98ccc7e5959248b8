namespace AcPhys.Formats.Cases;

/// <summary>The kinds of case (<see cref="AnyCase"/>); each has one codec and one set of judges (<c>Judges</c>).</summary>
public enum CaseKind
{
    /// <summary>One LandDefs input (<see cref="LandCase"/>), file kind <c>land</c>.</summary>
    Land,

    /// <summary>One open-land query (<see cref="OutdoorCase"/>), file kind <c>query</c>.</summary>
    Query,

    /// <summary>A walk on open land (<see cref="Walk"/>), file kind <c>walk</c>.</summary>
    Walk,

    /// <summary>A walk through a scene (<see cref="SceneWalk"/>), file kind <c>scene-walk</c>.</summary>
    SceneWalk,

    /// <summary>A parts query (<see cref="PartsCase"/>), file kind <c>parts</c>.</summary>
    Parts,
}
