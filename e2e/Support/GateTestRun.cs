using System.Diagnostics;
using System.Text;
using System.Xml.Linq;

namespace AcPhys.E2E.Support;

/// <summary>A <c>dotnet test</c> of a port's gate tests (AcPhys.Xunit) run as a process, read back from its TRX file.</summary>
internal static class GateTestRun
{
    /// <summary>Gets the build configuration the e2e tests were built in (the example's output folder).</summary>
    public static string Configuration => AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";

    /// <summary>Gets the example port's gate tests assembly.</summary>
    public static string ExampleGateDll => Path.Combine(RepoPaths.Root, "examples", "dotnet-port", "GateTests", "bin", Configuration, "net10.0", "ExamplePort.GateTests.dll");

    /// <summary>Gets the example port's assembly beside it: the one the gate tests load, so the one verify is pointed at.</summary>
    public static string ExamplePortDll => Path.Combine(Path.GetDirectoryName(ExampleGateDll)!, "ExamplePort.dll");

    /// <summary>Runs <c>dotnet</c> (or a command) and reads the TRX file it was told to write.</summary>
    /// <param name="args">The arguments after <c>dotnet</c> (or the command and its arguments), naming a TRX logger whose file is <paramref name="trx"/>.</param>
    /// <param name="trx">The TRX file, or null when none is expected.</param>
    /// <param name="environment">Extra environment.</param>
    /// <param name="folder">The working folder (the repository root when null).</param>
    /// <param name="viaDotnet">Whether <paramref name="args"/> are dotnet's; else the first is the program.</param>
    /// <returns>The exit code, output, and one row per test.</returns>
    public static (Run Run, IReadOnlyList<TrxRow> Rows) Dotnet(IEnumerable<string> args, string? trx, IReadOnlyDictionary<string, string> environment, string? folder = null, bool viaDotnet = true)
    {
        var list = args.ToList();
        var info = new ProcessStartInfo(viaDotnet ? "dotnet" : list[0])
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
            WorkingDirectory = folder ?? RepoPaths.Root,
        };
        foreach (var a in viaDotnet ? list : list.Skip(1))
        {
            info.ArgumentList.Add(a);
        }

        foreach (string name in new[] { "ACPHYS_PROFILE", "ACPHYS_SEED", "ACPHYS_PORT_BUG" })
        {
            info.Environment.Remove(name);
        }

        info.Environment["ACPHYS_COMMAND"] = "acphys";
        foreach (var (k, v) in environment)
        {
            info.Environment[k] = v;
        }

        var run = Acphys.RunToEnd(info, info.FileName + " " + string.Join(' ', info.ArgumentList));
        if (trx is null)
        {
            return (run, []);
        }

        Assert.True(File.Exists(trx), "no TRX file " + trx + "\n" + run);
        return (run, Read(trx));
    }

    private static IReadOnlyList<TrxRow> Read(string trx)
    {
        var doc = XDocument.Load(trx);
        return doc.Descendants().Where(e => e.Name.LocalName == "UnitTestResult").Select(e => new TrxRow(
            (string)e.Attribute("testName")!,
            (string)e.Attribute("outcome")!,
            string.Join('\n', e.Descendants().Where(d => d.Name.LocalName is "Message" or "StdOut").Select(d => d.Value)))).ToArray();
    }
}

/// <summary>One test of a TRX file.</summary>
/// <param name="Name">The test's display name.</param>
/// <param name="Outcome">Passed, Failed or NotExecuted (skipped).</param>
/// <param name="Text">Its message and output.</param>
internal sealed record TrxRow(string Name, string Outcome, string Text);
