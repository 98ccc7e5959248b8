using System.Text;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;
using static AcPhys.Cli.Render.SvgText;

namespace AcPhys.Cli.Render;

/// <summary>
/// Draws a checked scene walk as SVG in world metres, north up, on the 24 m land-cell grid with the 192 m block lines
/// labelled: blocks that are not loaded shaded; every env cell's footprint (<see cref="SceneFootprint"/>, one group of
/// class <c>cell-outline</c> per cell, upper storeys dashed, each labelled with its z range); every cell portal as a
/// thick segment (class <c>portal exit</c>, <c>portal inter</c> or <c>portal hint</c>, labelled with index, target and
/// PortalSide) and every building portal (class <c>bld-portal</c>) over the portal it names; building origins; the
/// path of sphere 0 with one marker per step in its containing cell's colour (circle indoors, square outdoors); and the
/// first violating step in red. The root carries <c>data-world-left</c>, <c>data-world-top</c> and <c>data-px-per-m</c>
/// so a reader can map drawing coordinates back to world metres.
/// </summary>
internal static class SceneSvg
{
    private const double MaxScale = 32; // pixels per metre at most; shrunk for large scenes
    private const double MaxPixels = 1400;
    private const double MinPixels = 720;
    private const double Header = 70;
    private const double Line = 14;
    private const int MaxRows = 64;
    private const double CharPixels = 6.7; // one monospace character at font-size 11
    private const string CellsKey = "cells: filled outline per env cell (dashed: upper storey), label id and z range; steps: circle = indoor, square = outdoor, coloured by containing cell";
    private const string PortalsKey = "portals: orange = exit, teal = between cells, grey = into an unloaded cell, black dashes = building portal; pN→target ps=PortalSide (1: cell on the plane's negative side)";
    private const double Pad = 4; // metres of margin around the cells, buildings and path
    private const double PortalInset = 3.5; // pixels: a portal is drawn this far inside its own cell, so both sides show

