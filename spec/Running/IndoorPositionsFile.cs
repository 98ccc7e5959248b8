using System.Globalization;
using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Running;

/// <summary>
/// Reads the indoor rows of a real positions file (../shared/data/retail-positions.tsv: tab-separated with a header;
/// columns <c>obj_cell_id</c> (0x hex), <c>x</c>, <c>y</c>, <c>z</c>, <c>kind</c>). Rows that do not parse are skipped and counted.
/// </summary>
public static class IndoorPositionsFile
{
    /// <summary>Reads the indoor rows.</summary>
    /// <param name="path">The file.</param>
    /// <param name="skipped">Rows of kind indoor that did not parse.</param>
    /// <returns>The rows.</returns>
    /// <exception cref="FormatException">The header lacks a needed column.</exception>
    public static List<IndoorPosition> Read(string path, out int skipped)
    {
        using var reader = new StreamReader(path);
        var header = (reader.ReadLine() ?? string.Empty).Split('\t');
        int Col(string name) => Array.IndexOf(header, name) is int i and >= 0 ? i : throw new FormatException($"{path}: no column '{name}' in the header");
        int cCell = Col("obj_cell_id"), cX = Col("x"), cY = Col("y"), cZ = Col("z"), cKind = Col("kind");
        var rows = new List<IndoorPosition>();
        skipped = 0;
        while (reader.ReadLine() is { } line)
        {
            var f = line.Split('\t');
            if (f.Length <= Math.Max(cKind, Math.Max(cCell, Math.Max(cX, Math.Max(cY, cZ)))) || f[cKind] != "indoor")
            {
                continue;
            }

            string id = f[cCell].StartsWith("0x", StringComparison.OrdinalIgnoreCase) ? f[cCell][2..] : f[cCell];
            if (uint.TryParse(id, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint cell)
                && float.TryParse(f[cX], NumberStyles.Float, CultureInfo.InvariantCulture, out float x)
                && float.TryParse(f[cY], NumberStyles.Float, CultureInfo.InvariantCulture, out float y)
                && float.TryParse(f[cZ], NumberStyles.Float, CultureInfo.InvariantCulture, out float z))
            {
                rows.Add(new IndoorPosition(new CellId(cell), new Vector3(x, y, z)));
            }
            else
            {
                skipped++;
            }
        }

        return rows;
    }
}
