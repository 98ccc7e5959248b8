"""The indoor half of find_cell_list for acphys_impl.py: scenes of env cells, portals and buildings.

Standard library only. Written from the facts specification (../shared/spec/retail-cell-physics-facts.md, "facts §x")
and docs/indoor.md ("Scene files", "Scene semantics a port applies"), not from the C# core. It reads the project's
scene JSON (docs/protocol.md, "Scenes") and answers find_cell in a scene: the seed, the transit closure through
portals and buildings, the containing pick and the indoor visibility filter (facts §4), as static placement or as a
movement transition.

The outdoor half (land cells, AdjustToOutside, the land pick) stays in acphys_impl.py and is handed in as `Land`.

Arithmetic: the inputs are float32 and a position moved by GetBlockOffset is rounded to float32 as retail does; the
rotations and plane distances are computed in double. Where that decides a boundary differently from retail's float32
the difference is a few ulps, which the gate treats as a tie (docs/conformance.md, "Numerical ties").

HitsInteriorCell is deliberately not reported: the example shows what a port that leaves an optional answer field out
gets, HITS-INTERIOR reported NOT TESTED with the field named.
"""

import collections
import json
import struct

EPSILON = struct.unpack("<f", struct.pack("<f", 0.0002))[0]   # facts §1.5: portal planes and the point test
BSP_PADDING = 0.01           # the cell BSP's sphere test pads the radius by 0.01, not EPS (facts §5.7, §6.10)
NO_PORTAL = 0xFFFF           # a building portal with this index is never entered (facts §5.3)
BLOCK_LENGTH = 192.0

# What the indoor half needs of the outdoor half (acphys_impl.py):
#   outside_cells(position, spheres) -> [land cell ids]  add_all_outside_cells, every block loaded (facts §3.3)
#   contains(cell, x, y) -> bool                         a land cell holds the point (its block frame, facts §5.5)
#   adjust_to_outside(cell, x, y) -> (ok, cell, x, y)    facts §2.1
Land = collections.namedtuple("Land", "outside_cells contains adjust_to_outside")


class SceneError(ValueError):
    """A scene or scene request this implementation cannot read."""


def f32(v):
    return struct.unpack("<f", struct.pack("<f", v))[0]


def block_of(cell):
    return cell >> 16


def is_indoor(cell):
    return cell & 0xFFFF >= 0x100         # env cells and the block id 0xAABBFFFF (facts §1.1)


def is_env(cell):
    return 0x100 <= cell & 0xFFFF <= 0xFFFD


def is_land(cell):
    return 1 <= cell & 0xFFFF <= 64


def read_id(text, digits=8):
    if not (isinstance(text, str) and len(text) == digits + 2 and text[:2] in ("0x", "0X")):
        raise SceneError("expected an id 0x + %d hex digits, got %r" % (digits, text))
    return int(text[2:], 16)


def block_offset(position, cell):
    """GetBlockOffset(position, cell): metres from position's block frame to cell's (facts §5.8)."""
    return (BLOCK_LENGTH * ((cell >> 24) - (position >> 24)), BLOCK_LENGTH * (((cell >> 16) & 0xFF) - ((position >> 16) & 0xFF)))


# ---- geometry in a cell's own frame (facts §5.7, §5.8) ----------------------------------------------------------------

def plane(item):
    """A plane {n, d} with its normal made unit length, so distances are metres (docs/indoor.md, "Planes")."""
    # Scene numbers are float32 values written as their shortest decimals: read them back as those float32 values.
    (nx, ny, nz), d = (f32(float(v)) for v in item["n"]), f32(float(item["d"]))
    length = (nx * nx + ny * ny + nz * nz) ** 0.5
    if not length > 0:
        raise SceneError("a plane with a zero normal")
    return (nx / length, ny / length, nz / length, d / length)


def distance(p, point):
    return p[0] * point[0] + p[1] * point[1] + p[2] * point[2] + p[3]


def piece_planes(piece):
    """A convex piece's inner half-spaces (N·p + D >= 0 inside): an axis-aligned box or a list of planes."""
    if "box" in piece:
        (x0, y0, z0), (x1, y1, z1) = ([f32(float(v)) for v in piece["box"][k]] for k in ("min", "max"))
        return [(1.0, 0.0, 0.0, -x0), (-1.0, 0.0, 0.0, x1), (0.0, 1.0, 0.0, -y0),
                (0.0, -1.0, 0.0, y1), (0.0, 0.0, 1.0, -z0), (0.0, 0.0, -1.0, z1)]
    return [plane(p) for p in piece["planes"]]


Portal = collections.namedtuple("Portal", "plane other side")   # other: a full id, or None for an exit


