#!/usr/bin/env python3
"""A small implementation of Asheron's Call outdoor cell membership, speaking AcPhysVerify protocol v1.

Standard library only. It reads one JSON request per line on stdin and answers one JSON object per line on stdout,
in order (docs/protocol.md); logs go to stderr. It offers the LandDefs ops, outside_cells and find_cell on open land
with the retail pick, find_cell in scenes (the indoor half, in acphys_indoor.py beside this file: env cells,
portals, buildings, static placement and movement transitions) and the parts variant on open land and in scenes
(acphys_parts.py: outside_cells_parts, find_cell_parts_scene, find_cell_parts_transition), written from the facts specification
(../shared/spec/retail-cell-physics-facts.md, cited as "facts §x"), not from the C# core.

Run it under the suite:

    acphys verify --impl-cmd "python3 examples/python/acphys_impl.py"

Seeded bugs, to see the suite catch a defect through the process protocol (--bug NAME or ACPHYS_PY_BUG=NAME):

    clamp-106    candidates and the containing pick clamped to the position's landblock (acdream #106)
    trunc-floor  get_outside_lcoord truncates x/24 toward zero instead of flooring (facts §6.2)
    portal-side-inverted  a portal's PortalSide read backwards when adding a load hint (facts §5.4)

--ops NAME[,NAME...] announces only some ops (a partial implementation: the rest is reported as not tested). Without
find_cell_walk among them the tool sends walks one find_cell per step, as to an implementation written before the op;
without pipeline it waits for each answer before the next request.
"""

import argparse
import json
import math
import os
import struct
import sys

import acphys_indoor
import acphys_parts

PROTOCOL = 1
LAND_LENGTH = 2040          # lcoords per map side (facts §1.3)
CELL_LENGTH = 24.0          # metres per land cell side
BLOCK_LENGTH = 192.0        # metres per landblock side
EPSILON = struct.unpack("<f", struct.pack("<f", 0.0002))[0]   # facts §1.5, the float32 value of 0.0002f
ALL_OPS = ["blockid_to_lcoord", "gid_to_lcoord", "lcoord_to_gid", "inbound_valid_cellid",
           "get_outside_lcoord", "adjust_to_outside", "outside_cells", "outside_cells_parts", "find_cell", "find_cell_walk",
           "find_cell_scene", "find_cell_transition", "find_cell_parts_scene", "find_cell_parts_transition", "load_scene",
           "pipeline"]          # answers depend on the request alone: the tool may send the next before this is answered
BUGS = ("clamp-106", "trunc-floor", "portal-side-inverted")


class BadRequest(Exception):
    """A request this implementation cannot read."""


_F32 = struct.Struct("<f")


def f32(v):
    """Rounds a Python float (a double) to the nearest float32, as a float32 operation in C would."""
    try:
        return _F32.unpack(_F32.pack(v))[0]
    except OverflowError:
        return math.copysign(math.inf, v)


# ---- values on the wire -------------------------------------------------------------------------------------------

def read_cell(text):
    if not (isinstance(text, str) and len(text) == 10 and text[:2] in ("0x", "0X")):
        raise BadRequest("cell id must be a string 0xAABBCCCC, got %r" % (text,))
    try:
        return int(text[2:], 16)
    except ValueError:
        raise BadRequest("cell id must be 8 hex digits, got %r" % (text,))


def cell_text(cell):
    return "0x%08X" % cell


def read_float(v):
    if isinstance(v, str):
        if v == "NaN":
            return math.nan
        if v == "Infinity":
            return math.inf
        if v == "-Infinity":
            return -math.inf
        raise BadRequest("not a number: %r" % (v,))
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise BadRequest("not a number: %r" % (v,))
    return f32(float(v))


def float_value(v):
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return "Infinity" if v > 0 else "-Infinity"
    return v


def read_int(v):
    if isinstance(v, bool) or not isinstance(v, int):
        raise BadRequest("not an integer: %r" % (v,))
    return v


def read_spheres(items):
    if not isinstance(items, list):
        raise BadRequest("spheres must be a list")
    return [(read_float(s["x"]), read_float(s["y"]), read_float(s["z"]), read_float(s["r"])) for s in items]


def read_vector(item, names="xyz"):
    if not isinstance(item, dict):
        raise BadRequest("expected an object {%s}" % ", ".join(names))
    return tuple(read_float(item[n]) for n in names)


