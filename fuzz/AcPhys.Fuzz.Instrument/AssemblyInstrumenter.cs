using Mono.Cecil;
using Mono.Cecil.Cil;
using Mono.Cecil.Rocks;

namespace AcPhys.Fuzz.Instrument;

/// <summary>Outcome of instrumenting one assembly.</summary>
/// <param name="Path">The assembly file.</param>
/// <param name="Skipped">Why nothing was done, or null when the file was rewritten.</param>
/// <param name="Methods">Methods probed.</param>
/// <param name="Blocks">Probes inserted.</param>
internal sealed record InstrumentResult(string Path, string? Skipped, int Methods, int Blocks);

/// <summary>
/// Rewrites an assembly in place so that every basic block starts with <c>ldc.i4 ID; call Trace::Hit(int32)</c>
/// (AcPhys.Fuzz.Runtime), and marks it with <c>[assembly: Instrumented(blocks)]</c>.
/// </summary>
internal sealed class AssemblyInstrumenter
{
    private const string RuntimeName = "AcPhys.Fuzz.Runtime";
    private const string TraceType = RuntimeName + ".Trace";
    private const string MarkerType = RuntimeName + ".InstrumentedAttribute";

    private readonly string runtimePath;
    private readonly ulong seed;

    /// <summary>Initializes a new instance of the <see cref="AssemblyInstrumenter"/> class.</summary>
    /// <param name="runtimePath">AcPhys.Fuzz.Runtime.dll, exactly the one the harness loads.</param>
    /// <param name="seed">Block id seed.</param>
    public AssemblyInstrumenter(string runtimePath, ulong seed)
    {
        this.runtimePath = runtimePath;
        this.seed = seed;
    }

    /// <summary>Instruments <paramref name="path"/> in place unless it is the runtime, a framework assembly, or already done.</summary>
    /// <param name="path">The assembly file.</param>
    /// <returns>What was done.</returns>
    public InstrumentResult Instrument(string path)
    {
        using var resolver = new DefaultAssemblyResolver();
        resolver.AddSearchDirectory(Path.GetDirectoryName(Path.GetFullPath(path))!);
        resolver.AddSearchDirectory(Path.GetDirectoryName(Path.GetFullPath(runtimePath))!);

        string pdb = Path.ChangeExtension(path, ".pdb");
        bool symbols = File.Exists(pdb);
        var read = new ReaderParameters { InMemory = true, AssemblyResolver = resolver, ReadSymbols = symbols };
        using var module = ModuleDefinition.ReadModule(path, read);

        string? skip = WhySkip(module);
        if (skip is not null)
        {
            return new InstrumentResult(path, skip, 0, 0);
        }

        using var runtime = ModuleDefinition.ReadModule(runtimePath, new ReaderParameters { AssemblyResolver = resolver });
        var trace = runtime.GetType(TraceType) ?? throw new InvalidOperationException($"{TraceType} not in {runtimePath}");
        var hit = module.ImportReference(trace.Methods.Single(m => m.Name == "Hit"));

        var ids = new BlockIds(module.Assembly.Name.Name, seed);
        int methods = 0, blocks = 0;
        foreach (var type in module.GetTypes())
        {
            foreach (var method in type.Methods.Where(m => m.HasBody))
            {
                int inserted = InstrumentMethod(method, hit, ids);
                blocks += inserted;
                methods += inserted > 0 ? 1 : 0;
            }
        }

        var marker = runtime.GetType(MarkerType) ?? throw new InvalidOperationException($"{MarkerType} not in {runtimePath}");
        var attribute = new CustomAttribute(module.ImportReference(marker.Methods.Single(m => m.IsConstructor && !m.IsStatic)));
        attribute.ConstructorArguments.Add(new CustomAttributeArgument(module.TypeSystem.Int32, blocks));
        module.Assembly.CustomAttributes.Add(attribute);

        module.Write(path, new WriterParameters { WriteSymbols = symbols });
        return new InstrumentResult(path, null, methods, blocks);
    }

    private static string? WhySkip(ModuleDefinition module)
    {
        string name = module.Assembly.Name.Name;
        if (name == RuntimeName)
        {
            return "the fuzzing runtime itself";
        }

        if (name is "mscorlib" or "netstandard" || name.StartsWith("System.", StringComparison.Ordinal)
            || name.StartsWith("Microsoft.", StringComparison.Ordinal))
        {
            return "a framework assembly";
        }

        if (module.Assembly.CustomAttributes.Any(a => a.AttributeType.FullName == MarkerType))
        {
            return "already instrumented";
        }

        return null;
    }

    // Each probe goes *in front of* a block start without retargeting anything: the start instruction object (which
    // branches, switch tables, exception-handler bounds and sequence points refer to) is turned into the probe's
    // "ldc.i4 id", and its original opcode and operand move to a new instruction after the "call Hit".
    private static int InstrumentMethod(MethodDefinition method, MethodReference hit, BlockIds ids)
    {
        var body = method.Body;
        body.SimplifyMacros();
        var starts = BlockFinder.FindStarts(body);
        var il = body.GetILProcessor();
        foreach (var start in starts)
        {
            var original = Instruction.Create(OpCodes.Nop);
            original.OpCode = start.OpCode;
            original.Operand = start.Operand;

            start.OpCode = OpCodes.Ldc_I4;
            start.Operand = ids.Get(method.MetadataToken.ToUInt32(), start.Offset);

            il.InsertAfter(start, original);
            il.InsertAfter(start, Instruction.Create(OpCodes.Call, hit));
        }

        body.OptimizeMacros();
        return starts.Count;
    }
}
