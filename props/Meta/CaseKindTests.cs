using System.Reflection;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Props.Corpus;
using AcPhys.Spec.Judging;

namespace AcPhys.Props.Meta;

/// <summary>
/// Issue 42: a case kind is handled everywhere. The compiler checks what goes through <see cref="AnyCase.Match{T}"/> and
/// <see cref="CaseKinds.Pick{T}"/>; this checks the rest at run time, for every value of <see cref="CaseKind"/>.
/// </summary>
public sealed class CaseKindTests
{
    [Fact(DisplayName = "CASE-KINDS-CLOSED: every case kind has exactly one AnyCase subtype, and every subtype is of a distinct kind")]
    public void EveryKindHasOneSubtype()
    {
        var subtypes = typeof(AnyCase).GetNestedTypes(BindingFlags.Public).Where(t => t.IsSubclassOf(typeof(AnyCase))).ToArray();
        var kinds = OneOfEachKind().ToDictionary(c => c.Kind, c => c.GetType());
        Assert.Equal(Enum.GetValues<CaseKind>().Order(), kinds.Keys.Order());
        Assert.Equal(subtypes.OrderBy(t => t.Name, StringComparer.Ordinal), kinds.Values.OrderBy(t => t.Name, StringComparer.Ordinal));
    }

    [Fact(DisplayName = "CASE-KINDS-HANDLED: a case of every kind has a distinct file kind, round-trips through the corpus format and is judged by its kind's judges")]
    public void EveryKindIsStoredAndJudged()
    {
        var names = new HashSet<string>(StringComparer.Ordinal);
        foreach (var c in OneOfEachKind())
        {
            string name = CorpusEntry.KindName(c.Kind);
            Assert.True(names.Add(name), $"{c.Kind}: file kind '{name}' is used twice");
            var entry = CorpusEntry.From(c, "case kind " + name, null, "props") ?? throw new InvalidOperationException($"{c.Kind}: no corpus entry");
            Assert.Equal(name, entry.Kind);
            var back = CorpusJson.Read(CorpusJson.Write(entry), name).Item;
            Assert.Equal(c.Kind, back.Kind);
            Assert.Equal(CorpusJson.Write(entry), CorpusJson.Write(CorpusEntry.From(back, "case kind " + name, null, "props")!));
            Assert.NotEmpty(Judges.For(c.Kind));
            Assert.Equal(Judges.For(c.Kind).Select(i => i.Id), Judges.Judge(ReferenceAdapter.Instance, back).Verdicts.Select(v => v.Invariant.Id));
        }
    }

    private static IEnumerable<AnyCase> OneOfEachKind() => JudgesTests.OneOfEachKind();
}
