namespace AcPhys.Formats.Cases;

/// <summary>The route a generated scene walk takes.</summary>
public enum SceneRoute
{
    /// <summary>From outside the front door into the target room.</summary>
    Enter,

    /// <summary>Into the target room and back out the same way.</summary>
    EnterAndBack,

    /// <summary>In by the front door, out by the back door.</summary>
    Through,

    /// <summary>Up to a portal (front door or an inner door) and ±jitter across its plane.</summary>
    PortalJitter,

    /// <summary>±jitter across a land-cell line next to the cottage.</summary>
    LineJitter,

    /// <summary>Around the storey above room 0.</summary>
    Storey,

    /// <summary>Along a dungeon chain from its first cell out of its exit.</summary>
    DungeonRun,

    /// <summary>Along a dungeon chain and back.</summary>
    DungeonRunAndBack,

    /// <summary>An estate: from its stairwell, where it overlaps room 0, west into room 0 and out of its door.</summary>
    Stairwell,

    /// <summary>An estate: along the lead-in dungeon from the next block, out of its exit, in by the entry door and out by another.</summary>
    LeadIn,

    /// <summary>
    /// An estate: up to the entry door, then outdoors along its facade within half a radius of the wall, past the rooms
    /// behind it (their doors, sealed walls and notches: building entry from outside), and away.
    /// </summary>
    Facade,

    /// <summary>A cottage with a sealed closet: from outside straight into the closet's middle and back out (facts §5.5).</summary>
    Closet,

    /// <summary>A hub (a hub plan): from Q0's middle to near the corner where the four quadrants meet, and back.</summary>
    Hub,

    /// <summary>Issue 27: a sphere at near-touch gaps from a plane that decides a test (a near-touch plan).</summary>
    NearTouch,

    /// <summary>Issue 27: into a dungeon hub's corner where a load hint comes early in the closure (a hint-hub plan).</summary>
    HintAhead,

    /// <summary>Issue 41: a sphere exactly at a comparison's bound in the tested cell's frame (SceneRecipe.Plan, spec).</summary>
    ExactBound,

    /// <summary>Issue 41: interiors side by side, a body leaving one while it touches the other (SceneRecipe.Plan, spec).</summary>
    SideBySide,
}
