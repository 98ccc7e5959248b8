using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// PARTS-INDOOR-SOUNDNESS on env ids that name no loaded cell (facts §4 step 3, §5.1): such an id is the anchor or a
/// load hint — a portal target of a cell the closure walked — and ACE's blind-neighbour hint (§7 #10) is excused only
/// where a loaded cell leads to the id without seeing it.
/// </summary>
public sealed class PartsLoadHintTests(ITestOutputHelper output)
{
    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS: an unloaded env id in the anchor's block that no portal leads to is not a load hint (facts §4 step 3, §5.1)")]
    public void InventedHintIsCaught() =>
        Caught(new Appending("an invented load hint", (parts, _) => parts[0].Cell.IsEnv ? parts[0].Cell.WithLow(0xFFF0) : null, IndoorFidelity.Retail), "neither the anchor nor a load hint");

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS: a landblock id listed after an env anchor is neither the anchor nor a load hint (facts §1.1)")]
    public void ListedBlockIdIsCaught() =>
        Caught(new Appending("a block id appended", (parts, _) => parts[0].Cell.IsEnv ? parts[0].Cell.WithLow(0xFFFF) : null, IndoorFidelity.Retail), "neither the anchor nor a load hint");

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (ace-neighbour-via-visible-cells declared): a listed, not-loaded env id is excused after static placement only when a loaded cell leads to it unseen (facts §7 #10)")]
    public void BlindHintExcuseNeedsAPortal() =>
        Caught(new Appending("a loaded cell no portal leads to, flagged not loaded", Unreached, IndoorFidelity.Retail with { AceNeighbourViaVisibleCells = true }), "no part's box comes within 1 mm");

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS: the reference passes with ace-load-hint-low-key and ace-neighbour-via-visible-cells declared (hints under ACE's keys are load hints)")]
    public void AceHintsAreHints()
    {
        foreach (var (name, indoor) in new[] { ("ace-load-hint-low-key", IndoorFidelity.Retail with { AceLoadHintLowKey = true }), ("ace-neighbour-via-visible-cells", IndoorFidelity.Retail with { AceNeighbourViaVisibleCells = true }) })
        {
            var result = PartsIndoorInvariants.Soundness.Run(new ReferenceAdapter { Indoor = indoor }, 1000, PropertyRun.SeedFor(PartsIndoorInvariants.Soundness.Id));
            Assert.True(result.Status == ResultStatus.Passed, result.Violation?.Message);
            output.WriteLine($"{name}: {result.Cases} cases, {result.Applicable} applicable");
        }
    }

    // A loaded env cell no cell of the scene has a portal to, other than the anchor, appended as if a hint.
    private static CellId? Unreached(IReadOnlyList<Part> parts, Scene scene)
    {
        var anchor = parts[0].Cell;
        var targets = scene.Cells.SelectMany(c => c.Portals.Select(p => c.Id.WithLow(p.Other))).ToHashSet();
        return scene.Cells.Any(c => c.Id == anchor) && scene.Cells.FirstOrDefault(c => c.Id != anchor && !targets.Contains(c.Id)) is { } other ? other.Id : null;
    }

    private void Caught(ICellPhysics impl, string why)
    {
        var result = PartsIndoorInvariants.Soundness.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(PartsIndoorInvariants.Soundness.Id), maxClasses: 1);
        Assert.True(result.Status == ResultStatus.Failed, $"{impl.Name} should fail PARTS-INDOOR-SOUNDNESS");
        Assert.Contains(why, result.Violation!.Message, StringComparison.Ordinal);
        output.WriteLine($"{impl.Name}: caught after {result.Cases} cases: {result.Violation!.Message}");
    }

    // The reference, with one id appended (flagged not loaded) to every parts answer the pick gives one for.
    private sealed class Appending(string defect, Func<IReadOnlyList<Part>, Scene, CellId?> pick, IndoorFidelity indoor) : Forwarding(new ReferenceAdapter { Indoor = indoor })
    {
        public override string Name => "reference with " + defect;

        public override FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells)
        {
            var answer = Inner.FindCellParts(scene, parts, loadCells);
            if (pick(parts, scene) is not { } id || answer.Cells.Contains(id))
            {
                return answer;
            }

            var flags = answer.Loaded ?? [.. answer.Cells.Select(_ => true)];
            return answer with { Cells = [.. answer.Cells, id], Loaded = [.. flags, false] };
        }
    }
}
