using System.Globalization;
using System.Numerics;
using System.Text;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Capture;

/// <summary>
/// An indoor capture writer of the tests' own, from the documented format (docs/corpus-format.md, "Captures"), not the
/// tool's reader: a client's loop in a scene (find_cell_scene from the cell it holds, current cell that cell, float32
/// position in its block frame; a containing cell re-frames the position, none keeps it), each frame printed as
/// <c>frame cell x y z</c> in the cell's block frame with the decimals asked, the body in the header.
/// </summary>
internal static class SceneCaptureWriter
{
    /// <summary>The corpus cottages' body: two spheres of radius 0.5 at 0.6 and 1.3 m.</summary>
    public static readonly (float X, float Y, float Z, float R)[] Cottager = [(0, 0, 0.6f, 0.5f), (0, 0, 1.3f, 0.5f)];

    /// <summary>Walks a port through a scene and writes the capture.</summary>
    /// <param name="port">The port.</param>
    /// <param name="scene">The scene it walks in.</param>
    /// <param name="start">The start cell.</param>
    /// <param name="x">Start x in the start cell's block frame.</param>
    /// <param name="y">Start y.</param>
    /// <param name="moves">One move per frame after the first.</param>
    /// <param name="cells">The port's cell after each frame, as written.</param>
    /// <param name="decimals">Decimals printed.</param>
    /// <returns>The capture text.</returns>
    public static string Native(ICellPhysics port, Scene scene, uint start, float x, float y, IReadOnlyList<Vector2> moves, out List<uint> cells, int decimals = 3)
    {
        var text = new StringBuilder("# an indoor capture of the tests' own\n# frame: block\n# body: [");
        text.Append(string.Join(",", Cottager.Select(b => string.Create(CultureInfo.InvariantCulture, $"{{\"x\":{b.X},\"y\":{b.Y},\"z\":{b.Z},\"r\":{b.R}}}"))));
        text.Append("]\n");
        cells = [];
        uint frame = start;
        var current = CellId.None;
        for (int i = 0; i <= moves.Count; i++)
        {
            if (i > 0)
            {
                x += moves[i - 1].X;
                y += moves[i - 1].Y;
            }

            var spheres = Cottager.Select(b => new Sphere(new Vector3(x + b.X, y + b.Y, b.Z), b.R)).ToArray();
            var answer = port.FindCell(scene, new CellId(frame), spheres, current);
            if (!answer.Containing.IsNone)
            {
                uint c = answer.Containing.Value;
                x -= 192f * ((int)(c >> 24) - (int)(frame >> 24));
                y -= 192f * ((int)((c >> 16) & 0xFF) - (int)((frame >> 16) & 0xFF));
                frame = c;
                current = answer.Containing;
            }

            cells.Add(frame);
            text.Append(CultureInfo.InvariantCulture, $"{i}\t0x{frame:X8}\t{F(x, decimals)}\t{F(y, decimals)}\t{F(0, decimals)}\n");
        }

        return text.ToString();
    }

    /// <summary>Returns <paramref name="n"/> equal moves.</summary>
    /// <param name="n">How many.</param>
    /// <param name="dx">Each move's x.</param>
    /// <param name="dy">Each move's y.</param>
    /// <returns>The moves.</returns>
    public static IEnumerable<Vector2> Moves(int n, float dx, float dy) => Enumerable.Repeat(new Vector2(dx, dy), n);

    private static string F(double v, int decimals) => v.ToString("F" + decimals, CultureInfo.InvariantCulture);
}
