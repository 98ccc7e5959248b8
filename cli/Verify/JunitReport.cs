using System.Globalization;
using System.Text;
using System.Xml;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// Renders a run as JUnit XML in the common Ant / Jenkins shape (schemas/junit-10.xsd): one <c>testsuite</c>, one
/// <c>testcase</c> per invariant; a violation is a <c>failure</c> carrying the shrunk case, the replay line and the
/// findings (root causes, issue #18) it belongs to, a missing operation is <c>skipped</c>; the suite's
/// <c>system-out</c> lists the findings, so a CI page shows one root cause once, with every invariant it breaks.
/// </summary>
internal static class JunitReport
{
    /// <summary>Renders the XML.</summary>
    /// <param name="run">The run.</param>
    /// <returns>The document text (UTF-8 declaration).</returns>
    public static string Render(GateRun run)
    {
        var settings = new XmlWriterSettings { Indent = true, Encoding = new UTF8Encoding(false), NewLineChars = "\n" };
        using var buffer = new MemoryStream();
        using (var xml = XmlWriter.Create(buffer, settings))
        {
            string suite = X("acphys verify: " + run.ImplName);
            xml.WriteStartDocument();
            xml.WriteStartElement("testsuites");
            xml.WriteAttributeString("name", suite);
            Counts(xml, run);
            xml.WriteStartElement("testsuite");
            xml.WriteAttributeString("name", suite);
            Counts(xml, run);
            xml.WriteAttributeString("timestamp", DateTime.UtcNow.ToString("yyyy-MM-ddTHH:mm:ss", CultureInfo.InvariantCulture));
            xml.WriteAttributeString("hostname", "localhost");
            xml.WriteStartElement("properties");
            Property(xml, "implementation", run.ImplName);
            Property(xml, "profile", run.Settings.Profile.Name);
            Property(xml, "cases-per-invariant", run.Settings.Profile.CasesPerInvariant.ToString(CultureInfo.InvariantCulture));
            Property(xml, "seed", run.SeedText);
            if (run.UnknownOps.Count > 0)
            {
                Property(xml, "unknown-ops", "warning: the implementation announced ops protocol v1 does not know (ignored): " + run.UnknownOpsText);
            }

            xml.WriteEndElement();

            var findings = Findings.Of(run.Results);
            foreach (var r in run.Results)
            {
                xml.WriteStartElement("testcase");
                xml.WriteAttributeString("name", r.Invariant.Id);
                xml.WriteAttributeString("classname", "acphys.invariants");
                xml.WriteAttributeString("time", Seconds(r.Elapsed));
                switch (r.Status)
                {
                    case ResultStatus.Failed:
                        xml.WriteStartElement("failure");
                        xml.WriteAttributeString("message", X($"{r.Invariant.Id}: {r.Violation?.Message ?? "violated"}"));
                        xml.WriteAttributeString("type", "InvariantViolated");
                        xml.WriteString(X(FailureText(r, run.Failures.GetValueOrDefault(r.Invariant.Id)) + FindingsOf(r.Invariant.Id, findings)));
                        xml.WriteEndElement();
                        break;
                    case ResultStatus.NotTested:
                        xml.WriteStartElement("skipped");
                        xml.WriteAttributeString("message", X("not tested: " + (r.NotTestedReason ?? "the implementation lacks an operation it needs")));
                        xml.WriteEndElement();
                        break;
                }

                xml.WriteStartElement("system-out");
                xml.WriteString($"{r.Invariant.Statement}\ncases {r.Cases}, applicable {r.Applicable}, exhaustive {r.ExhaustiveCases}, seed {r.Seed}\n");
                xml.WriteEndElement();
                xml.WriteEndElement();
            }

            if (run.TooFewTested)
            {
                // A run that tested (almost) nothing is a failure of the gate itself, so a JUnit consumer turns red too.
                xml.WriteStartElement("testcase");
                xml.WriteAttributeString("name", "MIN-TESTED");
                xml.WriteAttributeString("classname", "acphys.gate");
                xml.WriteAttributeString("time", Seconds(TimeSpan.Zero));
                xml.WriteStartElement("failure");
                xml.WriteAttributeString("message", X(run.TooFewTestedText));
                xml.WriteAttributeString("type", "TooFewTested");
                xml.WriteString(X(run.TooFewTestedText + "\n"));
                xml.WriteEndElement();
                xml.WriteEndElement();
            }

            if (findings.Count > 0)
            {
                xml.WriteStartElement("system-out");
                xml.WriteString(X(FindingsText.Plain(findings)));
                xml.WriteEndElement();
            }

            xml.WriteEndElement();
            xml.WriteEndElement();
            xml.WriteEndDocument();
        }

        return Encoding.UTF8.GetString(buffer.ToArray());
    }

    private static string FailureText(InvariantResult r, FailureDetail? detail)
    {
        var text = new StringBuilder();
        text.Append("statement: ").Append(r.Invariant.Statement).Append('\n');
        if (r.Violation is { } v)
        {
            text.Append("shrunk:    ").Append(v.CaseText).Append('\n');
            text.Append("message:   ").Append(v.Message).Append('\n');
        }

        if (r.Original is { } o && o != r.Violation)
        {
            text.Append("original:  ").Append(o.CaseText).Append('\n');
        }

        text.Append("seed:      ").Append(r.Seed.ToString()).Append('\n');
        if (detail is not null)
        {
            text.Append("replay:    ").Append(detail.ReplayLine).Append('\n');
            if (detail.CaseReplay is not null)
            {
                text.Append("case file: ").Append(detail.CaseFile).Append('\n');
                text.Append("replay:    ").Append(detail.CaseReplay).Append('\n');
            }
        }

        return text.ToString();
    }

    // The findings an invariant's failures belong to, by their number in the suite's findings list.
    private static string FindingsOf(string id, IReadOnlyList<Finding> findings)
    {
        var text = new StringBuilder();
        for (int i = 0; i < findings.Count; i++)
        {
            if (findings[i].Invariants.Contains(id, StringComparer.Ordinal))
            {
                text.Append($"finding:   F{i + 1} [{findings[i].Cause}] breaks {string.Join(", ", findings[i].Invariants)}\n");
            }
        }

        return text.ToString();
    }

    private static void Counts(XmlWriter xml, GateRun run)
    {
        int gate = run.TooFewTested ? 1 : 0;
        xml.WriteAttributeString("tests", (run.Results.Count + gate).ToString(CultureInfo.InvariantCulture));
        xml.WriteAttributeString("failures", (run.Failed + gate).ToString(CultureInfo.InvariantCulture));
        xml.WriteAttributeString("errors", "0");
        xml.WriteAttributeString("skipped", run.NotTested.ToString(CultureInfo.InvariantCulture));
        xml.WriteAttributeString("time", Seconds(run.Elapsed));
    }

    // Every text of a report passes here: an implementation's control characters never reach (or break) the XML (issue 28).
    private static string X(string text) => AcPhys.Formats.Values.InputQuote.Escape(text, keepLines: true);

    private static void Property(XmlWriter xml, string name, string value)
    {
        xml.WriteStartElement("property");
        xml.WriteAttributeString("name", name);
        xml.WriteAttributeString("value", X(value));
        xml.WriteEndElement();
    }

    private static string Seconds(TimeSpan t) => t.TotalSeconds.ToString("0.000", CultureInfo.InvariantCulture);
}
