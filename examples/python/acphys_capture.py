#!/usr/bin/env python3
"""Writes a capture of a walk as a port would record it, with the Python example port (acphys_impl.py) as the port.

An independent capture writer: it knows the capture formats only from their documentation (docs/corpus-format.md,
"Captures"; the acdream probe lines of docs/ports.md, "Your own sessions"), not from the tool's reader. The walk is
threaded as a client threads it (docs/protocol.md, "Whole walks"): each frame moves the float32 position, asks
find_cell from the cell the port holds, and a containing cell re-frames the position; with none the cell is kept.

    python3 examples/python/acphys_capture.py --bug clamp-106 --start 0xA9B40031 150 2 --step 0 -0.1 --frames 40 > frozen.tsv
    acphys capture check frozen.tsv

--format acdream writes [cellset-build] and [cell-transit] lines (world frame from --world-origin's south-west corner,
3 decimals as acdream prints them) with unrelated log lines between them.

--cottage writes an indoor capture instead: a walk in by the north door of the corpus cottage
(corpus/seeds/cottage-a9b3-a9b4-in-and-out.json: room 1 at x 144..150, y -4..2 of 0xA9B4, its door at y = 2; room 2 at
x 138..144), west into room 2 and back out, in steps of 0.25 m, each frame's cell the cell its centre lies in, read off
the cottage's geometry (independent of any port: with small steps a frame's cell is the room its centre lies in). --cottage-bug holds the land cell indoors, as a port
whose pick lets outdoor cells win. Check it with the cottage as dat files:

    acphys scene to-dat corpus/seeds/cottage-a9b3-a9b4-in-and-out.json --cell cell.dat --portal portal.dat
    python3 examples/python/acphys_capture.py --cottage > indoor.tsv
    acphys capture check indoor.tsv --cell-dat cell.dat --portal-dat portal.dat
"""

import argparse
import sys

import acphys_impl as port


def parse_cell(text):
    if not (text.lower().startswith("0x") and len(text) == 10):
        raise argparse.ArgumentTypeError("expected 0x and 8 hex digits, got %r" % text)
    return int(text, 16)


def cell_text(cell):
    return "0x%08X" % cell


def cottage(held):
    """The indoor walk of --cottage: (frame, cell, x, y) in 0xA9B4's block frame."""
    path = [(147.1, 3.1 - 0.25 * i) for i in range(10)]
    path += [(147.1 - 0.25 * i, 0.85) for i in range(1, 25)]
    path += [(141.1 + 0.25 * i, 0.85) for i in range(1, 25)]
    path += [(147.1, 0.85 + 0.25 * i) for i in range(1, 10)]
    for i, (x, y) in enumerate(path):
        land = 0xA9B40001 + int(x // 24) * 8 + int(y // 24)
        if 144 < x < 150 and -4 < y < 2 and not held:
            cell = 0xA9B40100
        elif 138 < x < 144 and -4 < y < 2 and not held:
            cell = 0xA9B40101
        else:
            cell = land
        yield i, cell, x, y


def write_cottage(held, out):
    out.write("# written by examples/python/acphys_capture.py --cottage%s\n" % (" --cottage-bug" if held else ""))
    out.write("# frame: block\n")
    out.write('# body: [{"x":0,"y":0,"z":0.6,"r":0.5},{"x":0,"y":0,"z":1.3,"r":0.5}]\n')
    for i, cell, x, y in cottage(held):
        out.write("%d\t%s\t%.3f\t%.3f\t%.3f\n" % (i, cell_text(cell), x, y, 0.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bug", choices=port.BUGS, help="the example port's seeded bug")
    parser.add_argument("--start", nargs=3, metavar=("CELL", "X", "Y"), help="start cell and block-frame x, y (required unless --cottage)")
    parser.add_argument("--z", type=float, default=0.0)
    parser.add_argument("--step", nargs=2, type=float, metavar=("DX", "DY"), help="the move of every frame, metres (required unless --cottage)")
    parser.add_argument("--frames", type=int, help="frames (required unless --cottage)")
    parser.add_argument("--radius", type=float, default=0.48)
    parser.add_argument("--decimals", type=int, default=3, help="decimals printed per coordinate")
    parser.add_argument("--format", choices=("native", "acdream"), default="native")
    parser.add_argument("--frame", choices=("block", "world"), default="block", help="native: the positions' frame")
    parser.add_argument("--candidates", action="store_true", help="native: write the radius and candidate columns")
    parser.add_argument("--world-origin", type=lambda t: int(t, 16), default=0xA9B4, help="acdream: the landblock at world (0, 0)")
    parser.add_argument("--cottage", action="store_true", help="an indoor capture through the corpus cottage (see above)")
    parser.add_argument("--cottage-bug", action="store_true", help="--cottage: the port holds its land cell indoors")
    args = parser.parse_args()
    if args.cottage:
        write_cottage(args.cottage_bug, sys.stdout)
        return
    if args.start is None or args.step is None or args.frames is None:
        parser.error("--start, --step and --frames are required (or --cottage)")
    port.BUG = args.bug

    cell = parse_cell(args.start[0])
    px, py, pz = port.f32(float(args.start[1])), port.f32(float(args.start[2])), port.f32(args.z)
    frame = cell
    r = args.radius
    d = args.decimals
    ox, oy = 192.0 * (args.world_origin >> 8), 192.0 * (args.world_origin & 0xFF)
    out = sys.stdout
    if args.format == "native":
        out.write("# written by examples/python/acphys_capture.py%s\n" % (" --bug " + args.bug if args.bug else ""))
        out.write("# frame: %s\n" % args.frame)
        out.write("# radius: %s\n" % r)
    for i in range(args.frames):
        if i > 0:
            px, py, pz = port.f32(px + args.step[0]), port.f32(py + args.step[1]), port.f32(pz + 0.0)
        before = frame
        cells, containing = port.find_cell(frame, [(px, py, pz, r)], (px, py))
        if containing:
            px = port.f32(px - 192.0 * (port.block_x(containing) - port.block_x(frame)))
            py = port.f32(py - 192.0 * (port.block_y(containing) - port.block_y(frame)))
            frame = containing
        wx, wy = 192.0 * port.block_x(frame) + px, 192.0 * port.block_y(frame) + py
        if args.format == "native":
            x, y = (wx, wy) if args.frame == "world" else (px, py)
            fields = [str(i), cell_text(frame), "%.*f" % (d, x), "%.*f" % (d, y), "%.*f" % (d, pz)]
            if args.candidates:
                fields += [str(r), ",".join(cell_text(c) for c in cells) or "none"]
            out.write("\t".join(fields) + "\n")
        else:
            pos = "(%.*f,%.*f,%.*f)" % (d, wx - ox, d, wy - oy, d, pz)
            out.write("[render] frame %d drawn in 16 ms\n" % i)
            out.write("[cellset-build] seed=%s sphere=%s count=%d ids=%s\n" % (cell_text(before), pos, len(cells), ",".join(cell_text(c) for c in cells)))
            if frame != before:
                out.write("[cell-transit] %s -> %s pos=%s reason=walk\n" % (cell_text(before), cell_text(frame), pos))


if __name__ == "__main__":
    main()