    /// <summary>Renders the SVG document.</summary>
    /// <param name="sw">The scene walk.</param>
    /// <param name="check">Its trace and violations.</param>
    /// <param name="title">A caption.</param>
    /// <returns>The SVG text.</returns>
    public static string Render(SceneWalk sw, CaseRun check, string title)
    {
        var scene = sw.Scene;
        var colours = new CellColours(scene);
        var cells = scene.Cells.Select(SceneFootprint.Of).ToList();
        var portals = scene.Cells.SelectMany(c => c.Portals.Select((_, i) => SceneFootprint.Portal(c, i))).ToList();
        var centres = check.Trace.Select(s => SceneOracle.World(s.Query.Cell, s.Query.Spheres[0].Center)).Select(p => new WorldPoint(p.X, p.Y)).ToList();
        var origins = scene.Buildings.Select(b => SceneFootprint.World(b.Block.BlockCell, b.Origin.X, b.Origin.Y)).ToList();

        var all = centres.Concat(origins).Concat(cells.SelectMany(c => c.Pieces.SelectMany(p => p))).ToList();
        double reach = sw.Walk.Body.Select(b => Math.Max(Math.Abs(b.Offset.X), Math.Abs(b.Offset.Y)) + b.Radius).DefaultIfEmpty(0).Max();
        double minX = Math.Floor(all.Min(p => p.X) - reach - Pad), maxX = Math.Ceiling(all.Max(p => p.X) + reach + Pad);
        double minY = Math.Floor(all.Min(p => p.Y) - reach - Pad), maxY = Math.Ceiling(all.Max(p => p.Y) + reach + Pad);
        double scale = Math.Clamp(MinPixels / (maxX - minX), 1e-3, Math.Min(MaxScale, MaxPixels / Math.Max(maxX - minX, maxY - minY)));
        var rows = LegendRows(check);
        // A step row and the key lines are never cut (the title may be, it is also the file's <title>).
        double widest = (rows.Select(r => r.Line.Length).Append(CellsKey.Length).Append(PortalsKey.Length).Max() * CharPixels) + 12;
        double width = Math.Max(Math.Max((maxX - minX) * scale, MinPixels), widest), height = (maxY - minY) * scale;
        maxX = minX + (width / scale);
        // Every legend line counted: the indoor cells, the land cells the walk stands in, the step rows, two headings
        // and the gaps (issue 28: the land cells were left out, so the last step rows fell off the picture).
        int landCells = check.Trace.Select(s => s.Containing).Where(c => c.IsLand).Distinct().Count();
        double legend = ((cells.Count + landCells + rows.Count + 4) * Line) + 10;
        double Px(double x) => (x - minX) * scale;
        double Py(double y) => (maxY - y) * scale;
        string P(WorldPoint p) => $"{Num(Px(p.X))},{Num(Py(p.Y))}";

        int? bad = check.FirstViolatingStep;
        var badStep = bad is int b0 ? check.Trace[b0] : null;
        var sb = new StringBuilder();
        sb.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Num(width)}\" height=\"{Num(Header + height + legend)}\" viewBox=\"0 {Num(-Header)} {Num(width)} {Num(Header + height + legend)}\" font-family=\"monospace\" font-size=\"11\"");
        sb.Append($" data-world-left=\"{Num(minX)}\" data-world-top=\"{Num(maxY)}\" data-px-per-m=\"{scale:R}\">\n");
        sb.Append($"<title>{Escape(title)}</title>\n<rect x=\"0\" y=\"{Num(-Header)}\" width=\"{Num(width)}\" height=\"{Num(Header + height + legend)}\" fill=\"white\"/>\n");
        string headline = $"{sw.Size}; "
            + (bad is int b1 ? $"first violation at step {b1}: {string.Join(", ", check.PerStep[b1].Select(v => v.InvariantId).Distinct())}" : "no violation");
        int chars = (int)(width / CharPixels);
        sb.Append($"<text x=\"4\" y=\"{Num(-Header + 14)}\" font-weight=\"bold\">{Escape(Clip(title, chars))}</text>\n");
        sb.Append($"<text x=\"4\" y=\"{Num(-Header + 28)}\" fill=\"{(bad is null ? "#000" : "red")}\">{Escape(Clip(headline, chars))}</text>\n");
        sb.Append($"<text x=\"4\" y=\"{Num(-Header + 42)}\" fill=\"#555\">{Escape(Clip(CellsKey, chars))}</text>\n");
        sb.Append($"<text x=\"4\" y=\"{Num(-Header + 56)}\" fill=\"#555\">{Escape(Clip(PortalsKey, chars))}</text>\n");

        sb.Append($"<clipPath id=\"map\"><rect x=\"0\" y=\"0\" width=\"{Num(width)}\" height=\"{Num(height)}\"/></clipPath>\n<g clip-path=\"url(#map)\">\n");

        // Blocks in view that are not loaded.
        for (double bx = Math.Floor(minX / 192) * 192; bx < maxX; bx += 192)
        {
            for (double by = Math.Floor(minY / 192) * 192; by < maxY; by += 192)
            {
                bool onMap = bx >= 0 && by >= 0 && bx / 192 <= LandDefs.MaxBlockByte && by / 192 <= LandDefs.MaxBlockByte;
                var id = onMap ? new LandblockId((byte)(bx / 192), (byte)(by / 192)) : default;
                if (onMap && scene.Blocks.Contains(id))
                {
                    continue;
                }

                double x0 = Math.Max(Px(bx), 0), x1 = Math.Min(Px(bx + 192), width), y0 = Math.Max(Py(by + 192), 0), y1 = Math.Min(Py(by), height);
                string what = !onMap ? "off the map" : scene.UnloadedBlocks.Contains(id) ? $"block {id} declared unloaded" : $"block {id} not loaded";
                sb.Append($"<rect class=\"unloaded-block\" data-block=\"{(onMap ? id.ToString() : "off-map")}\" x=\"{Num(x0)}\" y=\"{Num(y0)}\" width=\"{Num(x1 - x0)}\" height=\"{Num(y1 - y0)}\" fill=\"#777\" fill-opacity=\"{(onMap && scene.UnloadedBlocks.Contains(id) ? "0.35" : "0.22")}\"><title>{Escape(what)}</title></rect>\n");
                sb.Append($"<text x=\"{Num(x0 + 4)}\" y=\"{Num(y0 + 14)}\" fill=\"#444\">{Escape(what)}</text>\n");
            }
        }

        // Land cells that contain some step, tinted in their colour and labelled; the violating step's outlined red.
        foreach (var id in check.Trace.Select(s => s.Containing).Where(c => c.IsLand).Distinct())
        {
            var (gx, gy) = Oracle.LcoordOf(id);
            bool isBad = badStep?.Containing == id;
            sb.Append($"<rect class=\"land-cell\" data-cell=\"{id}\" x=\"{Num(Px(24.0 * gx))}\" y=\"{Num(Py(24.0 * (gy + 1)))}\" width=\"{Num(24 * scale)}\" height=\"{Num(24 * scale)}\" fill=\"{colours.Of(id)}\" fill-opacity=\"0.12\" stroke=\"{(isBad ? "red" : "none")}\" stroke-width=\"4\"/>\n");
            double vx0 = Math.Clamp(Px(24.0 * gx), 0, width), vx1 = Math.Clamp(Px(24.0 * (gx + 1)), 0, width);
            double vy0 = Math.Clamp(Py(24.0 * (gy + 1)), 0, height), vy1 = Math.Clamp(Py(24.0 * gy), 0, height);
            sb.Append($"<text class=\"land-label\" x=\"{Num((vx0 + vx1) / 2)}\" y=\"{Num(((vy0 + vy1) / 2) + 4)}\" text-anchor=\"middle\" font-size=\"12\" fill=\"{colours.Of(id)}\" fill-opacity=\"0.8\">land {id}</text>\n");
        }

        for (double x = Math.Ceiling(minX / 24) * 24; x <= maxX; x += 24)
        {
            bool block = x % 192 == 0;
            sb.Append($"<line class=\"grid\" x1=\"{Num(Px(x))}\" y1=\"0\" x2=\"{Num(Px(x))}\" y2=\"{Num(height)}\" stroke=\"{(block ? "#222" : "#bbb")}\" stroke-width=\"{(block ? 2.5 : 1)}\"/>\n");
            sb.Append($"<text x=\"{Num(Px(x) + 2)}\" y=\"10\" font-size=\"9\" fill=\"#777\">x {Num(((x % 192) + 192) % 192)}</text>\n");
        }

        for (double y = Math.Ceiling(minY / 24) * 24; y <= maxY; y += 24)
        {
            bool block = y % 192 == 0;
            sb.Append($"<line class=\"grid\" x1=\"0\" y1=\"{Num(Py(y))}\" x2=\"{Num(width)}\" y2=\"{Num(Py(y))}\" stroke=\"{(block ? "#222" : "#bbb")}\" stroke-width=\"{(block ? 2.5 : 1)}\"/>\n");
            sb.Append($"<text x=\"{Num(width - 3)}\" y=\"{Num(Py(y) - 3)}\" text-anchor=\"end\" font-size=\"9\" fill=\"#777\">y {Num(((y % 192) + 192) % 192)}</text>\n");
        }

        for (double bx = Math.Floor(minX / 192) * 192; bx < maxX; bx += 192)
        {
            for (double by = Math.Floor(minY / 192) * 192; by < maxY; by += 192)
            {
                if (bx >= 0 && by >= 0 && bx / 192 <= LandDefs.MaxBlockByte && by / 192 <= LandDefs.MaxBlockByte)
                {
                    var id = new LandblockId((byte)(bx / 192), (byte)(by / 192));
                    sb.Append($"<text class=\"block-label\" x=\"{Num(Math.Max(Px(bx), 0) + 3)}\" y=\"{Num(Math.Min(Py(by), height) - 4)}\" fill=\"#222\" font-weight=\"bold\">block {id}</text>\n");
                }
            }
        }

        // Env cells: one group per cell, one polygon per convex piece.
        foreach (var cell in cells)
        {
            bool storey = IsUpperStorey(cell, cells);
            bool isBad = badStep?.Containing == cell.Id;
            bool loaded = scene.Blocks.Contains(cell.Id.Landblock);
            string colour = colours.Of(cell.Id);
            sb.Append($"<g class=\"cell-outline{(storey ? " storey" : string.Empty)}\" id=\"cell-{cell.Id}\" data-cell=\"{cell.Id}\" data-z-min=\"{Num(cell.ZMin)}\" data-z-max=\"{Num(cell.ZMax)}\">");
            sb.Append($"<title>{cell.Id}: z {Num(cell.ZMin)}..{Num(cell.ZMax)}{(loaded ? string.Empty : " (its block is not loaded)")}</title>\n");
            foreach (var piece in cell.Pieces)
            {
                sb.Append($"<polygon class=\"piece\" points=\"{string.Join(' ', piece.Select(P))}\" fill=\"{colour}\" fill-opacity=\"{(storey ? "0.06" : "0.16")}\" stroke=\"{(isBad ? "red" : colour)}\" stroke-width=\"{(isBad ? 3 : 1.5)}\"{(storey ? " stroke-dasharray=\"6 4\"" : string.Empty)}/>\n");
            }

            var c = cell.Centre;
            double top = Py(cell.Bounds.MaxY);
            sb.Append($"<text x=\"{Num(Px(c.X))}\" y=\"{Num(top + 16)}\" text-anchor=\"middle\" fill=\"{colour}\" font-weight=\"bold\">{cell.Id.Low:X4}</text>");
            sb.Append($"<text x=\"{Num(Px(c.X))}\" y=\"{Num(top + 28)}\" text-anchor=\"middle\" fill=\"{colour}\">z {Num(cell.ZMin)}–{Num(cell.ZMax)}</text></g>\n");
        }

        // Cell portals, drawn a few pixels inside their own cell so the two sides of a shared portal both show.
        foreach (var portal in portals)
        {
            var other = portal.Owner.WithLow(portal.Portal.Other);
            string kind = portal.Portal.IsExit ? "exit" : SceneOracle.IsLoadedEnv(scene, other) ? "inter" : "hint";
            string colour = kind switch { "exit" => CellColours.Exit, "inter" => CellColours.Inter, _ => CellColours.Hint };
            var shift = new WorldPoint(portal.Inward.X * PortalInset / scale, portal.Inward.Y * PortalInset / scale);
            var pts = portal.Points.Select(p => new WorldPoint(p.X + shift.X, p.Y + shift.Y)).ToList();
            string target = portal.Portal.IsExit ? "out" : $"{portal.Portal.Other:X4}";
            string attrs = $"class=\"portal {kind}{(portal.Approximate ? " approximate" : string.Empty)}\" id=\"portal-{portal.Owner}-{portal.Index}\" data-owner=\"{portal.Owner}\" data-index=\"{portal.Index}\" data-other=\"{(portal.Portal.IsExit ? "outside" : other.ToString())}\" data-portal-side=\"{(portal.Portal.PortalSide ? "true" : "false")}\"";
            string tip = $"<title>{portal.Owner} portal {portal.Index} → {(portal.Portal.IsExit ? "outside" : other.ToString())}, PortalSide {portal.Portal.PortalSide}{(portal.Approximate ? " (plane misses the cell: stub)" : string.Empty)}</title>";
            sb.Append(pts.Count >= 3
                ? $"<polygon {attrs} points=\"{string.Join(' ', pts.Select(P))}\" fill=\"{colour}\" fill-opacity=\"0.3\" stroke=\"{colour}\" stroke-width=\"3\">{tip}</polygon>\n"
                : $"<line {attrs} x1=\"{Num(Px(pts[0].X))}\" y1=\"{Num(Py(pts[0].Y))}\" x2=\"{Num(Px(pts[^1].X))}\" y2=\"{Num(Py(pts[^1].Y))}\" stroke=\"{colour}\" stroke-width=\"4\" stroke-linecap=\"butt\"{(kind == "hint" ? " stroke-dasharray=\"4 3\"" : string.Empty)}>{tip}</line>\n");
            var mid = new WorldPoint(pts.Average(p => p.X), pts.Average(p => p.Y));
            double tx = Px(mid.X) + (portal.Inward.X * 12), ty = Py(mid.Y) - (portal.Inward.Y * 12) + 4;
            sb.Append($"<text class=\"portal-label\" x=\"{Num(tx)}\" y=\"{Num(ty)}\" text-anchor=\"middle\" font-size=\"9\" fill=\"{colour}\">p{portal.Index}→{target} ps={(portal.Portal.PortalSide ? 1 : 0)}</text>\n");
        }

        // Buildings: origin, owning land cell, and each building portal over the cell portal it names.
        for (int i = 0; i < scene.Buildings.Count; i++)
        {
            var building = scene.Buildings[i];
            var o = origins[i];
            var owner = new Building(building.Block, building.Origin, []).OwningCell();
            sb.Append($"<g class=\"building\" id=\"building-{i}\" data-block=\"{building.Block}\"><title>building {i} in {building.Block} at ({Num(building.Origin.X)}, {Num(building.Origin.Y)}, {Num(building.Origin.Z)}), owning land cell {owner}</title>");
            sb.Append($"<path d=\"M{Num(Px(o.X) - 6)},{Num(Py(o.Y))} h12 M{Num(Px(o.X))},{Num(Py(o.Y) - 6)} v12\" stroke=\"#000\" stroke-width=\"2\"/>");
            sb.Append($"<text x=\"{Num(Px(o.X) + 7)}\" y=\"{Num(Py(o.Y) - 7)}\" font-size=\"10\">bldg {i} (owner {owner})</text></g>\n");
            for (int j = 0; j < building.Portals.Count; j++)
            {
                var bp = building.Portals[j];
                var cellId = building.Block.BlockCell.WithLow(bp.Cell);
                int cellIndex = scene.Cells.ToList().FindIndex(c => c.Id == cellId);
                var trace = cellIndex >= 0 && bp.Portal < scene.Cells[cellIndex].Portals.Count ? portals.First(p => p.Owner == cellId && p.Index == bp.Portal) : null;
                string attrs = $"class=\"bld-portal{(trace is null ? " missing" : string.Empty)}\" id=\"bld-{i}-portal-{j}\" data-cell=\"{cellId}\" data-portal=\"{bp.Portal}\"";
                string tip = $"<title>building {i} portal {j} → {cellId} portal {bp.Portal}{(trace is null ? " (no such loaded cell portal)" : string.Empty)}</title>";
                if (trace is null)
                {
                    sb.Append($"<circle {attrs} cx=\"{Num(Px(o.X))}\" cy=\"{Num(Py(o.Y))}\" r=\"{9 + (3 * j)}\" fill=\"none\" stroke=\"#000\" stroke-dasharray=\"2 2\">{tip}</circle>\n");
                    continue;
                }

                var a = trace.Points[0];
                var z = trace.Points[^1];
                var m = new WorldPoint(trace.Points.Average(p => p.X), trace.Points.Average(p => p.Y));
                sb.Append($"<line {attrs} x1=\"{Num(Px(a.X))}\" y1=\"{Num(Py(a.Y))}\" x2=\"{Num(Px(z.X))}\" y2=\"{Num(Py(z.Y))}\" stroke=\"#000\" stroke-width=\"2\" stroke-dasharray=\"5 4\">{tip}</line>\n");
                sb.Append($"<line class=\"bld-link\" x1=\"{Num(Px(o.X))}\" y1=\"{Num(Py(o.Y))}\" x2=\"{Num(Px(m.X))}\" y2=\"{Num(Py(m.Y))}\" stroke=\"#000\" stroke-width=\"0.6\" stroke-dasharray=\"1 3\"/>\n");
            }
        }

        // The walk: sphere 0's path, then one marker per step in the containing cell's colour.
        sb.Append("<polyline class=\"path\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\" points=\"").Append(string.Join(' ', centres.Select(P))).Append("\"/>\n");
        var labels = new List<(double X, double Y)>();
        foreach (var step in check.Trace)
        {
            var p = centres[step.Index];
            bool isBad = step.Index == bad;
            bool violation = check.PerStep[step.Index].Count > 0;
            string place = step.Containing.IsNone ? "none" : step.Containing.IsEnv ? "indoor" : "outdoor";
            string cls = $"step {place}{(isBad ? " fail" : violation ? " violation" : string.Empty)}";
            string colour = colours.Of(step.Containing);
            string stroke = violation ? "red" : "#000";
            string tip = $"<title>step {step.Index}: cell {step.Frame} ({FloatText.Format(step.Position.X)}, {FloatText.Format(step.Position.Y)}, {FloatText.Format(step.Position.Z)}), containing {step.Containing}, current {step.Current}, candidates [{string.Join(", ", step.Cells)}]{string.Concat(check.PerStep[step.Index].Select(v => $"; {v.InvariantId}: {v.Message}"))}</title>";
            string data = $"data-step=\"{step.Index}\" data-cell=\"{step.Frame}\" data-containing=\"{step.Containing}\"";
            sb.Append(step.Containing.IsLand
                ? $"<rect class=\"{cls}\" {data} x=\"{Num(Px(p.X) - 3)}\" y=\"{Num(Py(p.Y) - 3)}\" width=\"6\" height=\"6\" fill=\"{colour}\" stroke=\"{stroke}\" stroke-width=\"0.6\">{Escape(tip)}</rect>\n"
                : $"<circle class=\"{cls}\" {data} cx=\"{Num(Px(p.X))}\" cy=\"{Num(Py(p.Y))}\" r=\"3.5\" fill=\"{colour}\" stroke=\"{stroke}\" stroke-width=\"0.6\">{Escape(tip)}</circle>\n");
            if (isBad)
            {
                foreach (var sphere in step.Query.Spheres)
                {
                    var (sx, sy) = SceneOracle.World(step.Query.Cell, sphere.Center);
                    sb.Append($"<circle class=\"fail-sphere\" cx=\"{Num(Px(sx))}\" cy=\"{Num(Py(sy))}\" r=\"{Num(Math.Max(sphere.Radius * scale, 4))}\" fill=\"red\" fill-opacity=\"0.12\" stroke=\"red\" stroke-width=\"2\"/>\n");
                }
            }

            bool changes = step.Index == 0 || step.Index == check.Trace.Count - 1 || check.Trace[step.Index - 1].Containing != step.Containing;
            if (changes || isBad)
            {
                double sx = Px(p.X) + 6, sy = Py(p.Y) - 5;
                while (labels.Any(l => Math.Abs(l.X - sx) < 18 && Math.Abs(l.Y - sy) < 10))
                {
                    sy += 11; // another step's label is here (a walk that comes back): stack below it
                }

                labels.Add((sx, sy));
                sb.Append($"<text class=\"step-label\" x=\"{Num(sx)}\" y=\"{Num(sy)}\" font-size=\"10\" fill=\"{(isBad ? "red" : "#000")}\"{(isBad ? " font-weight=\"bold\"" : string.Empty)}>{step.Index}{(isBad ? " ✗" : string.Empty)}</text>\n");
            }
        }

        sb.Append($"</g>\n<rect x=\"0\" y=\"0\" width=\"{Num(width)}\" height=\"{Num(height)}\" fill=\"none\" stroke=\"#000\"/>\n");
        sb.Append($"<path d=\"M{Num(width - 12 - (5 * scale))},{Num(height - 10)} h{Num(5 * scale)}\" stroke=\"#000\" stroke-width=\"3\"/><text x=\"{Num(width - 12 - (2.5 * scale))}\" y=\"{Num(height - 15)}\" text-anchor=\"middle\" font-size=\"10\">5 m</text>\n");

        // Legend: the cells, then the steps where something changes.
        double ly = height + Line + 4;
        sb.Append($"<text x=\"4\" y=\"{Num(ly)}\" font-weight=\"bold\" xml:space=\"preserve\">cell        kind     z range       steps containing</text>\n");
        foreach (var cell in cells.Select(c => (Id: c.Id, Text: $"indoor   z {Num(c.ZMin)}..{Num(c.ZMax)}")).Concat(check.Trace.Select(s => s.Containing).Where(c => c.IsLand).Distinct().Select(c => (Id: c, Text: "outdoor  land cell   "))))
        {
            ly += Line;
            var idx = check.Trace.Where(s => s.Containing == cell.Id).Select(s => s.Index).ToList();
            string span = idx.Count == 0 ? "none" : $"{idx.Count} ({idx.Min()}..{idx.Max()})";
            sb.Append($"<rect x=\"4\" y=\"{Num(ly - 9)}\" width=\"9\" height=\"9\" fill=\"{colours.Of(cell.Id)}\"/><text x=\"16\" y=\"{Num(ly)}\" xml:space=\"preserve\">{Escape($"{cell.Id,-10}  {cell.Text,-20}  {span}")}</text>\n");
        }

        ly += Line * 1.5;
        sb.Append($"<text x=\"4\" y=\"{Num(ly)}\" font-weight=\"bold\" xml:space=\"preserve\">step  cell        position (block frame)        containing  current     candidates / violations</text>\n");
        foreach (var (line, isBad) in rows)
        {
            ly += Line;
            sb.Append($"<text class=\"legend-step\" x=\"4\" y=\"{Num(ly)}\" xml:space=\"preserve\" fill=\"{(isBad ? "red" : "#000")}\">{Escape(Clip(line, chars))}</text>\n");
        }

        sb.Append("</svg>\n");
        return sb.ToString();
    }

    // A cell drawn dashed: another cell's footprint overlaps its bounds and starts at least half a metre lower.
    private static bool IsUpperStorey(CellFootprint cell, IReadOnlyList<CellFootprint> all)
    {
        var a = cell.Bounds;
        return all.Any(o =>
        {
            var b = o.Bounds;
            return o.Id != cell.Id && o.ZMin < cell.ZMin - 0.5
                && Math.Min(a.MaxX, b.MaxX) - Math.Max(a.MinX, b.MinX) > 0.1 && Math.Min(a.MaxY, b.MaxY) - Math.Max(a.MinY, b.MinY) > 0.1;
        });
    }

    // The first and last step, each step whose containing cell changes, and each step with a violation (at most MaxRows).
    private static List<(string Line, bool Bad)> LegendRows(CaseRun check)
    {
        var rows = new List<(string, bool)>();
        foreach (var step in check.Trace)
        {
            var violations = check.PerStep[step.Index];
            bool changes = step.Index == 0 || step.Index == check.Trace.Count - 1 || check.Trace[step.Index - 1].Containing != step.Containing;
            if (!changes && violations.Count == 0)
            {
                continue;
            }

            if (rows.Count == MaxRows)
            {
                rows.Add(($"… {check.Trace.Count - step.Index} more steps not listed (acphys replay prints every step)", false));
                break;
            }

            string position = $"({FloatText.Format(step.Position.X)}, {FloatText.Format(step.Position.Y)}, {FloatText.Format(step.Position.Z)})";
            string tail = violations.Count > 0 ? "VIOLATED " + string.Join(", ", violations.Select(v => v.InvariantId).Distinct()) : $"[{string.Join(", ", step.Cells)}]";
            rows.Add(($"{step.Index,4}  {step.Frame,-10}  {position,-28}  {step.Containing,-10}  {step.Current,-10}  {tail}", violations.Count > 0));
        }

        return rows;
    }
}
