using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.E2E.Support;
using AcPhys.Protocol.Messages;

namespace AcPhys.E2E;

/// <summary>
/// Issue #29, world-frame mode: a port that keeps one world frame declares <c>"frame": "world"</c> and is sent every
/// point in world metres (docs/protocol.md, "World frame"); the conversion never fails a correct port, and a shim
/// that converts wrongly is failed.
/// </summary>
public sealed class WorldFrameTests
{
    private const int Seed = 2929;

    [Fact]
    public void WorldFrameReferencePassesTheWholeGateOverTheWire()
    {
        // 300 cases: at 60, NONFINITE-SPHERE-ENDS-LOOP and TIES-PINNED-INDOOR (issue 41's exact bounds) get no judged case.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --world-frame", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains(Expected.CleanSummary(ReferenceAdapter.Instance.Ops), run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void AShimWithAWrongBlockOriginFailsTheGate()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --world-frame --world-frame-fault swapped-block-axes", "--only", "COVERAGE,FIND-CELL-CONFORMANCE", "--cases", "100", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL COVERAGE", run.Out, StringComparison.Ordinal);
        Assert.Contains("FAIL FIND-CELL-CONFORMANCE", run.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "WORLD-FRAME-PIPELINE: a world-frame child is pipelined, and a point it cannot be sent (not judged) pairs no later answer with the wrong query")]
    public void UnposablePointsDoNotShiftPipelinedAnswers()
    {
        // Base seed 7700123001 draws adjust_to_outside and LandDefs points within 61 µm of a block line: each such case
        // is refused before it is counted (ProcessAdapter.RefuseUnposable). Counted and not sent, every later answer was
        // compared with the query before it: false failures of these invariants (commit 1966bb0).
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --world-frame", "--base-seed", "7700123001", "--only", "ADJUST-GEOMETRY,ADJUST-IDEMPOTENT,ADJUST-PRESERVES-POSITION,ADJUST-RANGE,LANDDEFS-CONFORMANCE", "--cases", "2000", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: pipeline: 5 invariant runs streamed", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryCentreSentInTheWorldFrameComesBackBitForBitOrIsNotSent()
    {
        // The rule of docs/protocol.md: world = 192·block + x in double, always exact for |x| ≥ 2⁻¹⁴ m, 0 and the
        // non-finite values; (float)(world − origin) is then x again. A sum a double cannot hold is refused (not judged), never rounded.
        var rnd = new Random(Seed);
        for (int i = 0; i < 20_000; i++)
        {
            var cell = new CellId((byte)rnd.Next(256), (byte)rnd.Next(256), (ushort)rnd.Next(1, 0x41));
            float x = BitConverter.Int32BitsToSingle(rnd.Next()) * (rnd.Next(2) == 0 ? 1 : -1);
            float y = (float)((rnd.NextDouble() * 400) - 100);
            string request = Wire.Line(w =>
            {
                w.WriteString("op", "find_cell");
                w.WriteNull("scene");
                Wire.WriteCell(w, "cell", cell);
                Wire.WriteSpheres(w, "spheres", [new Sphere(new(x, y, 0.5f), 0.5f)]);
                w.WriteNull("current");
            });
            bool alwaysSent = !float.IsFinite(x) || x == 0 || Math.Abs(x) >= 1.0 / (1 << 14);
            string world;
            try
            {
                world = WorldFrame.ToWorld(request);
            }
            catch (UnposableQueryException) when (!alwaysSent)
            {
                continue; // within 61 µm of the block's origin line and not exact in double: not sent, not judged
            }

            using var sent = JsonDocument.Parse(world);
            var origin = sent.RootElement.GetProperty("block_origin");
            Assert.Equal(192.0 * cell.BlockX, origin[0].GetDouble());
            Assert.Equal(192.0 * cell.BlockY, origin[1].GetDouble());
            using var back = Wire.Parse(WorldFrame.ToBlock(world));
            var sphere = Wire.ReadSpheres(back.RootElement, "spheres")[0];
            Assert.True(
                sphere.Center.X.Equals(x) || (x == 0 && sphere.Center.X == 0),
                $"seed {Seed}, i {i}: x {x:R} in {cell} came back as {sphere.Center.X:R} via {world}");
            Assert.Equal(y, sphere.Center.Y);
        }
    }
}
