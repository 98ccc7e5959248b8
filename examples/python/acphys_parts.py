"""The parts (bounding-box) cell list for acphys_impl.py: on open land (outside_cells_parts) and in a scene
(find_cell_parts_scene and find_cell_parts_transition).

Standard library only. Written from the facts specification (../shared/spec/retail-cell-physics-facts.md, "facts §x")
and docs/protocol.md ("Parts indoors"), not from the C# core. An object given by its parts instead of spheres: each part
has its own cell and frame (origin and rotation in that cell's block frame), a local bounding box and a sphere of radius
r centred on its origin. The first part is the anchor and its cell is the position. There is no containing-cell pick.

Retail's choices throughout: the outdoor parts variant anchors on the first part only, folds every part's box (or, for
Always2D, the square around its origin) into one range and adds the whole block of cells with no same-block guard
(facts §3.4); a building door pairs the box side with PortalSide as retail does, not ACE (facts §5.3, §7 #14; a port
that pairs as ACE does declares "ace-box-side-pairing").

Arithmetic follows acphys_indoor.py: float32 inputs, points moved between frames rounded to float32, rotations and
plane distances in double. HitsInteriorCell is not reported, as in the sphere variant (its invariants then compare
what is reported and skip the flag).
"""

import collections
import math

from acphys_indoor import EPSILON, NO_PORTAL, CellArray, block_of, block_offset, distance, f32, is_env, is_indoor, is_land

CELL_LENGTH = 24.0
LAND_LENGTH = 2040          # lcoords per map side (facts §1.3)

# cell: the part's cell id; origin (x, y, z) in that cell's block frame, also its sphere's centre; rotation (x, y, z, w);
# lo, hi: the local bounding box's corners; r: the sphere's radius; always2d: the part counts as a flat square (§3.4).
Part = collections.namedtuple("Part", "cell origin rotation lo hi r always2d")

# What the parts list needs of the outdoor half (acphys_impl.py):
#   adjust_to_outside(cell, x, y) -> (ok, cell, x, y)    facts §2.1
#   gid_to_lcoord(cell) -> (x, y) or None               facts §1.3
#   lcoord_to_gid(x, y) -> cell                          facts §1.3
Grid = collections.namedtuple("Grid", "adjust_to_outside gid_to_lcoord lcoord_to_gid")

POSITIVE, NEGATIVE, IN_PLANE, CROSSING = range(4)   # Sidedness (facts §5.7)


def to_global(part, v):
    """The part frame's LocalToGlobal: origin + R·v, R the rotation of the (assumed unit) quaternion (facts §5.8)."""
    x, y, z, w = part.rotation
    rx = (1 - 2 * (y * y + z * z)) * v[0] + 2 * (x * y - w * z) * v[1] + 2 * (x * z + w * y) * v[2]
    ry = 2 * (x * y + w * z) * v[0] + (1 - 2 * (x * x + z * z)) * v[1] + 2 * (y * z - w * x) * v[2]
    rz = 2 * (x * z - w * y) * v[0] + 2 * (y * z + w * x) * v[1] + (1 - 2 * (x * x + y * y)) * v[2]
    o = part.origin
    return (f32(o[0] + rx), f32(o[1] + ry), f32(o[2] + rz))


def corners(lo, hi):
    return [(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]) for k in range(8)]


def moved(point, target, source):
    """A point of source's block frame in target's block frame (GetBlockOffset, facts §5.8)."""
    dx, dy = block_offset(target, source)
    return (f32(point[0] + dx), f32(point[1] + dy), point[2])


def centre_in(cell, part):
    """Position.LocalToLocal of the part's sphere centre into an env cell's frame, block offset applied (facts §5.2)."""
    return cell.to_local(moved(part.origin, cell.id, part.cell))


def box_in(cell, part):
    """The part's box in an env cell's frame: its 8 corners carried over, then their axis-aligned hull."""
    points = [cell.to_local(moved(to_global(part, c), cell.id, part.cell)) for c in corners(part.lo, part.hi)]
    return (tuple(min(p[i] for p in points) for i in range(3)), tuple(max(p[i] for p in points) for i in range(3)))


