using System.Globalization;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Props.Support;
using Xunit.Abstractions;

namespace AcPhys.Props.Data;

/// <summary>
/// Real positions from the public ACE world databases with the cell ids stored beside them
/// (../shared/data/README.md). Read in place, never copied into the project.
/// </summary>
public sealed class RetailPositionsTests(ITestOutputHelper output)
{
    private static readonly Lazy<IReadOnlyList<Row>> Rows = new(Load);

    [RequiresSharedDataFact(DisplayName = "Real data: every outdoor row agrees with AdjustToOutside except the documented 47, each in a mechanical class")]
    public void OutdoorRowsAgree()
    {
        var outdoor = Rows.Value.Where(r => r.Kind == "outdoor").ToList();
        var disagree = new List<(Row Row, CellId Got, string Class)>();
        foreach (var row in outdoor)
        {
            var got = Adjust(row.Stored, row.X, row.Y);
            if (got != row.Stored)
            {
                disagree.Add((row, got, Classify(row)));
            }
        }

        int agree = outdoor.Count - disagree.Count;
        output.WriteLine($"outdoor rows {outdoor.Count}: agree {agree} ({100.0 * agree / outdoor.Count:F2} %), disagree {disagree.Count}");
        foreach (var group in disagree.GroupBy(d => d.Class).OrderBy(g => g.Key))
        {
            output.WriteLine($"  {group.Key}: {group.Count()}");
            foreach (var d in group)
            {
                output.WriteLine($"    {d.Row.Stored} ({d.Row.XText}, {d.Row.YText}) -> {d.Got}  [{d.Row.Ref}]");
            }
        }

        Assert.Equal(5824, outdoor.Count);   // data/README.md: 5,824 unique outdoor rows
        Assert.Equal(5777, agree);           // data/README.md: 5,777 agree (99.19 %)
        Assert.DoesNotContain(disagree, d => d.Class == "unexplained");
    }

    [RequiresSharedDataFact(DisplayName = "Real data: AdjustToOutside reproduces the file's expected_cell_id on every outdoor row")]
    public void OutdoorRowsMatchExpectedColumn()
    {
        var outdoor = Rows.Value.Where(r => r.Kind == "outdoor").ToList();
        var mismatches = outdoor.Where(r => Adjust(r.Stored, r.X, r.Y) != r.Expected).ToList();
        output.WriteLine($"outdoor rows {outdoor.Count}, mismatches with expected_cell_id {mismatches.Count}");
        Assert.Empty(mismatches.Select(r => $"{r.Stored} ({r.XText}, {r.YText}) expected {r.Expected}"));
    }

    [RequiresSharedDataFact(DisplayName = "Real data: every landblock_only row, re-seated from its block id 0xXXYYFFFF, lands in expected_cell_id")]
    public void LandblockOnlyRowsResolve()
    {
        var rows = Rows.Value.Where(r => r.Kind == "landblock_only").ToList();
        var mismatches = rows.Where(r => Adjust(r.Stored.Landblock.BlockCell, r.X, r.Y) != r.Expected).ToList();
        output.WriteLine($"landblock_only rows {rows.Count}, mismatches {mismatches.Count}");
        Assert.True(rows.Count > 40_000);
        Assert.Empty(mismatches.Select(r => $"{r.Stored} ({r.XText}, {r.YText}) expected {r.Expected}"));
    }

    [RequiresSharedDataFact(DisplayName = "Real data: stored ids classify as the file says (outdoor = land low word, indoor = env low word)")]
    public void KindsClassify()
    {
        var indoor = Rows.Value.Where(r => r.Kind == "indoor").ToList();
        var outdoor = Rows.Value.Where(r => r.Kind == "outdoor").ToList();
        output.WriteLine($"indoor rows {indoor.Count}, outdoor rows {outdoor.Count}");
        Assert.All(indoor, r => Assert.True(r.Stored.IsEnv && r.Stored.IsIndoorByLowWord, r.Stored.ToString()));
        Assert.All(outdoor, r => Assert.True(r.Stored.IsLand && !r.Stored.IsIndoorByLowWord, r.Stored.ToString()));
    }

    private static CellId Adjust(CellId id, float x, float y)
    {
        LandDefs.AdjustToOutside(ref id, ref x, ref y);
        return id;
    }

    // data/README.md groups: the (0,0,0) placeholder; a point on a 24 m line that touches the stored cell
    // (within 1e-3 m); or a point more than 1e-3 m from the stored cell's square (just across a line, or plain wrong).
    private static string Classify(Row row)
    {
        if (row.X == 0 && row.Y == 0 && row.Z == 0)
        {
            return "placeholder (0,0,0)";
        }

        int idx = row.Stored.Low - 1;
        double west = 24.0 * (idx / 8), south = 24.0 * (idx % 8);
        double dx = Math.Max(Math.Max(west - row.X, row.X - (west + 24)), 0);
        double dy = Math.Max(Math.Max(south - row.Y, row.Y - (south + 24)), 0);
        double distance = Math.Sqrt((dx * dx) + (dy * dy));
        bool onLine = NearLine(row.X) || NearLine(row.Y);
        if (distance <= 1e-3)
        {
            return onLine ? "on a line, stored cell touches the point" : "unexplained";
        }

        return "far from the stored cell (> 1e-3 m)";
    }

    private static bool NearLine(double v) => Math.Abs(v - (24 * Math.Round(v / 24))) <= 1e-3;

    private static List<Row> Load()
    {
        var rows = new List<Row>();
        using var reader = new StreamReader(RequiresSharedDataFactAttribute.DataFile);
        var header = reader.ReadLine()!.Split('\t');
        int Col(string name) => Array.IndexOf(header, name) is var i and >= 0 ? i : throw new InvalidDataException("column " + name + " missing");
        int cId = Col("obj_cell_id"), cX = Col("x"), cY = Col("y"), cZ = Col("z"), cKind = Col("kind"), cExp = Col("expected_cell_id"), cRef = Col("ref");
        for (string? line = reader.ReadLine(); line is not null; line = reader.ReadLine())
        {
            var f = line.Split('\t');
            Assert.True(CellIdText.TryParse(f[cId], out var stored), "bad id " + f[cId]);
            CellIdText.TryParse(f[cExp], out var expected);
            rows.Add(new Row(stored, expected, Parse(f[cX]), Parse(f[cY]), Parse(f[cZ]), f[cKind], f[cX], f[cY], f[cRef]));
        }

        return rows;
    }

    private static float Parse(string s) => float.Parse(s, NumberStyles.Float, CultureInfo.InvariantCulture);

    private sealed record Row(CellId Stored, CellId Expected, float X, float Y, float Z, string Kind, string XText, string YText, string Ref);
}
