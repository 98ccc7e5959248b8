using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>scene</c> target: bytes → <see cref="SceneCodec"/> (a bounded recipe: a cottage of 1–4 rooms or a dungeon
/// chain, placed anywhere, across block lines or at the map edge, with yaw, storey, unloaded neighbours, a body and a
/// route of at most about 100 steps) → the scene walk → <see cref="InvariantCatalogue.CheckSceneWalk"/>: every indoor
/// invariant the implementation is testable for. Crashes shrink with <see cref="SceneShrinker"/> into a
/// <c>scene-walk</c> regression.
/// </summary>
public sealed class SceneWalkTarget : PhysicsTarget<SceneWalk>
{
    /// <inheritdoc/>
    public override string Name => "scene";

    /// <inheritdoc/>
    public override bool MayHang => true;

    /// <inheritdoc/>
    public override string Description => "every indoor invariant on a scene walk (SceneCodec: cottage or dungeon, placement, body, route)";

    // Plain scenes: the zero input (a one-room cottage, walked into), a 6 m room entered and left, a dungeon run, and
    // "outside-two-steps" (the zero cottage, two steps toward its door, never inside), which passes under every indoor
    // fault that does not fail on every walk, so afl-fuzz always has a passing seed to mutate. The cottage corpus cases
    // are in corpus/fuzz/scene.

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]>
    {
        ["zeros"] = new byte[SceneCodec.Length],
        ["one-room-in-and-back"] = [0x00, 0x00, 0x08, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x30, 0x30, 0x40, 0x40, 0x01, 0x00, 0x04, 0x04, 0x00],
        ["outside-two-steps"] = [0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02],
        ["dungeon-run"] = [0x05, 0x01, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x30, 0x30, 0x14, 0x14, 0x00, 0x00, 0x04, 0x04, 0x00],
    };

    /// <inheritdoc/>
    public override CaseKind Judged => CaseKind.SceneWalk;

    /// <summary>
    /// Gives each input a fresh implementation where that is cheap: an indoor fault may keep state between queries
    /// (<c>stale-scene-array</c> keeps its cell array), and afl-fuzz's inputs must not see each other's state, so a
    /// crash is the input's own and triage (which starts from a fresh implementation) reproduces it.
    /// </summary>
    /// <param name="subject">The subject.</param>
    /// <returns>The implementation for one input.</returns>
    protected override ICellPhysics PerInput(Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        return subject.Fresh();
    }

    /// <inheritdoc/>
    public override SceneWalk Decode(ReadOnlySpan<byte> data) => SceneCodec.DecodeWalk(data);

    /// <inheritdoc/>
    public override Violation? Check(ICellPhysics impl, SceneWalk c) => InvariantCatalogue.CheckSceneWalk(impl, c);

    /// <inheritdoc/>
    /// <inheritdoc/>
    /// <remarks>One walk in static placement, its scene built on the first query: a judged input runs it in both kinds of query.</remarks>
    public override object Physics(SceneWalk c) => ReferenceAdapter.Instance.FindCellWalk(WalkRunner.Request(c.Walk, c.Scene));

    /// <inheritdoc/>
    public override IEnumerable<SceneWalk> Shrink(SceneWalk c) => SceneShrinker.Shrink(c);
}