class EnvCell:
    """An env cell: its frame in its block, the first piece's planes, its portals in dat order, what it sees."""

    def __init__(self, item):
        self.id = read_id(item["id"])
        self.origin = tuple(f32(float(v)) for v in item["frame"]["origin"])
        w, x, y, z = (float(v) for v in item["frame"]["rotation"])   # W, X, Y, Z: dat order
        # The rows of Rᵀ for the unit quaternion: local = Rᵀ·(p − origin) (AFrame.GlobalToLocal, facts §5.8).
        self.rows = ((1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)),
                     (2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)),
                     (2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)))
        # Retail's three cell queries follow the BSP's positive chain only, which holds the first piece: later pieces
        # of a union are never looked at (facts §5.7; docs/indoor.md, "Unions and the positive chain").
        self.planes = piece_planes(item["pieces"][0])
        block = self.id & 0xFFFF0000
        self.portals = [Portal(plane(p["plane"]), None if p["other"] == "outside" else block | read_id(p["other"], 4),
                               bool(p["portalSide"])) for p in item["portals"]]
        self.visible = frozenset(read_id(v) for v in item["visible"])

    def to_local(self, point):
        v = (f32(point[0] - self.origin[0]), f32(point[1] - self.origin[1]), f32(point[2] - self.origin[2]))
        return tuple(r[0] * v[0] + r[1] * v[1] + r[2] * v[2] for r in self.rows)

    def touches(self, spheres):
        """Some sphere is not Outside the cell: no plane has d <= -(r + 0.01) (sphere_intersects_cell_bsp, facts §5.7)."""
        for (x, y, z, r) in spheres:
            local, reach = self.to_local((x, y, z)), r + BSP_PADDING
            if all(distance(p, local) > -reach for p in self.planes):
                return True
        return False

    def holds(self, point):
        """point_in_cell: a cell without portals holds nothing; else d >= -EPS for every plane (facts §5.5, §5.7)."""
        local = self.to_local(point)
        return bool(self.portals) and all(distance(p, local) >= -EPSILON for p in self.planes)


class CellArray:
    """The candidates (facts §5.9): an ordered set of ids, each loaded or a load hint; removal swaps the last entry in."""

    def __init__(self):
        self.ids = []
        self.loaded = {}
        self.added_outside = False     # the AddedOutside latch (facts §3.5)

    def add(self, cell, loaded):
        if cell not in self.loaded:
            self.ids.append(cell)
            self.loaded[cell] = loaded

    def remove(self, cell):
        at = self.ids.index(cell)
        last = self.ids.pop()
        if at < len(self.ids):
            self.ids[at] = last
        del self.loaded[cell]


