namespace AcPhys.Spec.Cases;

/// <summary>What an anchor query's anchor names (<see cref="PartAnchors"/>).</summary>
internal enum AnchorKind
{
    /// <summary>An env cell of the position's block that the scene lacks.</summary>
    MissingEnv,

    /// <summary>The landblock id of the position's block (low word 0xFFFF).</summary>
    BlockId,

    /// <summary>A land cell of the neighbouring block across the block line the anchor is near.</summary>
    BlockEdge,
}
