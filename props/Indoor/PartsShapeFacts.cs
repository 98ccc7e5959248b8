using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The reference equals the facts on the parts classes of issue 53 (retail-like shapes and anchors): at every portal
/// of a listed env cell and every door of a listed land cell's building, one part at a time, the core's transit and
/// building check answer what facts §5.2 and §5.3 state (one-sided sphere gate first, then the box side, then the
/// target), and an anchor naming no loaded env cell lists itself alone (§4 step 3). Distribution printed.
/// </summary>
public sealed class PartsShapeFacts(ITestOutputHelper output)
{
    private const int Cases = 1500;

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE (facts §5.2, §5.3): per part, the core's portal transit and door check equal the facts' gate → box side → target, on pr cases where the gate and the box disagree (counts printed)")]
    public void TransitAndEntryAreTheFacts()
    {
        var judge = PartsIndoorInvariants.Coverage;
        var seen = new Dictionary<string, int> { ["gate-shut"] = 0, ["gate-open"] = 0, ["sphere-across-box-not"] = 0, ["door gate-shut"] = 0, ["door gate-open"] = 0, ["door sphere-across-box-not"] = 0 };
        int checkedParts = 0;
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            var scene = SceneBuild.Build(w.Scene);
            foreach (var (index, parts) in ScenePartsQueries.Of(w))
            {
                var listed = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, true).Cells;
                foreach (var id in listed)
                {
                    foreach (var part in parts)
                    {
                        if (id.IsEnv && scene.GetEnvCell(id) is { } env)
                        {
                            checkedParts++;
                            string? why = Transit(scene, env, part, seen);
                            Assert.True(why is null, $"step {index}, cell {id}: {why}");
                        }
                        else if (id.IsLand && scene.IsLoaded(id.Landblock) && scene.GetBuilding(id) is { } building)
                        {
                            foreach (var door in building.Portals)
                            {
                                if (scene.GetEnvCell(id.WithLow(door.OtherCellId)) is { } cell && door.OtherPortalId < cell.Portals.Length)
                                {
                                    checkedParts++;
                                    bool want = Enters(cell, cell.Portals[door.OtherPortalId], part, seen);
                                    bool got = EnvTransitParts.CheckBuildingTransit(new CellArray(), scene, cell, door.OtherPortalId, [part], IndoorFidelity.Retail);
                                    Assert.True(want == got, $"step {index}, door of {id} into {cell.Id}: the facts say {(want ? "enters" : "stays out")}, the core {(got ? "enters" : "stays out")}");
                                }
                            }
                        }
                    }
                }
            }

