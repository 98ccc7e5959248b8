namespace AcPhys.Core;

/// <summary>Answers which landblocks are loaded. A scene declares only the blocks a test needs; every other block is unloaded.</summary>
public interface ILandscape
{
    /// <summary>Tests whether the landblock of an id is loaded (its cells have payloads).</summary>
    /// <param name="block">The landblock.</param>
    /// <returns>True when loaded.</returns>
    bool IsLoaded(LandblockId block);
}

/// <summary>Open land: every landblock is loaded.</summary>
public sealed class OpenLand : ILandscape
{
    /// <summary>Gets the shared instance.</summary>
    public static OpenLand Instance { get; } = new();

    /// <inheritdoc/>
    public bool IsLoaded(LandblockId block) => true;
}
