using AcPhys.Contract;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>verify --impl: a .NET adapter assembly loaded in its own AssemblyLoadContext, tested on the ops it announces.</summary>
public sealed class InProcessTests
{
    private static string ExampleAdapter
    {
        get
        {
            string configuration = AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";
            return Path.Combine(RepoPaths.Root, "examples", "dotnet-adapter", "bin", configuration, "net10.0", "ExampleAdapter.dll");
        }
    }

    [Fact]
    public void ExampleAdapterPassesItsLandDefsInvariantsAndTheRestIsNotTested()
    {
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--cases", "500"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("against example-dotnet;", run.Out, StringComparison.Ordinal);
        Assert.Contains(Expected.CleanSummary(Op.LandDefs), run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED COVERAGE: implementation lacks outside_cells", run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void ExampleAdapterBugIsCaughtAndTheReplayLineLoadsTheAdapterAgain()
    {
        var bug = new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "inbound-x-only" };
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--only", "MAP-EDGE", "--cases", "2000"], bug);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL MAP-EDGE on example-dotnet+inbound-x-only", run.Out, StringComparison.Ordinal);
        Assert.Contains("--impl " + ExampleAdapter, run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void NotAnAssemblyIsExit2()
    {
        var run = Acphys.Run(["verify", "--impl", Path.Combine(RepoPaths.Root, "examples", "python", "acphys_impl.py")]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("--impl: cannot load", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void AssemblyWithoutAdapterIsExit2()
    {
        var run = Acphys.Run(["verify", "--impl", Path.Combine(AppContext.BaseDirectory, "AcPhys.Core.dll")]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("has no public class implementing AcPhys.Contract.ICellPhysics", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void ImplAndImplCmdExcludeEachOther()
    {
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--impl-cmd", Acphys.ServeCommand]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("--impl and --impl-cmd exclude each other", run.Err, StringComparison.Ordinal);
    }
}
