using System.Reflection;
using AcPhys.Core;
using AcPhys.Fuzz.Toy;
using SharpFuzz;
using Xunit;
using SharpTrace = SharpFuzz.Common.Trace;

namespace AcPhys.Fuzz.Tests;

/// <summary>SharpFuzz's instrumentation of the assemblies the campaigns instrument (copies in a temp folder).</summary>
[Collection(TraceCollection.Name)]
public sealed unsafe class InstrumenterTests : IDisposable
{
    private const int MapSize = 1 << 16;

    private readonly string directory = Directory.CreateTempSubdirectory("acphys-instrument-").FullName;
    private readonly byte[] map = GC.AllocateArray<byte>(MapSize, pinned: true);
    private readonly byte* previousMap = SharpTrace.SharedMem;

    public InstrumenterTests()
    {
        fixed (byte* p = map)
        {
            SharpTrace.SharedMem = p; // pinned: the address stays valid
        }
    }

    private delegate int Parser(ReadOnlySpan<byte> data);

    public void Dispose()
    {
        SharpTrace.SharedMem = previousMap;
        Directory.Delete(directory, recursive: true);
    }

    [Fact]
    public void Toy_is_instrumented_once_then_refused()
    {
        string toy = CopyOf(typeof(MagicHeader).Assembly);

        var types = Fuzzer.Instrument(toy, _ => true, Options.Value).ToList();

        Assert.Contains(typeof(MagicHeader).FullName!, types);
        var again = Assert.Throws<InstrumentationException>(() => Fuzzer.Instrument(toy, _ => true, Options.Value).ToList());
        Assert.Contains("already instrumented", again.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Instrumented_toy_keeps_its_behaviour_and_separates_paths()
    {
        _ = Fuzzer.Instrument(CopyOf(typeof(MagicHeader).Assembly), _ => true, Options.Value).ToList();
        var context = new IsolatedContext(directory);
        try
        {
            var parse = context.LoadFromAssemblyPath(Path.Combine(directory, "AcPhys.Fuzz.Toy.dll"))
                .GetType(typeof(MagicHeader).FullName!)!
                .GetMethod(nameof(MagicHeader.Parse))!
                .CreateDelegate<Parser>();

            byte[] a = Edges(() => Assert.Equal(1, parse("AXYZ"u8)));
            byte[] ac = Edges(() => Assert.Equal(2, parse("ACYZ"u8)));
            byte[] again = Edges(() => Assert.Equal(2, parse("ACYZ"u8)));
            Assert.Throws<InvalidOperationException>(() => parse("AC!P"u8));

            Assert.NotEqual(a, ac);
            Assert.Equal(ac, again);
            Assert.True(ac.Count(b => b != 0) >= 3);
        }
        finally
        {
            context.Unload();
        }
    }

    [Fact]
    public void The_instrumenter_probes_cores_branches_but_not_its_value_types()
    {
        // Issue 51: a probe at the entry of CellId's accessors kept the JIT from inlining them; value types get none.
        string copy = CopyOf(typeof(LandDefs).Assembly);
        var instrumented = Fuzzer.Instrument(copy, AcPhys.Fuzz.Instrumenter.ProbeChoice.For(copy), Options.Value).ToList();
        Assert.Contains(typeof(LandDefs).FullName!, instrumented);
        Assert.Contains(typeof(CellArray).FullName!, instrumented);
        Assert.DoesNotContain(typeof(CellId).FullName!, instrumented);
        Assert.DoesNotContain(typeof(Sphere).FullName!, instrumented);

        var context = new IsolatedContext(directory);
        try
        {
            var core = context.LoadFromAssemblyPath(Path.Combine(directory, "AcPhys.Core.dll"));
            var toGid = core.GetType(typeof(LandDefs).FullName!)!.GetMethod(nameof(LandDefs.LcoordToGid), [typeof(int), typeof(int)])!;
            Array.Clear(map);
            for (int gx = -4; gx < 2045; gx += 7)
            {
                Assert.Equal(LandDefs.LcoordToGid(gx, 2040 - gx).ToString(), toGid.Invoke(null, [gx, 2040 - gx])!.ToString());
            }

            Assert.True(map.Count(b => b != 0) > 3, "LandDefs' probes wrote no edge");
        }
        finally
        {
            context.Unload();
        }
    }

    [Fact]
    public void Instrumented_core_agrees_with_the_original()
    {
        _ = Fuzzer.Instrument(CopyOf(typeof(LandDefs).Assembly), _ => true, Options.Value).ToList();
        var context = new IsolatedContext(directory);
        try
        {
            var core = context.LoadFromAssemblyPath(Path.Combine(directory, "AcPhys.Core.dll"));
            var landDefs = core.GetType(typeof(LandDefs).FullName!)!;
            var cellIdType = core.GetType(typeof(CellId).FullName!)!;
            var outside = landDefs.GetMethod(nameof(LandDefs.GetOutsideLcoord))!;
            var toGid = landDefs.GetMethod(nameof(LandDefs.LcoordToGid), [typeof(int), typeof(int)])!;
            var random = new Random(1234);
            Array.Clear(map);

            for (int i = 0; i < 2000; i++)
            {
                uint id = (uint)random.NextInt64(0, 1L << 32);
                float x = (float)((random.NextDouble() - 0.5) * 600), y = i % 7 == 0 ? float.NaN : (float)((random.NextDouble() - 0.5) * 600);
                bool expected = LandDefs.GetOutsideLcoord(new CellId(id), x, y, out var lcoord);
                object?[] args = [Activator.CreateInstance(cellIdType, id), x, y, null];
                Assert.Equal(expected, (bool)outside.Invoke(null, args)!);
                Assert.Equal(lcoord.ToString(), args[3]!.ToString());

                int gx = random.Next(-10, 2050), gy = random.Next(-10, 2050);
                Assert.Equal(LandDefs.LcoordToGid(gx, gy).ToString(), toGid.Invoke(null, [gx, gy])!.ToString());
            }

            int edges = map.Count(b => b != 0);
            Assert.True(edges > 10, $"{edges} edges");
        }
        finally
        {
            context.Unload();
        }
    }

    private byte[] Edges(Action action)
    {
        Array.Clear(map);
        SharpTrace.PrevLocation = 0;
        action();
        return (byte[])map.Clone();
    }

    private string CopyOf(Assembly assembly)
    {
        string target = Path.Combine(directory, Path.GetFileName(assembly.Location));
        File.Copy(assembly.Location, target, overwrite: true);
        return target;
    }
}
