using System.Reflection;
using AcPhys.Core;
using AcPhys.Fuzz.Instrument;
using AcPhys.Fuzz.Runtime;
using AcPhys.Fuzz.Toy;
using Xunit;

namespace AcPhys.Fuzz.Tests;

[Collection(TraceCollection.Name)]
public sealed class InstrumenterTests : IDisposable
{
    private readonly string directory = Directory.CreateTempSubdirectory("acphys-instrument-").FullName;
    private readonly AssemblyInstrumenter instrumenter = new(typeof(Trace).Assembly.Location, seed: 0);

    private delegate int Parser(ReadOnlySpan<byte> data);

    public void Dispose() => Directory.Delete(directory, recursive: true);

    [Fact]
    public void Toy_is_instrumented_once_then_skipped()
    {
        string toy = CopyOf(typeof(MagicHeader).Assembly);

        var first = instrumenter.Instrument(toy);
        var second = instrumenter.Instrument(toy);

        Assert.Null(first.Skipped);
        Assert.Equal(1, first.Methods);
        Assert.True(first.Blocks >= 9, $"{first.Blocks} blocks"); // entry + 4 ifs × (taken, fall-through)
        Assert.Equal("already instrumented", second.Skipped);
    }

    [Fact]
    public void Runtime_is_never_instrumented()
    {
        string runtime = CopyOf(typeof(Trace).Assembly);

        Assert.Equal("the fuzzing runtime itself", instrumenter.Instrument(runtime).Skipped);
    }

    [Fact]
    public void Instrumented_toy_keeps_its_behaviour_and_separates_paths()
    {
        instrumenter.Instrument(CopyOf(typeof(MagicHeader).Assembly));
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
    public void Instrumented_core_agrees_with_the_original()
    {
        instrumenter.Instrument(CopyOf(typeof(LandDefs).Assembly));
        var context = new IsolatedContext(directory);
        try
        {
            var core = context.LoadFromAssemblyPath(Path.Combine(directory, "AcPhys.Core.dll"));
            var landDefs = core.GetType(typeof(LandDefs).FullName!)!;
            var cellIdType = core.GetType(typeof(CellId).FullName!)!;
            var outside = landDefs.GetMethod(nameof(LandDefs.GetOutsideLcoord))!;
            var toGid = landDefs.GetMethod(nameof(LandDefs.LcoordToGid), [typeof(int), typeof(int)])!;
            var random = new Random(1234);
            Trace.ClearMap();

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

            Assert.True(Trace.CountEdges() > 10, $"{Trace.CountEdges()} edges");
        }
        finally
        {
            context.Unload();
        }
    }

    private static unsafe byte[] Edges(Action action)
    {
        Trace.ClearMap();
        Trace.ResetPrevious();
        action();
        return new ReadOnlySpan<byte>(Trace.Map, Trace.MapSize).ToArray();
    }

    private string CopyOf(Assembly assembly)
    {
        string target = Path.Combine(directory, Path.GetFileName(assembly.Location));
        File.Copy(assembly.Location, target, overwrite: true);
        string pdb = Path.ChangeExtension(assembly.Location, ".pdb");
        if (File.Exists(pdb))
        {
            File.Copy(pdb, Path.ChangeExtension(target, ".pdb"), overwrite: true);
        }

        return target;
    }
}
