using System.Xml;
using System.Xml.Linq;
using System.Xml.Schema;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>verify --junit / --markdown: JUnit XML that a schema check accepts, and a PR-comment summary with each failure's minimised case, seed and replay line.</summary>
public sealed class GateOutputTests
{
    private static readonly string Schema = Path.Combine(RepoPaths.Root, "schemas", "junit-10.xsd");

    [Fact]
    public void JunitXmlOfAFailingRunIsAcceptedByTheSchemaAndCountsMatch()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-gate-").FullName;
        string junit = Path.Combine(dir, "out.xml"), markdown = Path.Combine(dir, "summary.md");
        var run = Acphys.Run(["verify", "--fault", "clamp-106", "--pick", "retail", "--only", "NO-BOUNDARY-FREEZE,LCOORD-ROUNDTRIP,HYSTERESIS", "--cases", "300", "--quiet", "--junit", junit, "--markdown", markdown]);
        Assert.True(run.Exit == 1, run.ToString());

        var errors = Validate(File.ReadAllText(junit));
        Assert.True(errors.Count == 0, string.Join("\n", errors));

        var suite = XDocument.Load(junit).Root!.Element("testsuite")!;
        Assert.Equal("3", suite.Attribute("tests")!.Value);
        Assert.Equal("1", suite.Attribute("failures")!.Value);
        Assert.Equal("1", suite.Attribute("skipped")!.Value);
        var failure = suite.Elements("testcase").Single(t => t.Attribute("name")!.Value == "NO-BOUNDARY-FREEZE").Element("failure")!;
        Assert.Contains("shrunk:    start ", failure.Value, StringComparison.Ordinal);
        Assert.Contains("replay:    acphys verify --only NO-BOUNDARY-FREEZE", failure.Value, StringComparison.Ordinal);
        Assert.NotNull(suite.Elements("testcase").Single(t => t.Attribute("name")!.Value == "HYSTERESIS").Element("skipped"));

        string md = File.ReadAllText(markdown);
        Assert.Contains("## acphys verify: ❌ 1 invariant violated", md, StringComparison.Ordinal);
        Assert.Contains("| `NO-BOUNDARY-FREEZE` | retail | ❌ **FAIL** |", md, StringComparison.Ordinal);
        Assert.Contains("| `LCOORD-ROUNDTRIP` | retail | ✅ pass |", md, StringComparison.Ordinal);
        Assert.Contains("Minimised walk:", md, StringComparison.Ordinal);
        Assert.Contains("The walk on reference+clamp-106:", md, StringComparison.Ordinal);
        Assert.Contains(" | none | [] |", md, StringComparison.Ordinal); // the step where the clamped port freezes
        Assert.Contains("Seed: `", md, StringComparison.Ordinal);
        Assert.Contains("acphys verify --only NO-BOUNDARY-FREEZE --cases 300 --seed ", md, StringComparison.Ordinal);
        Assert.Contains("- `HYSTERESIS`: applies to the current-first pick", md, StringComparison.Ordinal);
        Assert.Empty(Directory.GetFiles(dir, ".*.tmp")); // written atomically: no temporary left behind
    }

    [Fact]
    public void JunitXmlNamesEachRootCauseOnceWithEveryInvariantItBreaks()
    {
        // checked-cast: one port, two root causes (a non-finite and a huge coordinate both throw), several invariants each.
        string junit = Path.Combine(Directory.CreateTempSubdirectory("acphys-gate-").FullName, "findings.xml");
        var run = Acphys.Run(["verify", "--fault", "checked-cast", "--only", "LANDDEFS-CONFORMANCE,OUTSIDE-CELLS-CONFORMANCE,NONFINITE-REJECTED,ADJUST-RANGE", "--cases", "500", "--quiet", "--junit", junit]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Empty(Validate(File.ReadAllText(junit)));

        var suite = XDocument.Load(junit).Root!.Element("testsuite")!;
        string findings = suite.Element("system-out")!.Value;
        Assert.Contains("F1 [nonfinite] breaks ", findings, StringComparison.Ordinal);
        Assert.Contains("F2 [huge] breaks ", findings, StringComparison.Ordinal);
        Assert.Contains("NONFINITE-REJECTED (hardening, ", findings, StringComparison.Ordinal); // issue #29: the rule and its facts section
        Assert.Contains("LANDDEFS-CONFORMANCE (retail, ", findings, StringComparison.Ordinal);
        foreach (var failure in suite.Elements("testcase").Select(t => t.Element("failure")).OfType<XElement>())
        {
            Assert.Contains("finding:   F", failure.Value, StringComparison.Ordinal); // every failure says which root cause it is
        }

        var nonfiniteOnly = suite.Elements("testcase").Single(t => t.Attribute("name")!.Value == "NONFINITE-REJECTED").Element("failure")!.Value;
        Assert.DoesNotContain("[huge]", nonfiniteOnly, StringComparison.Ordinal);
    }

    [Fact]
    public void JunitXmlOfAPassingRunIsAcceptedByTheSchema()
    {
        string junit = Path.Combine(Directory.CreateTempSubdirectory("acphys-gate-").FullName, "pass.xml");
        var run = Acphys.Run(["verify", "--only", "ADJUST-RANGE,COVERAGE", "--cases", "200", "--quiet", "--junit", junit]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Empty(Validate(File.ReadAllText(junit)));
        Assert.Equal("0", XDocument.Load(junit).Root!.Attribute("failures")!.Value);
    }

    [Fact]
    public void SchemaRejectsMalformedJunit()
    {
        // The check can fail: a testcase without a name, and a count that is not a number.
        Assert.NotEmpty(Validate("<testsuites><testsuite name=\"s\" tests=\"1\"><testcase classname=\"c\"/></testsuite></testsuites>"));
        Assert.NotEmpty(Validate("<testsuites><testsuite name=\"s\" tests=\"many\"/></testsuites>"));
        Assert.NotEmpty(Validate("<testsuites><testsuite name=\"s\" tests=\"1\"><testcase name=\"t\"><skipped/><failure/></testcase></testsuite></testsuites>"));
    }

    [Fact]
    public void UnwritableOutputIsExit3()
    {
        var run = Acphys.Run(["verify", "--only", "ADJUST-RANGE", "--cases", "10", "--junit", "/proc/acphys/out.xml"]);
        Assert.True(run.Exit == 3, run.ToString());
        Assert.Contains("cannot write '/proc/acphys/out.xml'", run.Err, StringComparison.Ordinal);
    }

    private static List<string> Validate(string xml)
    {
        var schemas = new XmlSchemaSet();
        using (var reader = XmlReader.Create(Schema))
        {
            schemas.Add(null, reader);
        }

        var errors = new List<string>();
        var settings = new XmlReaderSettings { ValidationType = ValidationType.Schema, Schemas = schemas };
        settings.ValidationEventHandler += (_, e) => errors.Add($"{e.Severity}: {e.Message} (line {e.Exception?.LineNumber})");
        using var validating = XmlReader.Create(new StringReader(xml), settings);
        while (validating.Read())
        {
        }

        return errors;
    }
}
