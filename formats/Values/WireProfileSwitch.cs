namespace AcPhys.Formats.Values;

/// <summary>
/// Switches on the served path's stopwatch breakdown (<c>ACPHYS_WIRE_PROFILE=1</c>, docs/protocol.md "Speed"): the tool
/// reads the variable once, with its other settings, and calls this at start.
/// </summary>
public static class WireProfileSwitch
{
    /// <summary>Collects the breakdown from now on and prints it on stderr at exit.</summary>
    public static void Enable() => WireProfile.Enable();
}
