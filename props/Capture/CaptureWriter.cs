using System.Globalization;
using System.Numerics;
using System.Text;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Capture;

/// <summary>
/// A capture writer of the tests' own, from the documented format (docs/corpus-format.md, "Captures"), not the tool's
/// reader: it walks a port as a client does (float32 position, find_cell from the cell it holds, a containing cell
/// re-frames the position, none keeps it) and prints each frame's line with the decimals asked.
/// </summary>
internal static class CaptureWriter
{
    /// <summary>A walk to record: start cell and block-frame point, the move per frame, the body (offset x, y, z, radius).</summary>
    /// <param name="Start">The start cell.</param>
    /// <param name="X">Start x, block frame.</param>
    /// <param name="Y">Start y.</param>
    /// <param name="Dx">Move per frame, x.</param>
    /// <param name="Dy">Move per frame, y.</param>
    /// <param name="Frames">Frames.</param>
    /// <param name="Body">Spheres: (offset x, offset y, offset z, r).</param>
    /// <param name="Decimals">Decimals printed.</param>
    public sealed record Plan(uint Start, float X, float Y, float Dx, float Dy, int Frames, (float X, float Y, float Z, float R)[] Body, int Decimals = 3);

    /// <summary>Writes the native capture (block frame, body header, radius and candidate columns) of a walk on a port.</summary>
    /// <param name="port">The port.</param>
    /// <param name="plan">The walk.</param>
    /// <param name="candidates">Whether to write the radius and candidate columns.</param>
    /// <returns>The text.</returns>
    public static string Native(ICellPhysics port, Plan plan, bool candidates = true)
    {
        var text = new StringBuilder("# a test's capture\n# frame: block\n# body: [");
        text.Append(string.Join(",", plan.Body.Select(b => string.Create(CultureInfo.InvariantCulture, $"{{\"x\":{b.X},\"y\":{b.Y},\"z\":{b.Z},\"r\":{b.R}}}"))));
        text.Append("]\n");
        foreach (var (i, cell, p, cells) in Walk(port, plan))
        {
            text.Append(CultureInfo.InvariantCulture, $"{i}\t0x{cell:X8}\t{F(p.X, plan.Decimals)}\t{F(p.Y, plan.Decimals)}\t{F(p.Z, plan.Decimals)}");
            if (candidates)
            {
                text.Append(CultureInfo.InvariantCulture, $"\t-\t{(cells.Count == 0 ? "none" : string.Join(",", cells.Select(c => $"0x{c.Value:X8}")))}");
            }

            text.Append('\n');
        }

        return text.ToString();
    }

    /// <summary>Writes the walk as acdream probe lines (world frame from <paramref name="origin"/>'s south-west corner, 3 decimals).</summary>
    /// <param name="port">The port.</param>
    /// <param name="plan">The walk (one sphere at the position).</param>
    /// <param name="origin">The world origin landblock, 0xAABB.</param>
    /// <returns>The text.</returns>
    public static string Acdream(ICellPhysics port, Plan plan, int origin)
    {
        var text = new StringBuilder("acdream starting\n");
        uint before = plan.Start;
        foreach (var (i, cell, p, cells) in Walk(port, plan))
        {
            double wx = (192.0 * ((cell >> 24) - (origin >> 8))) + p.X, wy = (192.0 * (((cell >> 16) & 0xFF) - (origin & 0xFF))) + p.Y;
            string pos = $"({F(wx, 3)},{F(wy, 3)},{F(p.Z, 3)})";
            text.Append(CultureInfo.InvariantCulture, $"[net] tick {i}\n[cellset-build] seed=0x{before:X8} sphere={pos} count={cells.Count} ids={string.Join(",", cells.Select(c => $"0x{c.Value:X8}"))}\n");
            if (cell != before)
            {
                text.Append(CultureInfo.InvariantCulture, $"[cell-transit] 0x{before:X8} -> 0x{cell:X8} pos={pos} reason=moved\n");
            }

            before = cell;
        }

        return text.ToString();
    }

    private static string F(double v, int decimals) => v.ToString("F" + decimals, CultureInfo.InvariantCulture);

    // The client's loop, written out here rather than borrowed from the tool (docs/protocol.md, "The threading rule").
    private static IEnumerable<(int Index, uint Cell, Vector3 Position, IReadOnlyList<CellId> Cells)> Walk(ICellPhysics port, Plan plan)
    {
        uint frame = plan.Start;
        var current = CellId.None;
        float x = plan.X, y = plan.Y, z = 0f;
        for (int i = 0; i < plan.Frames; i++)
        {
            if (i > 0)
            {
                x += plan.Dx;
                y += plan.Dy;
            }

            var spheres = plan.Body.Select(b => new Sphere(new Vector3(x + b.X, y + b.Y, z + b.Z), b.R)).ToArray();
            var answer = port.FindCell(new CellId(frame), new Vector3(x, y, z), spheres, current);
            if (!answer.Containing.IsNone)
            {
                uint c = answer.Containing.Value;
                x -= 192f * ((int)(c >> 24) - (int)(frame >> 24));
                y -= 192f * ((int)((c >> 16) & 0xFF) - (int)((frame >> 16) & 0xFF));
                frame = c;
                current = answer.Containing;
            }

            yield return (i, frame, new Vector3(x, y, z), answer.Cells);
        }
    }
}