def read_parts(items):
    """The parts of outside_cells_parts and find_cell_parts_* (docs/protocol.md): float32 numbers, each part in its own cell."""
    if not isinstance(items, list):
        raise BadRequest("parts must be a list")
    parts = []
    for p in items:
        if not isinstance(p, dict) or not isinstance(p.get("always2d", False), bool):
            raise BadRequest("a part is an object {cell, origin, rotation, min, max, r, always2d}")
        parts.append(acphys_parts.Part(read_cell(p["cell"]), read_vector(p["origin"]), read_vector(p["rotation"], "xyzw"),
                                       read_vector(p["min"]), read_vector(p["max"]), read_float(p["r"]),
                                       p.get("always2d", False)))
    return parts


def read_origin(request):
    """the optional "origin" {x, y, z}: the position's own point, sent only with an empty sphere list"""
    o = request.get("origin")
    if o is None:
        return (0.0, 0.0)
    if not isinstance(o, dict):
        raise BadRequest("origin must be an object {x, y, z}")
    return (read_float(o.get("x")), read_float(o.get("y")))


# ---- LandDefs (facts §1-§2) ---------------------------------------------------------------------------------------

def block_x(cell):
    return (cell >> 24) & 0xFF


def block_y(cell):
    return (cell >> 16) & 0xFF


def low(cell):
    return cell & 0xFFFF


def in_bounds(x, y):
    return 0 <= x < LAND_LENGTH and 0 <= y < LAND_LENGTH


def cell_in_range(lo):
    return lo == 0xFFFF or 1 <= lo <= 64 or 0x100 <= lo <= 0xFFFD


def blockid_to_lcoord(cell):
    if cell == 0:
        return None                      # retail reports failure for id 0 (facts §2)
    x, y = block_x(cell) * 8, block_y(cell) * 8
    if x >= LAND_LENGTH or y >= LAND_LENGTH:
        return None
    return x, y


def inbound_valid_cellid(cell):
    # retail tests both block bytes (facts §2; ACE tests only bx)
    return cell_in_range(low(cell)) and block_x(cell) * 8 < LAND_LENGTH and block_y(cell) * 8 < LAND_LENGTH


def gid_to_lcoord(cell):
    if not inbound_valid_cellid(cell) or low(cell) >= 0x100:
        return None
    index = low(cell) - 1                # X is the major index (facts §1.2)
    x = block_x(cell) * 8 + (index >> 3)
    y = block_y(cell) * 8 + (index & 7)
    return (x, y) if in_bounds(x, y) else None


def lcoord_to_gid(x, y):
    if not in_bounds(x, y):
        return 0
    return ((x >> 3) << 24) | ((y >> 3) << 16) | (1 + ((x & 7) << 3) + (y & 7))


def get_outside_lcoord(cell, x, y):
    if not cell_in_range(low(cell)):
        return None
    block = blockid_to_lcoord(cell)
    if block is None or not (math.isfinite(x) and math.isfinite(y)):
        return None
    if BUG == "trunc-floor":
        cx, cy = math.trunc(x / CELL_LENGTH), math.trunc(y / CELL_LENGTH)
    else:
        cx, cy = math.floor(x / CELL_LENGTH), math.floor(y / CELL_LENGTH)   # floor toward -inf (facts §2)
    gx, gy = block[0] + cx, block[1] + cy
    return (gx, gy) if in_bounds(gx, gy) else None


def rebase(v, length):
    """v - length * floor(v / length), exact in double, rounded once to float32."""
    return f32(v - length * math.floor(v / length))


def adjust_to_outside(cell, x, y):
    """facts §2.1: returns (ok, cell, x, y)."""
    if not cell_in_range(low(cell)):
        return False, 0, x, y            # loc untouched
    if abs(x) < EPSILON:                 # strict, per axis
        x = 0.0
    if abs(y) < EPSILON:
        y = 0.0
    lc = get_outside_lcoord(cell, x, y)
    if lc is None:
        return False, 0, x, y            # the snapped loc is kept
    return True, lcoord_to_gid(*lc), rebase(x, BLOCK_LENGTH), rebase(y, BLOCK_LENGTH)


# ---- outdoor cell sets (facts §3, §4) ------------------------------------------------------------------------------

def add_outside_cell(cells, x, y, position):
    if not in_bounds(x, y):
        return
    cell = lcoord_to_gid(x, y)
    if BUG == "clamp-106" and (cell >> 16) != (position >> 16):
        return                           # the seeded bug: candidates clamped to the position's landblock
    if cell not in cells:
        cells.append(cell)               # every block is loaded on open land