class Scene:
    """A scene read from the project's scene JSON (docs/indoor.md, "Scene files"), answering find_cell_list."""

    def __init__(self, item, land, bug=None):
        self.land = land
        self.bug = bug
        self.blocks = frozenset(read_id(b, 4) for b in item["blocks"])
        # Only cells of loaded blocks exist for a query; any other id behind a portal is a load hint (facts §5.1).
        self.cells = {}
        for c in item["cells"]:
            cell = EnvCell(c)
            if block_of(cell.id) in self.blocks:
                self.cells[cell.id] = cell
        # A building belongs to the land cell its origin re-seats into, and only in its own block (facts §5.3).
        self.buildings = {}
        for b in item["buildings"]:
            block = read_id(b["block"], 4)
            x, y, _ = (f32(float(v)) for v in b["origin"])
            ok, owner, _, _ = land.adjust_to_outside((block << 16) | 0xFFFF, x, y)
            if ok and block_of(owner) == block and block in self.blocks:
                self.buildings[owner] = [((owner & 0xFFFF0000) | read_id(p["cell"], 4), p["portal"]) for p in b["portals"]]

    def add_outside(self, array, position, spheres):
        """add_all_outside_cells into the array: once per query (the latch), land cells of unloaded blocks as hints."""
        if array.added_outside:
            return
        array.added_outside = True
        for cell in self.land.outside_cells(position, spheres):
            array.add(cell, block_of(cell) in self.blocks)

    def find_cell_list(self, position, spheres, load_cells):
        """facts §4: returns (ids, containing cell or 0, loaded flags). Centres are in position's block frame."""
        array = CellArray()
        indoor = is_indoor(position)
        if indoor:
            seen = position in self.cells
            array.add(position, seen)                      # even when not loaded: a load hint
        else:
            seen = is_land(position) and block_of(position) in self.blocks
            self.add_outside(array, position, spheres)

        containing = 0
        if seen and spheres:
            self.transit_closure(array, position, spheres)
            containing = self.pick(array, position, spheres[0])

        # The visibility filter belongs to static placement only: a movement transition loads cells (facts §4 step 5,
        # §6.14), and retail runs it after an interior pick too.
        if not load_cells and indoor and seen and spheres:
            self.filter_visible(array, position)
        return array.ids, containing, [array.loaded[c] for c in array.ids]

    def transit_closure(self, array, position, spheres):
        """Every loaded candidate, including those added on the way, adds what its portals reach (facts §4 step 4a)."""
        i = 0
        while i < len(array.ids):
            cell = array.ids[i]
            if array.loaded[cell]:
                if is_env(cell):
                    self.env_transit(array, self.cells[cell], position, spheres)
                elif is_land(cell):
                    self.add_outside(array, position, spheres)
                    self.enter_building(array, cell, spheres)
            i += 1

    def env_transit(self, array, cell, position, spheres):
        """EnvCell.find_transit_cells, spheres (facts §5.1). The centres are used with no block offset (facts §6.11)."""
        leaves = False
        for portal in cell.portals:
            if portal.other in self.cells:
                # A loaded neighbour: some sphere touches it, in its own frame (facts §5.1).
                if self.cells[portal.other].touches(spheres):
                    array.add(portal.other, True)
                continue
            # Distances to this cell's portal plane, radius padded by EPS.
            reach = [(distance(portal.plane, cell.to_local((x, y, z))), r + EPSILON) for (x, y, z, r) in spheres]
            if portal.other is None:
                # An exit: a sphere straddling the infinite plane, both bounds strict, no side test (facts §6.9).
                leaves = leaves or any(-big < d < big for (d, big) in reach)
            elif any(self.towards_other_side(portal.side, d, big) for (d, big) in reach):
                array.add(portal.other, False)             # a load hint, under the neighbour's full id (facts §7 #11)
        if leaves:
            self.add_outside(array, position, spheres)

    def towards_other_side(self, portal_side, d, big):
        # PortalSide: the owning cell is on the plane's negative side, the neighbour on the positive (facts §5.4).
        if self.bug == "portal-side-inverted":
            portal_side = not portal_side                  # the seed's "intuition" paragraph, which is backwards
        return d > -big if portal_side else d < big

    def enter_building(self, array, land_cell, spheres):
        """A land cell's building: each portal's env cell that some sphere touches is entered (facts §5.3)."""
        for (cell, portal) in self.buildings.get(land_cell, ()):
            if portal != NO_PORTAL and cell in self.cells and self.cells[cell].touches(spheres):
                array.add(cell, True)

    def pick(self, array, position, sphere):
        """The containing cell for sphere 0's centre: the first env cell holding it, else the last land cell (facts §4 step 4b)."""
        picked = 0
        for cell in array.ids:
            if not array.loaded[cell] or not (is_env(cell) or is_land(cell)):
                continue
            dx, dy = block_offset(position, cell)
            x, y = f32(sphere[0] - dx), f32(sphere[1] - dy)   # the centre in the candidate's block frame
            if is_env(cell):
                if self.cells[cell].holds((x, y, sphere[2])):
                    return cell
            elif self.land.contains(cell, x, y):
                picked = cell
        return picked

    def filter_visible(self, array, position):
        """Keeps the position's cell, the loaded cells it sees, and every load hint (facts §4 step 5)."""
        sees = self.cells[position].visible
        for cell in list(array.ids):
            if array.loaded[cell] and cell != position and not (cell in sees and cell in self.cells):
                array.remove(cell)


class Scenes:
    """The scenes a request names: loaded once by load_scene (docs/protocol.md, "Loading a scene once") or sent whole."""

    def __init__(self, land, bug=None):
        self.land = land
        self.bug = bug
        self.loaded = {}
        self.next = 1
        self.last = (None, None)       # a scene sent whole with every query: the last one, by its text

    def load(self, request):
        if "scene" not in request:
            raise SceneError("load_scene takes a scene as JSON (dat_records is not offered)")
        scene_id = request.get("scene_id")
        if scene_id is None:
            scene_id = "s%d" % self.next
            self.next += 1
        elif not isinstance(scene_id, str) or scene_id in self.loaded:
            # pipeline: the tool chose the id (docs/protocol.md, "Pipelining"); it must be new.
            raise SceneError("scene_id %r is not a new string" % (scene_id,))
        self.loaded[scene_id] = Scene(request["scene"], self.land, self.bug)
        return {"scene_id": scene_id}

    def unload(self, request):
        if self.loaded.pop(request.get("scene_id"), None) is None:
            raise SceneError("no scene %r is loaded" % (request.get("scene_id"),))
        return {"ok": True}

    def of(self, request):
        """The request's scene, or None for open land (`"scene": null`)."""
        if "scene_id" in request:
            scene = self.loaded.get(request["scene_id"])
            if scene is None:
                raise SceneError("no scene %r is loaded" % (request["scene_id"],))
            return scene
        item = request.get("scene")
        if item is None:
            return None
        text = json.dumps(item, sort_keys=True)
        if self.last[0] != text:
            self.last = (text, Scene(item, self.land, self.bug))
        return self.last[1]
