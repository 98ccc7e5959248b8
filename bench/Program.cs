using BenchmarkDotNet.Running;

// Run everything: dotnet run -c Release --project bench -- --filter '*'
// Short run (as recorded in bench/results): add --job short
// bench/capture-memory.sh: write a capture of N outdoor frames (CaptureFrames) to a file.
if (args is ["capture-file", var count, var path])
{
    using var file = new StreamWriter(path, false, new System.Text.UTF8Encoding(false), 1 << 16);
    AcPhys.Bench.CaptureFrames.Write(int.Parse(count, System.Globalization.CultureInfo.InvariantCulture), file);
    return;
}

BenchmarkSwitcher.FromAssembly(typeof(AcPhys.Bench.LandDefsBenchmarks).Assembly).Run(args);