def check_add_cell_boundary(cells, pt_x, pt_y, x, y, min_rad, max_rad, position):
    # facts §3.2: strict comparisons, exact order; not "else": with r > 12 both x sides can fire
    if pt_x > max_rad:
        add_outside_cell(cells, x + 1, y, position)
        if pt_y > max_rad:
            add_outside_cell(cells, x + 1, y + 1, position)
        if pt_y < min_rad:
            add_outside_cell(cells, x + 1, y - 1, position)
    if pt_x < min_rad:
        add_outside_cell(cells, x - 1, y, position)
        if pt_y > max_rad:
            add_outside_cell(cells, x - 1, y + 1, position)
        if pt_y < min_rad:
            add_outside_cell(cells, x - 1, y - 1, position)
    if pt_y > max_rad:
        add_outside_cell(cells, x, y + 1, position)
    if pt_y < min_rad:
        add_outside_cell(cells, x, y - 1, position)


def outside_cells(position, spheres, origin=(0.0, 0.0)):
    """facts §3.3, the sphere variant, every landblock loaded; with no spheres the position's own point is re-seated."""
    cells = []
    if not spheres:
        ok, cell, _, _ = adjust_to_outside(position, origin[0], origin[1])
        if ok:
            add_outside_cell(cells, *gid_to_lcoord(cell), position)
        return cells
    for (sx, sy, _, r) in spheres:
        ok, cell, cx, cy = adjust_to_outside(position, sx, sy)   # each sphere starts from the position's id
        if not ok:
            break                        # a failed sphere ends the loop; cells already added stay
        pt_x = cx - CELL_LENGTH * math.floor(cx / CELL_LENGTH)   # exact: cx is in [0, 192)
        pt_y = cy - CELL_LENGTH * math.floor(cy / CELL_LENGTH)
        lx, ly = gid_to_lcoord(cell)
        add_outside_cell(cells, lx, ly, position)
        check_add_cell_boundary(cells, pt_x, pt_y, lx, ly, r, f32(CELL_LENGTH - r), position)
    return cells


def cuts_sw_to_ne(gx, gy):
    """facts §5.6: the cell's diagonal, from its global lcoord in unsigned 32-bit wrap-around arithmetic."""
    s = (gy * (214614067 * gx + 1813693831) - 1109124029 * gx - 1369149221) & 0xFFFFFFFF
    return s >= 0x80000000


def rejects(prev, cur, px, py):
    """point_in_poly2D's edge test, side Positive (facts §5.5): the float32 cross (cur - prev) x (p - cur) > 0.

    The edge's components are differences of cell corners, 0 or +-24 m: exact in float32, so they are not rounded, and
    a zero component's product is an exact zero, so an axis-aligned edge's cross is its one rounded product."""
    ax, ay = cur[0] - prev[0], cur[1] - prev[1]
    bx, by = f32(px - cur[0]), f32(py - cur[1])
    if ax == 0.0:
        return -f32(ay * bx) > 0.0
    if ay == 0.0:
        return f32(ax * by) > 0.0
    return f32(f32(ax * by) - f32(ay * bx)) > 0.0


def in_triangle(v0, v1, v2, px, py):
    """point_in_poly2D walks the edges v0->v2, v2->v1, v1->v0 (facts §5.5)."""
    return not rejects(v0, v2, px, py) and not rejects(v2, v1, px, py) and not rejects(v1, v0, px, py)


def land_square_contains(cell, px, py):
    """facts §5.5: a land cell contains p when either terrain triangle does, each test rounded to float32 as retail's.
    Up to rounding that is the closed 24 m square; the rounding decides points within an ulp or so of an edge."""
    if not (math.isfinite(px) and math.isfinite(py)):
        return False
    index = low(cell) - 1
    cx, cy = index >> 3, index & 7
    west, south = CELL_LENGTH * cx, CELL_LENGTH * cy
    sw, se = (west, south), (west + CELL_LENGTH, south)
    nw, ne = (west, south + CELL_LENGTH), (west + CELL_LENGTH, south + CELL_LENGTH)
    if cuts_sw_to_ne(block_x(cell) * 8 + cx, block_y(cell) * 8 + cy):
        return in_triangle(sw, se, ne, px, py) or in_triangle(sw, ne, nw, px, py)
    return in_triangle(sw, se, nw, px, py) or in_triangle(ne, nw, se, px, py)


