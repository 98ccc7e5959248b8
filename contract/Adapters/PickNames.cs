using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>Protocol names of pick policies: <c>retail</c> and <c>current-first</c>.</summary>
public static class PickNames
{
    /// <summary>Returns the protocol name of a policy.</summary>
    /// <param name="policy">The policy.</param>
    /// <returns>The name.</returns>
    public static string Of(PickPolicy policy) => policy == PickPolicy.CurrentFirst ? "current-first" : "retail";

    /// <summary>Parses a protocol name.</summary>
    /// <param name="name">The name (null means retail).</param>
    /// <param name="policy">The policy.</param>
    /// <returns>True for a known name.</returns>
    public static bool TryParse(string? name, out PickPolicy policy)
    {
        policy = PickPolicy.Retail;
        switch (name)
        {
            case null or "retail":
                return true;
            case "current-first":
                policy = PickPolicy.CurrentFirst;
                return true;
            default:
                return false;
        }
    }
}
