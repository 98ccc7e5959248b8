using System.Globalization;
using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Dat.Container;

namespace AcPhys.Spec.Running;

/// <summary>A stored indoor position: the env cell a live server stored beside it and the position in that cell's block frame.</summary>
/// <param name="Cell">The stored env cell.</param>
/// <param name="Position">The position (block frame, metres).</param>
public readonly record struct IndoorPosition(CellId Cell, Vector3 Position);

/// <summary>What the indoor real-data check found: rows by outcome (agrees, or the reason it could not or did not).</summary>
/// <param name="Rows">Rows checked.</param>
/// <param name="ByReason">Rows by outcome.</param>
/// <param name="Disagreements">The first rows that named another cell (row, the cell named), at most 20.</param>
public sealed record IndoorPositionResult(int Rows, IReadOnlyDictionary<string, int> ByReason, IReadOnlyList<(IndoorPosition Row, CellId Got)> Disagreements)
{
    /// <summary>The outcome of a row whose find_cell names the stored cell.</summary>
    public const string Agrees = "agrees";

    /// <summary>The outcome of a row whose find_cell names another cell (or none).</summary>
    public const string NamesAnother = "find_cell names another cell";

    /// <summary>Gets the number of rows that agree.</summary>
    public int Agreeing => ByReason.GetValueOrDefault(Agrees);

    /// <summary>Summarises the result, reasons by count.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"{Rows} indoor rows: ") + string.Join("; ", ByReason.OrderByDescending(r => r.Value).Select(r => string.Create(CultureInfo.InvariantCulture, $"{r.Key} {r.Value}")));
}

/// <summary>
/// The indoor rows of the real positions file as a real-data check over a dat world (docs/dat-container.md): for each
/// row, the scene of its block is extracted (whole block, once per block) and find_cell from the stored cell, with a
/// small sphere (radius <see cref="Radius"/>, centred that far above the stored position: an object's origin is its
/// base), must name the stored env cell as containing; a row that cannot be checked is counted by its reason.
/// </summary>
public static class IndoorPositionCheck
{
    /// <summary>The query sphere's radius and its height above the stored position, metres.</summary>
    public const float Radius = 0.1f;

    /// <summary>Checks rows.</summary>
    /// <param name="world">The dat world.</param>
    /// <param name="impl">The implementation (find_cell_scene).</param>
    /// <param name="rows">The rows.</param>
    /// <returns>The counts.</returns>
    public static IndoorPositionResult Run(DatWorld world, ICellPhysics impl, IEnumerable<IndoorPosition> rows)
    {
        var scenes = new Dictionary<LandblockId, (Scene? Scene, string? Why)>();
        var counts = new Dictionary<string, int>();
        var disagreements = new List<(IndoorPosition, CellId)>();
        int n = 0;
        foreach (var row in rows)
        {
            n++;
            string outcome = Check(world, impl, row, scenes, out var got);
            counts[outcome] = counts.GetValueOrDefault(outcome) + 1;
            if (outcome == IndoorPositionResult.NamesAnother && disagreements.Count < 20)
            {
                disagreements.Add((row, got));
            }
        }

        return new IndoorPositionResult(n, counts, disagreements);
    }

    private static string Check(DatWorld world, ICellPhysics impl, IndoorPosition row, Dictionary<LandblockId, (Scene? Scene, string? Why)> scenes, out CellId got)
    {
        got = default;
        var block = row.Cell.Landblock;
        if (!world.Cell.Contains(SceneExtraction.LandblockRecordId(block)))
        {
            return "block not in the cell dat";
        }

        if (!world.Cell.Contains(row.Cell.Value))
        {
            return "stored cell not in the cell dat";
        }

        if (!scenes.TryGetValue(block, out var s))
        {
            try
            {
                s = (SceneExtraction.Extract(world, new ScenePlace(block)).Scene, null);
            }
            catch (DatContainerException e)
            {
                s = (null, "scene refused: " + Reason(e.Message));
            }

            scenes[block] = s;
        }

        if (s.Scene is null)
        {
            return s.Why!;
        }

        if (!s.Scene.Cells.Any(c => c.Id == row.Cell))
        {
            return "stored cell not kept (over the cell limit or not numbered within numCells)";
        }

        var sphere = new Sphere(row.Position + new Vector3(0, 0, Radius), Radius);
        got = impl.FindCell(s.Scene, row.Cell, [sphere], row.Cell).Containing;
        return got == row.Cell ? IndoorPositionResult.Agrees : IndoorPositionResult.NamesAnother;
    }

    // The record reader's reason without the record's id and offset, so rows group by kind of refusal.
    private static string Reason(string message)
    {
        int at = message.LastIndexOf(": ", StringComparison.Ordinal);
        return at < 0 ? message : message[(at + 2)..];
    }
}