            return true;
        });
        output.WriteLine($"{Cases} pr cases of {judge.Id}, {checkedParts:N0} part checks: " + string.Join(", ", seen.Select(kv => $"{kv.Key} {kv.Value:N0}")));
        Assert.All(seen.Where(kv => !kv.Key.StartsWith("door gate-open", StringComparison.Ordinal)), kv => Assert.True(kv.Value > 0, $"{kv.Key} never seen"));
    }

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (facts §1.1, §4 step 3): an anchor naming a missing env cell or a landblock id lists itself alone, not loaded, with HitsInteriorCell, in both kinds; a block-edge land anchor lists its own cell")]
    public void AnchorsAreTheFacts()
    {
        var judge = PartsIndoorInvariants.Soundness;
        var seen = new Dictionary<AnchorKind, int>();
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            foreach (var (index, kind, parts) in ScenePartsQueries.Anchors(w))
            {
                seen[kind] = seen.GetValueOrDefault(kind) + 1;
                foreach (bool loadCells in new[] { false, true })
                {
                    var answer = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, loadCells);
                    if (kind == AnchorKind.BlockEdge)
                    {
                        Assert.True(parts[0].Cell.IsLand && answer.Cells.Contains(parts[0].Cell), $"step {index}: block-edge anchor {parts[0].Cell} not in [{string.Join(", ", answer.Cells)}]");
                        continue;
                    }

                    Assert.Equal([parts[0].Cell], answer.Cells);
                    Assert.Equal([false], answer.Loaded!);
                    Assert.True(answer.HitsInteriorCell == true, $"step {index}: HitsInteriorCell for anchor {parts[0].Cell}");
                }
            }

            return true;
        });
        output.WriteLine($"{Cases} pr cases of {judge.Id}: anchor queries " + string.Join(", ", seen.Select(kv => $"{kv.Key} {kv.Value:N0}")));
        Assert.Equal(3, seen.Count);
    }

    // Facts §5.2, one part: per portal, the gate (PortalSide: skip d < −R, else d > R), the box side (skip Positive when
    // !PortalSide, Negative when PortalSide), then the exit, the load hint or the neighbour by box_intersects_cell.
    private static string? Transit(CellScene scene, EnvCell cell, Part part, Dictionary<string, int> seen)
    {
        var wantEnv = new HashSet<CellId>();
        bool wantOutside = false;
        foreach (var portal in cell.Portals.ToArray())
        {
            float d = Distance(cell, portal, part), r = part.Radius + LandDefs.Epsilon;
            var side = BoxSide.Of(portal.Plane, BoxSide.InFrame(part, cell.Id, cell.Frame));
            bool shut = portal.PortalSide ? d < -r : d > r;
            Count(seen, string.Empty, side, shut, MathF.Abs(d) > r, portal.PortalSide ? side == Sidedness.Negative : side == Sidedness.Positive);
            if (shut || (side == Sidedness.Positive && !portal.PortalSide) || (side == Sidedness.Negative && portal.PortalSide))
            {
                continue;
            }

            if (portal.LeadsOutside(default))
            {
                wantOutside = true;
            }
            else if (scene.GetEnvCell(cell.Id.WithLow(portal.OtherCellId)) is not { } other)
            {
                wantEnv.Add(cell.Id.WithLow(portal.OtherCellId));
            }
            else if (other.Volume.BoxIntersects(BoxSide.InFrame(part, other.Id, other.Frame)))
            {
                wantEnv.Add(other.Id);
            }
        }

        var array = new CellArray();
        EnvTransitParts.FindTransitCells(array, scene, cell, [part], IndoorFidelity.Retail);
        var got = array.ToIdArray();
        var gotEnv = got.Where(id => id.IsEnv).ToHashSet();
        bool gotOutside = got.Any(id => id.IsLand);
        return gotEnv.SetEquals(wantEnv) && gotOutside == wantOutside ? null
            : $"the facts say [{string.Join(", ", wantEnv)}]{(wantOutside ? " and the outside" : string.Empty)}, the core [{string.Join(", ", got)}]";
    }

    // Facts §5.3, one part: the mirrored gate (PortalSide: skip d > R, else d < −R), retail's pairing (Crossing, or
    // wholly on the cell's side), and box_intersects_cell.
    private static bool Enters(EnvCell cell, CellPortal portal, Part part, Dictionary<string, int> seen)
    {
        float d = Distance(cell, portal, part), r = part.Radius + LandDefs.Epsilon;
        var box = BoxSide.InFrame(part, cell.Id, cell.Frame);
        var side = BoxSide.Of(portal.Plane, box);
        bool shut = portal.PortalSide ? d > r : d < -r;
        var inside = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
        Count(seen, "door ", side, shut, MathF.Abs(d) > r, side != Sidedness.Crossing && side != inside);
        return !shut && (side == Sidedness.Crossing || side == inside) && cell.Volume.BoxIntersects(box);
    }

    private static void Count(Dictionary<string, int> seen, string at, Sidedness side, bool shut, bool apart, bool boxTurnsBack)
    {
        if (side == Sidedness.Crossing && apart)
        {
            seen[at + (shut ? "gate-shut" : "gate-open")]++;
        }
        else if (!apart && boxTurnsBack)
        {
            seen[at + "sphere-across-box-not"]++;
        }
    }

    private static float Distance(EnvCell cell, CellPortal portal, Part part) =>
        portal.Plane.Distance(cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell)));
}
