using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;

namespace AcPhys.Props.Corpus;

/// <summary>The one registry that decides which invariants judge a case of each kind (<see cref="Judges"/>), and the query codec.</summary>
public sealed class JudgesTests
{
    [Fact(DisplayName = "JUDGES-COVER: every catalogue invariant judges some case kind whose value it checks, so any failure it finds has a file that replays to it")]
    public void EveryInvariantJudgesAKind()
    {
        foreach (var invariant in InvariantCatalogue.All)
        {
            var kinds = Judges.KindsOf(invariant);
            Assert.True(kinds.Count > 0, $"{invariant.Id} judges no case kind: a failure it finds would replay as 'no violation'");
            Assert.Contains(kinds, k => Fits(k, invariant.CaseType));
        }
    }

    [Fact(DisplayName = "JUDGES-ORDER: judging a case asks exactly the judges its kind lists, in that order")]
    public void JudgeAsksTheListedJudges()
    {
        foreach (var c in OneOfEachKind())
        {
            var judgement = Judges.Judge(ReferenceAdapter.Instance, c);
            Assert.Equal(Judges.For(c.Kind).Select(i => i.Id), judgement.Verdicts.Select(v => v.Invariant.Id));
            Assert.False(judgement.IsViolation, $"{c.Kind}: {string.Join("; ", judgement.Violations)}");
        }
    }

    [Theory(DisplayName = "REPLAY-UNJUDGEABLE: a walk from a start that is not a land cell is vacuous for the walk invariants on the reference, never violated")]
    [InlineData(0x00000000u)]
    [InlineData(0xFFFFFFFFu)]
    [InlineData(0xA9B40077u)]
    public void WalkFromANonCellIsVacuous(uint start)
    {
        var walk = new Walk(new CellId(start), new Vector3(100, 100, 0), [new BodySphere(new Vector3(0, 0, 0.5f), 0.5f)], [new Vector2(30, 0), new Vector2(0, 30)]);
        var judgement = Judges.Judge(ReferenceAdapter.Instance, walk);
        Assert.Empty(judgement.Violations);
        Assert.All(judgement.Verdicts.Where(v => WalkInvariants.All.Contains(v.Invariant)), v => Assert.Equal(Verdict.Vacuous, v.Outcome?.Verdict));
    }

    [Fact(DisplayName = "QUERY-CODEC: a query is stored as asked (any id, no spheres, NaN and infinities) and read back equal")]
    public void QueryRoundTrips()
    {
        var queries = new[]
        {
            new OutdoorCase(CellId.None, []) { Origin = new Vector3(1.5f, -0f, 3) },
            new OutdoorCase(new CellId(0xFFFFFFFF), [new Sphere(new Vector3(float.NaN, float.PositiveInfinity, 1e-45f), -0f)]),
            new OutdoorCase(new CellId(0xA9B40031), [new Sphere(new Vector3(23.999998f, 0.1f, 0), 0.48f), new Sphere(new Vector3(24, 0.1f, 1.2f), 0.48f)]) { Origin = new Vector3(23.999998f, 0.1f, 0) },
        };
        foreach (var q in queries)
        {
            var entry = CorpusEntry.From(q, "t", "FIND-CELL-QUERY-CONFORMANCE", FinderNames.Verify)!;
            string text = CorpusJson.Write(entry);
            var back = CorpusJson.Read(text, "query");
            Assert.Equal("query", back.Kind);
            Assert.Equal(q.ToString() + " origin " + q.Origin, back.Query!.ToString() + " origin " + back.Query.Origin);
            Assert.Equal(text, CorpusJson.Write(back));
        }
    }

    private static bool Fits(CaseKind kind, Type caseType) => kind switch
    {
        CaseKind.Land => caseType == typeof(LandCase),
        CaseKind.Query => caseType == typeof(OutdoorCase),
        CaseKind.Walk => caseType == typeof(Walk) || caseType == typeof(OutdoorCase) || caseType == typeof(AnyWalk),
        CaseKind.SceneWalk => caseType == typeof(SceneWalk) || caseType == typeof(AnyWalk),
        CaseKind.Parts => caseType == typeof(PartsCase),
        _ => false,
    };

    /// <summary>Returns one case of each kind (CaseKindTests checks every kind is here).</summary>
    /// <returns>The cases.</returns>
    internal static IEnumerable<AnyCase> OneOfEachKind()
    {
        yield return new LandCase(new CellId(0xA9B40031), 30.5f, 12f, new Lcoord(1354, 1444));
        yield return new OutdoorCase(new CellId(0xA9B40031), [new Sphere(new Vector3(30.5f, 12f, 0.5f), 0.5f)]);
        yield return new Walk(new CellId(0xA9B40031), new Vector3(30.5f, 12f, 0), [new BodySphere(new Vector3(0, 0, 0.5f), 0.5f)], [new Vector2(10, 0)]);
        foreach (var kind in new[] { "scene-walk", "parts" })
        {
            yield return Directory.EnumerateFiles(RepoPaths.Corpus, "*.json", SearchOption.AllDirectories).Order(StringComparer.Ordinal)
                .Select(f => CorpusJson.ReadFile(f)).First(e => e.Kind == kind).Item;
        }
    }
}
