using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// Moving the scene by a landblock changes only the ids (facts §1.3, §5.8).
internal static partial class IndoorInvariants
{
    /// <summary>SCENE-TRANSLATION.</summary>
    public static readonly Invariant<SceneWalk> SceneTranslation = new(
        "SCENE-TRANSLATION",
        "Moving the whole scene and the walk by one landblock changes nothing but the ids: every step's candidates and containing cell are the originals moved by the same block offset (away from the map edge).",
        "facts §1.3, §5.8 (block frames are relative)",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            var blocks = w.Scene.Blocks.Concat(w.Scene.UnloadedBlocks).Append(w.Walk.StartCell.Landblock).ToList();
            int dx = blocks.Max(b => b.X) < 0xFC ? 1 : -1, dy = blocks.Max(b => b.Y) < 0xFC ? 1 : -1;
            if (blocks.Any(b => b.X + dx < 1 || b.Y + dy < 1 || b.X + dx > 0xFD || b.Y + dy > 0xFD))
            {
                return Outcome.Vacuous;
            }

            // A declared ace-load-hint-low-key keys hints by the bare 16-bit id, which no move changes (facts §7 #11); in a
            // scene holding block 0x0000 such a key cannot be told from a cell id, so the case is not judged.
            bool lowKey = impl.Indoor.AceLoadHintLowKey;
            if (lowKey && blocks.Any(b => b.X == 0 && b.Y == 0))
            {
                return Outcome.Vacuous;
            }

            CellId Moved(CellId id) => lowKey && id.IsEnv && id.BlockX == 0 && id.BlockY == 0 ? id : Move(id, dx, dy);
            var moved = new SceneWalk(w.Scene.Translated(dx, dy), w.Walk with { StartCell = Move(w.Walk.StartCell, dx, dy) });
            var a = SceneWalkRunner.Run(impl, w);
            var b = SceneWalkRunner.Run(impl, moved);
            foreach (var (x, y) in a.Zip(b))
            {
                var (wx, wy) = SceneOracle.World(x.Query.Cell, Center(x));
                if (!SceneOracle.OnMap(wx, wy, 192 + 48))
                {
                    return Outcome.Vacuous;
                }

                var expected = x.Cells.Select(Moved).ToList();
                if (!expected.SequenceEqual(y.Cells) || Move(x.Containing, dx, dy) != y.Containing)
                {
                    return Outcome.ViolatedAt(x.Index, $"step {x.Index}: moved by ({dx}, {dy}) blocks the answer is [{string.Join(", ", y.Cells)}] → {y.Containing}, expected [{string.Join(", ", expected)}] → {Move(x.Containing, dx, dy)}");
                }
            }

            return Outcome.Holds;
        },
        sceneForms: SceneQueryKinds.Either);


    private static CellId Move(CellId id, int dx, int dy) => id.IsNone ? id : new CellId((byte)(id.BlockX + dx), (byte)(id.BlockY + dy), id.Low);
}