def find_cell(position, spheres, origin=(0.0, 0.0)):
    """facts §4 on open land: the candidates, then the retail pick (the last cell containing sphere 0's centre)."""
    if low(position) >= 0x100:
        # an env cell or block id is indoor by its low word: seeded as itself; on open land no env cell is loaded,
        # so there is no transit and no pick (facts §4 steps 2-4)
        return [position], 0
    cells = outside_cells(position, spheres, origin)
    if not spheres:
        return cells, 0
    sx, sy = spheres[0][0], spheres[0][1]
    containing = 0
    for cell in cells:
        if not 1 <= low(cell) <= 64:
            continue
        # the centre re-expressed in the candidate's block frame (GetBlockOffset, float32 subtraction)
        px = f32(sx - BLOCK_LENGTH * (block_x(cell) - block_x(position)))
        py = f32(sy - BLOCK_LENGTH * (block_y(cell) - block_y(position)))
        if land_square_contains(cell, px, py):
            containing = cell
    return cells, containing


def find_cell_walk(cell, origin, current, body, steps, ask=None):
    """docs/protocol.md "Whole walks": the walk threaded as the tool threads it, one (cells, containing) per query.

    Every operation is float32, as the client's own: each move is added to the position (z + 0 too), the body's
    spheres are position + offset, and a containing cell re-frames the position by GetBlockOffset and becomes the
    frame and the current cell; with no containing cell both are kept. (current does not change the retail pick.)
    ask(frame, spheres) answers one query as (cells, containing, loaded flags or None); by default on open land."""
    frame = cell
    px, py, pz = origin
    answers = []
    for i in range(len(steps) + 1):
        if i > 0:
            dx, dy = steps[i - 1]
            px, py, pz = f32(px + dx), f32(py + dy), f32(pz + 0.0)
        spheres = [(f32(px + ox), f32(py + oy), f32(pz + oz), r) for (ox, oy, oz, r) in body]
        cells, containing, loaded = ask(frame, spheres) if ask else find_cell(frame, spheres, (px, py)) + (None,)
        answers.append(cell_answer(cells, containing, loaded))
        if containing:
            px = f32(px - BLOCK_LENGTH * (block_x(containing) - block_x(frame)))
            py = f32(py - BLOCK_LENGTH * (block_y(containing) - block_y(frame)))
            frame = current = containing
    return answers


# ---- the protocol --------------------------------------------------------------------------------------------------

def cell_answer(cells, containing, loaded=None):
    reply = {"cells": [cell_text(c) for c in cells], "containing": cell_text(containing) if containing else None}
    if loaded is not None:
        reply["loaded"] = loaded
    return reply


def lcoord_answer(lc):
    return {"ok": lc is not None, "x": lc[0] if lc else 0, "y": lc[1] if lc else 0}


def answer(request, ops):
    op = request.get("op")
    if op == "hello":
        if request.get("protocol") != PROTOCOL:
            return {"error": "only protocol %d is spoken here" % PROTOCOL}
        name = "python-example" + ("+" + BUG if BUG else "")
        return {"protocol": PROTOCOL, "name": name, "ops": ops, "pick": "retail"}
    if op not in ops and not (op == "unload_scene" and "load_scene" in ops):
        return {"error": "op %r not offered" % (op,)}
    if op == "blockid_to_lcoord":
        return lcoord_answer(blockid_to_lcoord(read_cell(request["cell"])))
    if op == "gid_to_lcoord":
        return lcoord_answer(gid_to_lcoord(read_cell(request["cell"])))
    if op == "lcoord_to_gid":
        return {"cell": cell_text(lcoord_to_gid(read_int(request["x"]), read_int(request["y"])))}
    if op == "inbound_valid_cellid":
        return {"ok": inbound_valid_cellid(read_cell(request["cell"]))}
    if op == "get_outside_lcoord":
        x, y = read_float(request["x"]), read_float(request["y"])
        return lcoord_answer(get_outside_lcoord(read_cell(request["cell"]), x, y))
    if op == "adjust_to_outside":
        ok, cell, x, y = adjust_to_outside(read_cell(request["cell"]), read_float(request["x"]), read_float(request["y"]))
        return {"ok": ok, "cell": cell_text(cell), "x": float_value(x), "y": float_value(y)}
    if op == "outside_cells":
        cells = outside_cells(read_cell(request["cell"]), read_spheres(request["spheres"]), read_origin(request))
        return {"cells": [cell_text(c) for c in cells]}
    if op == "outside_cells_parts":
        return {"cells": [cell_text(c) for c in acphys_parts.outside_cells_parts(GRID, read_parts(request["parts"]))]}
    if op == "load_scene":
        return SCENES.load(request)
    if op == "unload_scene":
        return SCENES.unload(request)
    scene = SCENES.of(request) if op in ("find_cell", "find_cell_walk") else None
    transition = request.get("load_cells") is True
    if scene is not None and ("find_cell_scene" not in ops or (transition and "find_cell_transition" not in ops)):
        return {"error": "scenes not offered (--ops)"}
    if op == "find_cell":
        cell, spheres = read_cell(request["cell"]), read_spheres(request["spheres"])
        if scene is not None:
            return cell_answer(*scene.find_cell_list(cell, spheres, transition))
        return cell_answer(*find_cell(cell, spheres, read_origin(request)))
    if op in ("find_cell_parts_scene", "find_cell_parts_transition"):
        scene = SCENES.of(request)
        if scene is None:
            raise BadRequest("%s takes a scene (no open-land form)" % op)
        ids, loaded = acphys_parts.find_cell_parts(scene, GRID, read_parts(request["parts"]), op.endswith("_transition"))
        return cell_answer(ids, 0, loaded)
    if op == "find_cell_walk":
        ask = (lambda frame, spheres: scene.find_cell_list(frame, spheres, transition)) if scene is not None else None
        o = request["origin"]
        if not isinstance(o, dict):
            raise BadRequest("origin must be an object {x, y, z}")
        steps = request["steps"]
        if not isinstance(steps, list):
            raise BadRequest("steps must be a list")
        current = request.get("current")
        answers = find_cell_walk(read_cell(request["cell"]), (read_float(o["x"]), read_float(o["y"]), read_float(o["z"])),
                                 read_cell(current) if current is not None else 0, read_spheres(request["body"]),
                                 [(read_float(d["x"]), read_float(d["y"])) for d in steps], ask)
        return {"steps": answers}
    return {"error": "op %r not implemented" % (op,)}


