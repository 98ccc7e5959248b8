using BenchmarkDotNet.Running;

// Run everything: dotnet run -c Release --project bench -- --filter '*'
// Short run (as recorded in bench/results): add --job short
BenchmarkSwitcher.FromAssembly(typeof(AcPhys.Bench.LandDefsBenchmarks).Assembly).Run(args);