def box_side(plane, box):
    """Plane.intersect_box (facts §5.7): Crossing when the min corner is within EPS; else every corner must agree with the
    min corner's side, a corner counting Positive when d > 0 and Negative when d < -2·EPS (the +EPS bias)."""
    d = distance(plane, box[0])
    if -EPSILON <= d <= EPSILON:
        return CROSSING
    provisional = POSITIVE if d > EPSILON else NEGATIVE
    for corner in corners(*box):
        e = distance(plane, corner)
        side = POSITIVE if e > 0 else NEGATIVE if e < -2 * EPSILON else IN_PLANE
        if side != provisional:
            return CROSSING
    return provisional


def box_touches(cell, box):
    """box_intersects_cell_bsp on the positive chain (facts §5.7): out only where a plane has every corner behind it."""
    for p in cell.planes:
        if distance(p, box[0]) >= -EPSILON:
            continue
        if all(distance(p, c) < -EPSILON for c in corners(*box)):
            return False
    return True


class PartsList:
    """One parts query over a scene (an acphys_indoor.Scene): its array, its latch, and the closure that fills it."""

    def __init__(self, scene, grid, parts):
        self.scene, self.grid, self.parts = scene, grid, parts
        self.array = CellArray()

    def run(self, load_cells):
        """Returns (ids, loaded flags). Seed, closure in insertion order, then the static filter (docs/protocol.md)."""
        array, scene = self.array, self.scene
        if not self.parts:
            return [], []
        position = self.parts[0].cell
        indoor = is_indoor(position)
        if indoor:
            seen = position in scene.cells
            array.add(position, seen)                     # even when not loaded: a load hint
        else:
            seen = is_land(position) and block_of(position) in scene.blocks
            self.add_outside()
        if seen:
            i = 0
            while i < len(array.ids):                     # cells added on the way are walked too (facts §4 step 4a)
                cell = array.ids[i]
                if array.loaded[cell]:
                    if is_env(cell) and cell in scene.cells:
                        self.env_transit(scene.cells[cell])
                    elif is_land(cell):
                        self.add_outside()                # latched: a no-op after the first (facts §3.5)
                        self.enter_building(cell)
                i += 1
        if not load_cells and indoor and seen:
            scene.filter_visible(array, position)         # static placement only (facts §4 step 5, §6.14)
        return array.ids, [array.loaded[c] for c in array.ids]

    def add_outside(self):
        """add_all_outside_cells, parts, retail (facts §3.4): the first part anchors one block of cells."""
        array = self.array
        if array.added_outside:
            return
        array.added_outside = True
        anchor = self.parts[0]
        ok, land, _, _ = self.grid.adjust_to_outside(anchor.cell, anchor.origin[0], anchor.origin[1])
        lcoord = self.grid.gid_to_lcoord(land) if ok else None
        if lcoord is None:
            return                                        # retail: the anchor's land cell must resolve
        own_x, own_y = ((land & 0xFFFF) - 1) >> 3, ((land & 0xFFFF) - 1) & 7
        lo_x = lo_y = hi_x = hi_y = 0                     # the range always holds the anchor's own cell
        for part in self.parts:
            if part.always2d:
                # the square of the sphere around the part's raw origin
                x, y, _ = moved(part.origin, land, part.cell)
                xs, ys = (f32(x - part.r), f32(x + part.r)), (f32(y - part.r), f32(y + part.r))
            else:
                points = [moved(to_global(part, c), land, part.cell) for c in corners(part.lo, part.hi)]
                xs = (min(p[0] for p in points), max(p[0] for p in points))
                ys = (min(p[1] for p in points), max(p[1] for p in points))
            if not all(math.isfinite(v) for v in xs + ys):
                continue                                  # a part with no finite extent names no cell
            lo_x, hi_x = min(lo_x, math.floor(xs[0] / CELL_LENGTH) - own_x), max(hi_x, math.floor(xs[1] / CELL_LENGTH) - own_x)
            lo_y, hi_y = min(lo_y, math.floor(ys[0] / CELL_LENGTH) - own_y), max(hi_y, math.floor(ys[1] / CELL_LENGTH) - own_y)
        # add_cell_block: x outer, y inner; off-map lcoords skipped (so the loops stop at the map's edges); no same-block
        # guard in retail, and a cell of an unloaded block is added as a load hint.
        gx, gy = lcoord
        for i in range(max(gx + lo_x, 0), min(gx + hi_x, LAND_LENGTH - 1) + 1):
            for j in range(max(gy + lo_y, 0), min(gy + hi_y, LAND_LENGTH - 1) + 1):
                cell = self.grid.lcoord_to_gid(i, j)
                array.add(cell, block_of(cell) in self.scene.blocks)

    def env_transit(self, cell):
        """EnvCell.find_transit_cells, parts (facts §5.2): per portal, the first part that passes every gate decides."""
        leaves = False
        for portal in cell.portals:
            for part in self.parts:
                reach, d = part.r + EPSILON, distance(portal.plane, centre_in(cell, part))
                # the sphere must reach the neighbour's side: PortalSide puts the neighbour on the positive side (§5.4)
                if (d < -reach) if portal.side else (d > reach):
                    continue
                side = box_side(portal.plane, box_in(cell, part))
                if (side == POSITIVE and not portal.side) or (side == NEGATIVE and portal.side):
                    continue                              # the box lies wholly on this cell's side
                if portal.other is None:
                    leaves = True
                    break
                other = self.scene.cells.get(portal.other)
                if other is None:
                    self.array.add(portal.other, False)   # a load hint under the neighbour's full id
                    break
                if box_touches(other, box_in(other, part)):
                    self.array.add(other.id, True)
                    break
        if leaves:
            self.add_outside()

    def enter_building(self, land_cell):
        """The land cell's building: each door's env cell checks the parts (facts §5.3)."""
        for (cell_id, portal_id) in self.scene.buildings.get(land_cell, ()):
            cell = self.scene.cells.get(cell_id)
            if cell is not None:
                self.building_transit(cell, portal_id)

    def building_transit(self, cell, portal_id):
        """EnvCell.check_building_transit, parts (facts §5.3): entering, so the sphere gate is the mirror of §5.2's, and
        the box must cross the door or lie on the cell's own side (retail: the side equal to portal_side)."""
        if portal_id == NO_PORTAL or portal_id >= len(cell.portals):
            return
        portal = cell.portals[portal_id]
        own_side = NEGATIVE if portal.side else POSITIVE
        for part in self.parts:
            reach, d = part.r + EPSILON, distance(portal.plane, centre_in(cell, part))
            if (d > reach) if portal.side else (d < -reach):
                continue
            box = box_in(cell, part)
            side = box_side(portal.plane, box)
            if side in (CROSSING, own_side) and box_touches(cell, box):
                self.array.add(cell.id, True)
                self.env_transit(cell)
                return


class OpenLand:
    """The world of outside_cells_parts: open land with every block loaded, no env cell and no building."""

    class EveryBlock:
        def __contains__(self, block):
            return True

    blocks = EveryBlock()


def outside_cells_parts(grid, parts):
    """outside_cells_parts (docs/protocol.md, facts §3.4): the land cells of the parts' boxes on open land, in insertion
    order, from a fresh array (its AddedOutside latch clear, facts §3.5); the first part is the anchor. No parts, no cells."""
    if not parts:
        return []
    query = PartsList(OpenLand(), grid, parts)
    query.add_outside()
    return query.array.ids


def find_cell_parts(scene, grid, parts, load_cells):
    """The parts cell list in a scene: (ids, loaded flags); static placement unless load_cells."""
    return PartsList(scene, grid, parts).run(load_cells)