def main():
    global BUG, SCENES, GRID
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bug", choices=BUGS, default=os.environ.get("ACPHYS_PY_BUG") or None,
                        help="switch on a seeded bug (or set ACPHYS_PY_BUG)")
    parser.add_argument("--ops", help="announce only these ops (comma-separated)")
    args = parser.parse_args()
    if args.bug is not None and args.bug not in BUGS:
        parser.error("unknown bug %r (known: %s)" % (args.bug, ", ".join(BUGS)))
    BUG = args.bug
    land = acphys_indoor.Land(outside_cells=outside_cells, contains=land_square_contains, adjust_to_outside=adjust_to_outside)
    SCENES = acphys_indoor.Scenes(land, BUG)
    GRID = acphys_parts.Grid(adjust_to_outside=adjust_to_outside, gid_to_lcoord=gid_to_lcoord, lcoord_to_gid=lcoord_to_gid)
    ops = ALL_OPS if not args.ops else [o for o in args.ops.split(",") if o]

    print("acphys_impl.py: protocol %d, ops %s%s" % (PROTOCOL, ",".join(ops), ", seeded bug " + BUG if BUG else ""),
          file=sys.stderr, flush=True)
    encode = json.JSONEncoder(allow_nan=False).encode   # made once: json.dumps with an option builds one per call
    requests = Requests(sys.stdin, sys.stdout.buffer)
    for line in requests:
        if not line.strip():
            continue
        try:
            reply = answer(json.loads(line.decode("utf-8")), ops)
        except (BadRequest, KeyError, TypeError, ValueError) as e:
            reply = {"error": "bad request: %s: %s" % (type(e).__name__, e)}
        requests.answer(encode(reply))


class Requests:
    """The request lines on stdin (bytes, newline removed), and the answers queued for stdout.

    Answers are written when no whole request is waiting: a tool that waits for each answer gets it at once (the
    queue is flushed before every blocking read), and a tool that streams (op pipeline) gets many answers per write
    instead of one system call and one pipe wake-up per answer. A read never waits for more than what is there.
    """
    def __init__(self, raw_in, out):
        self._in, self._sink, self._out = raw_in.fileno(), out, []

    def __iter__(self):
        buf, at, partial = b"", 0, []        # buf[at:] is unread; partial holds the start of a line still coming
        while True:
            cut = buf.find(b"\n", at)
            if cut >= 0:
                line = buf[at:cut]
                at = cut + 1
                if partial:
                    partial.append(line)
                    line = b"".join(partial)
                    partial = []
                yield line
                continue
            if at < len(buf):
                partial.append(buf[at:])
            self.flush()
            buf, at = os.read(self._in, 1 << 16), 0
            if not buf:                          # end of input: the tool is done
                if partial:
                    yield b"".join(partial)
                self.flush()
                return

    def answer(self, text):
        self._out.append(text)

    def flush(self):
        if self._out:
            self._sink.write(("\n".join(self._out) + "\n").encode("utf-8"))
            self._sink.flush()
            self._out.clear()

BUG = None
SCENES = None
GRID = None

if __name__ == "__main__":
    main()
