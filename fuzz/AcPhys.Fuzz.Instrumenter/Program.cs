using AcPhys.Fuzz.Instrumenter;
using SharpFuzz;

// Usage: AcPhys.Fuzz.Instrumenter ASSEMBLY.dll...
// Rewrites each assembly in place with SharpFuzz's AFL edge probes (every type but value types: ProbeChoice.cs). All
// assemblies go through this one process on purpose: SharpFuzz draws block ids from one generator with a fixed seed per process, so separate
// `sharpfuzz` runs would hand the same ids to different assemblies' blocks. An assembly SharpFuzz reports as already
// instrumented is skipped, so running twice over the same files is harmless. Exit 0 when every assembly was
// instrumented or skipped, 1 on a failure, 2 on a usage error. Each line names the assembly's probes (instrumented
// blocks: SharpFuzz's writes of Trace.PrevLocation), the denominator of a port campaign's coverage (docs/fuzzing.md).
if (args.Length == 0 || args is ["-h" or "--help"])
{
    Console.Error.WriteLine("usage: AcPhys.Fuzz.Instrumenter ASSEMBLY.dll...");
    return args.Length == 0 ? 2 : 0;
}

int failures = 0;
foreach (string target in args)
{
    try
    {
        int types = Fuzzer.Instrument(target, ProbeChoice.For(target), Options.Value).Count();
        Console.WriteLine($"instrumented {target}: {types} types, {Probes(target)} probes (SharpFuzz)");
    }
    catch (InstrumentationException e) when (e.Message.Contains("already instrumented", StringComparison.Ordinal))
    {
        Console.WriteLine($"skipped {target}: already instrumented, {Probes(target)} probes");
    }
    catch (Exception e) when (e is InstrumentationException or IOException or BadImageFormatException or UnauthorizedAccessException)
    {
        Console.Error.WriteLine($"failed {target}: {e.Message}");
        failures++;
    }
}

return failures == 0 ? 0 : 1;

// Counts SharpFuzz's probes: one store to SharpFuzz.Common.Trace.PrevLocation closes each instrumented block.
static int Probes(string path)
{
    using var module = dnlib.DotNet.ModuleDefMD.Load(File.ReadAllBytes(path));
    return module.GetTypes()
        .SelectMany(t => t.Methods)
        .Where(m => m.HasBody)
        .SelectMany(m => m.Body.Instructions)
        .Count(i => i.OpCode == dnlib.DotNet.Emit.OpCodes.Stsfld && i.Operand is dnlib.DotNet.IField f && f.Name == "PrevLocation"
            && f.DeclaringType?.FullName == "SharpFuzz.Common.Trace");
}

