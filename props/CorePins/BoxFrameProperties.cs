using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// A part's box carried into another cell's frame (facts §5.8): the eight corners of a box, and the axis-aligned box
/// around them after the part's rotation, the block offset to the target cell and the target's inverse frame.
/// </summary>
public sealed class BoxFrameProperties
{
    private static readonly CellId Target = new(0xA9B40105);

    [Fact(DisplayName = "facts §5.7: a box's eight corners are exactly the points with each coordinate its min or its max")]
    public void Corners_AreEveryMinMaxChoice()
    {
        var box = new Box(new Vector3(1, 2, 3), new Vector3(10, 20, 30));
        var expected = from x in new[] { 1f, 10f } from y in new[] { 2f, 20f } from z in new[] { 3f, 30f } select new Vector3(x, y, z);
        Assert.Equal(expected.OrderBy(Key), Enumerable.Range(0, 8).Select(box.Corner).OrderBy(Key));
    }

    [FixedSeedProperty(0x1D00_0020, DisplayName = "facts §5.8: a part's box in a target frame is the axis-aligned box around its 8 rotated corners, moved by 192 m per block of difference, in the target's local frame")]
    public Property InFrame_FoldsTheEightCarriedCorners() =>
        Prop.ForAll(Cases.ToArbitrary(), t =>
        {
            var (part, targetFrame) = t;
            var box = BoxSide.InFrame(part, Target, targetFrame);

            // Spelled out from the fact, not from LandDefs: the block difference in whole blocks times 192 m.
            var shift = new Vector3(192f * (part.Cell.BlockX - Target.BlockX), 192f * (part.Cell.BlockY - Target.BlockY), 0);
            var b = part.Bounds;
            var carried = (from x in new[] { b.Min.X, b.Max.X }
                           from y in new[] { b.Min.Y, b.Max.Y }
                           from z in new[] { b.Min.Z, b.Max.Z }
                           let inTargetBlock = shift + part.Frame.Origin + Vector3.Transform(new Vector3(x, y, z), part.Frame.Rotation)
                           select Vector3.Transform(inTargetBlock - targetFrame.Origin, Quaternion.Conjugate(targetFrame.Rotation))).ToArray();
            var min = carried.Aggregate(Vector3.Min);
            var max = carried.Aggregate(Vector3.Max);
            bool same = Vector3.Distance(box.Min, min) < 2e-3f && Vector3.Distance(box.Max, max) < 2e-3f;
            bool neighbour = part.Cell.Landblock != Target.Landblock;
            return same.Label($"expected [{min}, {max}], got [{box.Min}, {box.Max}]")
                .Classify(neighbour, "part in a neighbouring block").Classify(part.Frame.Rotation != Quaternion.Identity, "rotated part");
        });

    private static Gen<(Part Part, Frame TargetFrame)> Cases { get; } =
        from block in Gen.Elements(0xA9B4u, 0xA8B4u, 0xAAB4u, 0xA9B3u, 0xA9B5u, 0xAAB5u)
        from lo in Gen.Choose(-8, 0).Three()
        from size in Gen.Choose(1, 6).Three()
        from origin in Gen.Choose(-20, 212).Three()
        from yaw in Gen.Elements(0f, 0.3f, 1.2f, -2f, MathF.PI / 2)
        from tilt in Gen.Elements(0f, 0f, 0.4f)
        from targetOrigin in Gen.Choose(0, 192).Three()
        from targetYaw in Gen.Elements(0f, 0.7f, -MathF.PI / 2, 2.5f)
        let min = new Vector3(lo.Item1, lo.Item2, lo.Item3) * 0.5f
        let bounds = new Box(min, min + (new Vector3(size.Item1, size.Item2, size.Item3) * 0.75f))
        let rotation = Quaternion.CreateFromYawPitchRoll(tilt, 0, yaw) // yaw about +Z (AC up), tilt about +Y
        let frame = new Frame(new Vector3(origin.Item1, origin.Item2, origin.Item3 * 0.1f), rotation)
        let part = new Part(new CellId((block << 16) | 0x0001), frame, bounds, 1f, false)
        select (part, new Frame(new Vector3(targetOrigin.Item1, targetOrigin.Item2, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, targetYaw)));

    private static (float, float, float) Key(Vector3 v) => (v.X, v.Y, v.Z);
}
