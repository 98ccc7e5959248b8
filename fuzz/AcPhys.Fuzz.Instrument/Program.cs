using System.Globalization;
using AcPhys.Fuzz.Instrument;

// Usage: AcPhys.Fuzz.Instrument [--runtime RUNTIME.dll] [--seed N] ASSEMBLY.dll...
// Rewrites each assembly in place with AFL edge-coverage probes (see AssemblyInstrumenter). Exit 0 when every
// assembly was instrumented or deliberately skipped, 1 on a failure, 2 on a usage error.
string? runtime = null;
ulong seed = 0;
var targets = new List<string>();
for (int i = 0; i < args.Length; i++)
{
    switch (args[i])
    {
        case "--runtime" when i + 1 < args.Length:
            runtime = args[++i];
            break;
        case "--seed" when i + 1 < args.Length:
            seed = ulong.Parse(args[++i], CultureInfo.InvariantCulture);
            break;
        case "-h" or "--help":
            Console.WriteLine("usage: AcPhys.Fuzz.Instrument [--runtime AcPhys.Fuzz.Runtime.dll] [--seed N] ASSEMBLY.dll...");
            return 0;
        default:
            targets.Add(args[i]);
            break;
    }
}

if (targets.Count == 0)
{
    Console.Error.WriteLine("usage: AcPhys.Fuzz.Instrument [--runtime AcPhys.Fuzz.Runtime.dll] [--seed N] ASSEMBLY.dll...");
    return 2;
}

// Default: the runtime that sits beside the first target, i.e. the copy the harness will load.
runtime ??= Path.Combine(Path.GetDirectoryName(Path.GetFullPath(targets[0]))!, "AcPhys.Fuzz.Runtime.dll");
if (!File.Exists(runtime))
{
    Console.Error.WriteLine($"runtime not found: {runtime} (pass --runtime)");
    return 2;
}

var instrumenter = new AssemblyInstrumenter(runtime, seed);
int failures = 0;
foreach (string target in targets)
{
    try
    {
        var result = instrumenter.Instrument(target);
        Console.WriteLine(result.Skipped is null
            ? $"instrumented {target}: {result.Methods} methods, {result.Blocks} blocks"
            : $"skipped {target}: {result.Skipped}");
    }
    catch (Exception e) when (e is IOException or BadImageFormatException or InvalidOperationException or UnauthorizedAccessException)
    {
        Console.Error.WriteLine($"failed {target}: {e.Message}");
        failures++;
    }
}

return failures == 0 ? 0 : 1;
