using System.Text;
using AcPhys.Core;

namespace AcPhys.Cli.Render;

/// <summary>The <c>block 0xXXYY</c> label at the south-west corner of every landblock in view (WalkSvg, CaptureSvg).</summary>
internal static class BlockLabels
{
    /// <summary>Appends the labels.</summary>
    /// <param name="sb">The SVG being written.</param>
    /// <param name="minX">The view's west edge, world metres.</param>
    /// <param name="maxX">Its east edge.</param>
    /// <param name="minY">Its south edge.</param>
    /// <param name="maxY">Its north edge.</param>
    /// <param name="px">World x to pixels.</param>
    /// <param name="py">World y to pixels.</param>
    /// <param name="height">The drawing's height in pixels.</param>
    public static void Append(StringBuilder sb, double minX, double maxX, double minY, double maxY, Func<double, double> px, Func<double, double> py, double height)
    {
        for (double bx = Math.Floor(minX / 192) * 192; bx < maxX; bx += 192)
        {
            for (double by = Math.Floor(minY / 192) * 192; by < maxY; by += 192)
            {
                if (bx >= 0 && by >= 0 && bx / 192 <= LandDefs.MaxBlockByte && by / 192 <= LandDefs.MaxBlockByte)
                {
                    var id = new LandblockId((byte)(bx / 192), (byte)(by / 192));
                    sb.Append($"<text x=\"{SvgText.Num(Math.Max(px(bx), 0) + 3)}\" y=\"{SvgText.Num(Math.Min(py(by), height) - 4)}\" fill=\"#555\">block {id}</text>\n");
                }
            }
        }
    }
}
