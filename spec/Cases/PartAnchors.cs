using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Extra parts queries of a scene walk whose anchor (first part) names a cell the walk's position never is (issue 53):
/// an env cell the scene lacks, the landblock id (low word 0xFFFF) of the position's block, or a land cell of the
/// neighbouring block across a block line the anchor is near (its origin re-based by ±192 m, <see cref="PartFrames"/>).
/// One such query rides on every <see cref="Every"/>-th query step, the kinds in turn; the other parts are the step's.
/// </summary>
/// <remarks>
/// What retail answers (facts §1.1, §4 steps 2–3, 5): an anchor indoor by its low word (an env id, and 0xFFFF too) is
/// added with its load flag — false when the scene lacks it — and sets HitsInteriorCell; the closure runs only from a
/// loaded anchor, and the filter only inside that guard, so a missing anchor's list is the anchor alone. A land anchor
/// in the next block seeds the outdoor cells from that block's frame and runs the closure when its block is loaded.
/// </remarks>
internal static class PartAnchors
{
    /// <summary>How many query steps apart the anchor queries ride (a quarter of the steps: the pr gate's budget).</summary>
    public const int Every = 4;

    /// <summary>Returns the anchor query of a step, if it has one: the kind in turn and the step's parts with the anchor re-seated.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="step">The step index.</param>
    /// <param name="parts">The step's parts (the first is the anchor).</param>
    /// <returns>The kind and the parts, or null when the step has none (not its turn, or a block-edge turn far from a line).</returns>
    public static (AnchorKind Kind, Part[] Parts)? Of(CellScene scene, int step, Part[] parts)
    {
        if (step % Every != Every - 1)
        {
            return null;
        }

        var kind = (AnchorKind)(step / Every % 3);
        var anchor = parts[0];
        CellId? cell = kind switch
        {
            AnchorKind.MissingEnv => MissingEnv(scene, anchor.Cell),
            AnchorKind.BlockId => anchor.Cell.WithLow(LandDefs.BlockCellId),
            _ => null,
        };
        var seated = anchor;
        if (cell is { } id)
        {
            seated = anchor with { Cell = id };
        }
        else if (PartFrames.AcrossLine(anchor.Cell, anchor.Frame.Origin) is { } across)
        {
            seated = anchor with { Cell = across.Cell, Frame = anchor.Frame with { Origin = across.Origin } };
        }
        else
        {
            return null;
        }

        var asked = (Part[])parts.Clone();
        asked[0] = seated;
        return (kind, asked);
    }

    // The highest env cell id of the anchor's block that the scene lacks (a scene holds a few cells from 0x0100 up).
    private static CellId MissingEnv(CellScene scene, CellId anchor)
    {
        for (ushort low = LandDefs.LastEnvCellId; ; low--)
        {
            var id = anchor.WithLow(low);
            if (scene.GetEnvCell(id) is null)
            {
                return id;
            }
        }
    }
}
