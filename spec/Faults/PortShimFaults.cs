using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults around the physics rather than in it (issue 42): the switches that were <c>acphys serve</c> options
/// only (<c>--world-frame-fault</c>, <c>--announce-retail</c>), registered like every other fault so that
/// <c>acphys faults</c>, <c>acphys bite</c>, the known-bug catalogue and <c>verify --fault</c> (in process and served)
/// know them.
/// </summary>
public static class PortShimFaults
{
    /// <summary>A world-frame shim that takes the block origin with its axes swapped.</summary>
    public static readonly PlantedFault WorldFrameSwappedAxes = new(
        "world-frame-swapped-axes",
        "a world-frame port's shim takes the block origin as (192 · block y, 192 · block x): every block-frame point is moved by 192 · (bx − by) m on x and the opposite on y",
        "issue #29: a port that keeps one world frame converts each point with its cell's block origin (docs/protocol.md, \"World frame\"); reading the id's two block bytes the wrong way round is harmless on the diagonal (bx = by) and puts every other point in the wrong place (was `acphys serve --world-frame --world-frame-fault swapped-block-axes`).",
        ["OUTSIDE-LCOORD-GEOMETRY", "ADJUST-GEOMETRY", "COVERAGE", "PARTS-COVERAGE", "PORTAL-TRANSIT", "LANDDEFS-CONFORMANCE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>ACE's documented deviations, served while the port announces retail.</summary>
    public static readonly PlantedFault AceAnnouncedRetail = new(
        "ace-announced-retail",
        "the port behaves as ACE (every documented deviation of --fidelity ace) but its hello announces retail",
        "docs/facts-coverage.md \"Declared deviations\": a deviation is excused only when declared; a port that follows ACE and says nothing must fail the gate on each deviation a scene reaches (was `acphys serve --fidelity ace --announce-retail`; the option still serves any mode undeclared).",
        ["PORTAL-TRANSIT", "VISIBILITY", "SCENE-SOUNDNESS", "HITS-INTERIOR", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Gets every fault of this list.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [WorldFrameSwappedAxes, AceAnnouncedRetail];

    /// <summary>Returns a mode's answers under a retail declaration: the pick and every deviation announced retail.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The implementation, announcing retail.</returns>
    public static ICellPhysics AnnouncingRetail(ICellPhysics impl) => new AnnouncedRetail(impl);

    /// <summary>Returns a world-frame shim with swapped block axes in front of an implementation.</summary>
    /// <param name="impl">The implementation behind the shim.</param>
    /// <returns>The faulty implementation.</returns>
    public static ICellPhysics BehindSwappedShim(ICellPhysics impl) => new SwappedOriginShim(impl);

    /// <summary>Returns the implementation a fault of this list plants, or null for any other fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The faulty adapter, or null.</returns>
    internal static ICellPhysics? Create(PlantedFault fault)
    {
        if (fault == WorldFrameSwappedAxes)
        {
            return BehindSwappedShim(ReferenceAdapter.Instance);
        }

        if (fault == AceAnnouncedRetail)
        {
            if (!FidelityNames.TryParse([FidelityNames.Ace], out var indoor, out var outdoor, out _))
            {
                throw new InvalidOperationException("the fidelity name 'ace' is not known");
            }

            return AnnouncingRetail(new ReferenceAdapter(PickPolicy.Retail, outdoor: outdoor) { Indoor = indoor });
        }

        return null;
    }
}
