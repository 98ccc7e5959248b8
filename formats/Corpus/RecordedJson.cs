using System.Text.Json;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// The optional <c>recorded</c> array of a walk file (docs/corpus-format.md): one <c>{"cell": "0x…", "cells": [...]}</c>
/// per query of the walk (the start, then each step), the port's answers as a capture recorded them (<c>cells</c>
/// optional). Strict: the count must be the walk's, no other field, every id <c>0x</c> and 8 hex digits.
/// </summary>
internal static class RecordedJson
{
    /// <summary>The most candidates one recorded answer may hold.</summary>
    public const int MaxCells = 1024;

    /// <summary>Writes the array as the property <c>recorded</c>.</summary>
    /// <param name="w">The writer, inside the entry object.</param>
    /// <param name="recorded">The answers.</param>
    public static void Write(Utf8JsonWriter w, IReadOnlyList<RecordedAnswer> recorded)
    {
        w.WriteStartArray("recorded");
        foreach (var a in recorded)
        {
            w.WriteStartObject();
            w.WriteString("cell", CellIdText.Format(a.Cell));
            if (a.Cells is { } cells)
            {
                w.WriteStartArray("cells");
                foreach (var c in cells)
                {
                    w.WriteStringValue(CellIdText.Format(c));
                }

                w.WriteEndArray();
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
    }

    /// <summary>Reads and validates the array.</summary>
    /// <param name="e">The <c>recorded</c> element.</param>
    /// <param name="queries">How many queries the walk makes (steps + 1).</param>
    /// <param name="source">File name for messages.</param>
    /// <returns>The answers.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path.</exception>
    public static IReadOnlyList<RecordedAnswer> Read(JsonElement e, int queries, string source)
    {
        CorpusJson.Require(e.ValueKind == JsonValueKind.Array, source, "$.recorded", "expected an array of recorded answers, one per query");
        CorpusJson.Require(e.GetArrayLength() == queries, source, "$.recorded", $"{e.GetArrayLength()} recorded answers for a walk of {queries} queries (the start and one per step): expected one per query");
        var answers = new List<RecordedAnswer>(queries);
        int i = 0;
        foreach (var a in e.EnumerateArray())
        {
            string at = $"$.recorded[{i}]";
            CorpusJson.Require(a.ValueKind == JsonValueKind.Object, source, at, "expected {\"cell\": \"0x…\"} with an optional \"cells\": [...]");
            foreach (var p in a.EnumerateObject())
            {
                CorpusJson.Require(p.Name is "cell" or "cells", source, at + "." + AcPhys.Formats.Values.InputQuote.Brief(p.Name), "unknown field (known: cell, cells)");
            }

            var cell = Id(CorpusJson.Prop(a, "cell", source, at), source, at + ".cell");
            IReadOnlyList<Core.CellId>? cells = null;
            if (a.TryGetProperty("cells", out var list))
            {
                CorpusJson.Require(list.ValueKind == JsonValueKind.Array && list.GetArrayLength() <= MaxCells, source, at + ".cells", $"expected an array of at most {MaxCells} cell ids");
                cells = [.. list.EnumerateArray().Select((c, k) => Id(c, source, $"{at}.cells[{k}]"))];
            }

            answers.Add(new RecordedAnswer(cell, cells));
            i++;
        }

        return answers;
    }

    private static Core.CellId Id(JsonElement e, string source, string at)
    {
        CorpusJson.Require(e.ValueKind == JsonValueKind.String, source, at, "expected a cell id string \"0x\" and 8 hex digits");
        string text = CorpusJson.Text(e, source, at);
        CorpusJson.Require(CellIdText.TryParse(text, out var id), source, at, $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(text)}\"");
        return id;
    }
}
