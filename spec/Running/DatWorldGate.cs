using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Dat.Container;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>A violation found on a walk through a scene read from a dat world: the block, the walk (cell, portal) and the violation.</summary>
/// <param name="Block">The landblock the scene was extracted at.</param>
/// <param name="Walk">The walk.</param>
/// <param name="Violation">The violation (invariant id, message).</param>
public sealed record DatWorldFinding(LandblockId Block, DatWorldWalk Walk, Violation Violation)
{
    /// <summary>Formats the finding on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"{Violation.InvariantId} in landblock {Block}, walk {Walk}: {Violation.Message}";
}

/// <summary>What a dat-world gate run did: blocks sampled, extracted or refused (with reasons), walks judged, findings.</summary>
/// <param name="Candidates">Landblocks with a LandblockInfo (buildings or env cells) in the cell database.</param>
/// <param name="Sampled">The blocks sampled, in order.</param>
/// <param name="Refused">Blocks whose scene could not be read, and why.</param>
/// <param name="Cells">Env cells in the scenes judged.</param>
/// <param name="Walks">Walks judged.</param>
/// <param name="Findings">Violations.</param>
public sealed record DatWorldResult(
    int Candidates,
    IReadOnlyList<LandblockId> Sampled,
    IReadOnlyList<(LandblockId Block, string Reason)> Refused,
    int Cells,
    int Walks,
    IReadOnlyList<DatWorldFinding> Findings);

/// <summary>
/// The gate over a dat world (docs/dat-container.md "The gate over a dat world"): a deterministic sample of the
/// landblocks holding buildings or env cells, each extracted as a scene (<see cref="SceneExtraction"/>, the whole block),
/// walked (<see cref="DatWorldWalks"/>) and judged by every scene invariant and FIND-CELL-CONFORMANCE
/// (<see cref="InvariantCatalogue.CheckSceneWalk"/>).
/// </summary>
public static class DatWorldGate
{
    /// <summary>Blocks sampled by the pr profile.</summary>
    public const int PrBlocks = 8;

    /// <summary>Blocks sampled by the nightly profile.</summary>
    public const int NightlyBlocks = 64;

    /// <summary>The sample's seed (fixed: the same files give the same sample).</summary>
    public const int SampleSeed = 43;

    /// <summary>Gets the landblocks holding a LandblockInfo (buildings or env cells), ascending.</summary>
    /// <param name="world">The world.</param>
    /// <returns>The blocks.</returns>
    public static List<LandblockId> Candidates(DatWorld world) =>
        [.. world.Cell.Ids.Where(id => (id & 0xFFFF) == 0xFFFE && world.Cell.Contains(id | 1)).Select(id => new LandblockId((ushort)(id >> 16)))];

    /// <summary>Samples blocks: a seeded shuffle of the candidates, the first <paramref name="count"/>.</summary>
    /// <param name="candidates">The candidates.</param>
    /// <param name="count">How many.</param>
    /// <returns>The sample.</returns>
    public static List<LandblockId> Sample(IReadOnlyList<LandblockId> candidates, int count)
    {
        var random = new Random(SampleSeed);
        return [.. candidates.Select(b => (Key: random.Next(), Block: b)).OrderBy(x => x.Key).ThenBy(x => x.Block.Value).Take(count).Select(x => x.Block)];
    }

    /// <summary>Runs the gate on given blocks.</summary>
    /// <param name="world">The world.</param>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="blocks">The blocks.</param>
    /// <param name="candidates">How many candidates the blocks were sampled from (for the report).</param>
    /// <param name="progress">Called after each block.</param>
    /// <returns>The result.</returns>
    public static DatWorldResult Run(DatWorld world, ICellPhysics impl, IReadOnlyList<LandblockId> blocks, int candidates, Action<LandblockId>? progress = null)
    {
        var refused = new List<(LandblockId, string)>();
        var findings = new List<DatWorldFinding>();
        int cells = 0, walks = 0;
        foreach (var block in blocks)
        {
            ExtractedScene got;
            try
            {
                got = SceneExtraction.Extract(world, new ScenePlace(block));
            }
            catch (DatContainerException e)
            {
                refused.Add((block, e.Message));
                progress?.Invoke(block);
                continue;
            }

            cells += got.Scene.Cells.Count;
            foreach (var walk in DatWorldWalks.Of(got.Scene))
            {
                walks++;
                if (InvariantCatalogue.CheckSceneWalk(impl, new SceneWalk(got.Scene, walk.Walk)) is { } v)
                {
                    findings.Add(new DatWorldFinding(block, walk, v));
                }
            }

            progress?.Invoke(block);
        }

        return new DatWorldResult(candidates, blocks, refused, cells, walks, findings);
    }
}
