using System.Globalization;
using System.Numerics;
using System.Text;
using AcPhys.Core;

namespace AcPhys.Bench;

/// <summary>
/// Outdoor capture text for the capture benchmarks: a body (r = 0.48) walking a long zig-zag over open land from
/// 0xA9B40031, 0.15 m a frame, each frame answered by the reference as a client threads it (the cell it holds, the
/// position re-framed), printed as native capture lines with 3 decimals and the candidate column.
/// </summary>
internal static class CaptureFrames
{
    /// <summary>Writes the capture.</summary>
    /// <param name="frames">How many frames.</param>
    /// <param name="output">Where the text goes.</param>
    public static void Write(int frames, TextWriter output)
    {
        output.Write("# frame: block\n# radius: 0.48\n");
        var array = new CellArray();
        var cell = new CellId(0xA9B40031);
        var current = CellId.None;
        var p = new Vector3(150, 12, 0);
        var line = new StringBuilder(128);
        Sphere[] body = [new(p, 0.48f)];
        for (int i = 0; i < frames; i++)
        {
            // 2,000-frame legs (300 m) turning through eight headings: it crosses cell and block lines in every direction.
            double heading = Math.PI / 4 * ((i / 2000) % 8) + 0.3;
            p += new Vector3((float)(0.15 * Math.Cos(heading)), (float)(0.15 * Math.Sin(heading)), 0);
            body[0] = new Sphere(p, 0.48f);
            var containing = CellQuery.FindCellListOutdoor(array, cell, p, body, current, PickPolicy.Retail, OpenLand.Instance);
            if (!containing.IsNone)
            {
                p -= LandDefs.GetBlockOffset(cell, containing);
                cell = current = containing;
            }

            line.Clear();
            line.Append(CultureInfo.InvariantCulture, $"{i}\t0x{cell.Value:X8}\t{p.X:F3}\t{p.Y:F3}\t{p.Z:F3}\t-\t");
            for (int k = 0; k < array.Count; k++)
            {
                line.Append(k == 0 ? string.Empty : ",").Append(CultureInfo.InvariantCulture, $"0x{array[k].Id.Value:X8}");
            }

            output.Write(line.Append('\n'));
        }
    }

    /// <summary>Returns the capture as UTF-8 bytes.</summary>
    /// <param name="frames">How many frames.</param>
    /// <returns>The bytes.</returns>
    public static byte[] Bytes(int frames)
    {
        using var buffer = new MemoryStream();
        using (var w = new StreamWriter(buffer, new UTF8Encoding(false), 1 << 16))
        {
            Write(frames, w);
        }

        return buffer.ToArray();
    }
}
