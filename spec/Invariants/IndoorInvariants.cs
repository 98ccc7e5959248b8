using System.Numerics;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Invariants of walks in scenes: interior wins, hysteresis, portal transit, no tunnelling, visibility, and the rest (facts §4, §5).
/// One concept per file: the pick (<c>IndoorInvariants.Pick.cs</c>), moving through portals (<c>.Transit.cs</c>), which
/// cells one query can enter (<c>.Entry.cs</c>), load hints (<c>.LoadHints.cs</c>), the documented no-answers and the
/// walk off retail's track after one (<c>.NeverNull.cs</c>), what a candidate may be (<c>.Soundness.cs</c>), moving the
/// scene (<c>.Translation.cs</c>) and a cell's portals read from the geometry (<c>.OutwardPortals.cs</c>).
/// </summary>
internal static partial class IndoorInvariants
{
    /// <summary>Depth, metres, beyond which a point is robustly inside or outside a cell (far above EPS and the BSP's 0.01 only where stated).</summary>
    public const double Margin = 1e-3;

    // Set in the static constructor, which runs after every field initializer of every part of this class (the order of
    // the parts' initializers is not specified): the catalogue order of the scene invariants.
    static IndoorInvariants()
    {
        All = [InteriorWins, HysteresisIndoor, PortalTransit, NoTunnel, Visibility, EnterExit, SceneTranslation, ContainingContains, NeverNull, SceneSoundness];
    }

    /// <summary>Gets every scene invariant.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; }

    private static Vector3 Center(WalkStep s) => s.Query.Spheres[0].Center;
}
