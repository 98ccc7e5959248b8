using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// One building of an estate while it is drafted in the building frame: cells as boxes, portals as (inward normal,
/// point, other) — then mapped into each cell's own frame. Every portal is added in pairs, so each side's plane is
/// the same building-frame plane and the partner indices agree.
/// </summary>
internal sealed class EstateDraft(LandblockId block, ushort baseLow, Frame frame, float width, float depth, int flips)
{
    private readonly List<DraftCell> cells = [];
    private readonly List<(int Cell, int Portal, bool Valid)> doors = [];
    private int flipIndex;

    /// <summary>Returns cell i's full id.</summary>
    /// <param name="i">Draft index.</param>
    /// <returns>The id.</returns>
    public CellId Id(int i) => block.BlockCell.WithLow(cells[i].Low);

    /// <summary>Returns the south-west floor corner of a grid room, building frame.</summary>
    /// <param name="p">Grid position.</param>
    /// <returns>The corner.</returns>
    public Vector3 Corner((int X, int Y) p) => new(p.X * width, p.Y * depth, EstatePlan.Floor);

    /// <summary>Returns the midpoint of a grid room's wall, at the walk's height (z = 0), building frame.</summary>
    /// <param name="p">Grid position.</param>
    /// <param name="s">The wall.</param>
    /// <returns>The point.</returns>
    public Vector3 WallPoint((int X, int Y) p, GridSide s)
    {
        var c = new Vector3((p.X + 0.5f) * width, (p.Y + 0.5f) * depth, 0);
        return c + (EstateKit.Outward(s) * new Vector3(width / 2, depth / 2, 0));
    }

    /// <summary>Adds a grid room (draft index = room index while only rooms have been added).</summary>
    /// <param name="p">Grid position.</param>
    /// <param name="own">Whether it gets its own frame.</param>
    /// <param name="turns">Its quarter turns.</param>
    public void Room((int X, int Y) p, bool own, int turns)
    {
        var min = Corner(p);
        Add(own ? new CellPlacement(min, turns) : default, [(min, min + new Vector3(width, depth, EstatePlan.Height))]);
    }

    /// <summary>Adds the storey above a grid room.</summary>
    /// <param name="p">Grid position of the room below.</param>
    /// <param name="own">Whether it gets its own frame.</param>
    /// <returns>Its draft index.</returns>
    public int Storey((int X, int Y) p, bool own)
    {
        var min = Corner(p) + new Vector3(0, 0, EstatePlan.Height);
        return Add(own ? new CellPlacement(min + new Vector3(width, 0, 0), 1) : default, [(min, min + new Vector3(width, depth, EstatePlan.Height))]);
    }

    /// <summary>
    /// Where a stairwell starts across its room (fraction of the width): off the room's centre line, so that routes
    /// through door and wall midpoints never run along its west face (in its tie band the stairwell, when current,
    /// would be kept: facts §4 step 4b).
    /// </summary>
    public const float StairwellFrom = 0.6f;

    /// <summary>
    /// Adds a stairwell over the east 40 % of a grid room: a lower flight from the floor to 1 m into the storey, and an
    /// upper landing in the east fifth up to the storey's ceiling. It overlaps the room and the storey, as retail
    /// stairwells do (the pick order decides, facts §4 step 4b).
    /// </summary>
    /// <param name="p">Grid position.</param>
    /// <param name="own">Whether it gets its own frame.</param>
    /// <returns>Its draft index.</returns>
    public int Stairwell((int X, int Y) p, bool own)
    {
        var c = Corner(p);
        const float h = EstatePlan.Height;
        return Add(own ? new CellPlacement(c + new Vector3(width, depth, 0), 2) : default,
        [
            (c + new Vector3(width * StairwellFrom, 0, 0), c + new Vector3(width, depth, h + 1)),
            (c + new Vector3(width * 0.8f, 0, h), c + new Vector3(width, depth, 2 * h)),
        ]);
    }

    /// <summary>Adds a vestibule: a cell 0.25 m thick in front of a room's wall, outside the grid.</summary>
    /// <param name="room">The room's draft index.</param>
    /// <param name="p">Its grid position.</param>
    /// <param name="s">The wall.</param>
    /// <param name="own">Whether it gets its own frame.</param>
    /// <returns>Its draft index.</returns>
    public int Vestibule(int room, (int X, int Y) p, GridSide s, bool own)
    {
        var (min, max) = cells[room].Boxes[0];
        const float t = EstatePlan.VestibuleDepth;
        var (a, b) = s switch
        {
            GridSide.South => (min with { Y = min.Y - t }, max with { Y = min.Y }),
            GridSide.North => (min with { Y = max.Y }, max with { Y = max.Y + t }),
            GridSide.West => (min with { X = min.X - t }, max with { X = min.X }),
            _ => (min with { X = max.X }, max with { X = max.X + t }),
        };
        _ = p;
        return Add(own ? new CellPlacement(a, 3) : default, [(a, b)]);
    }

    /// <summary>Makes a room L-shaped: piece 0 is the room without a quarter strip along one wall, piece 1 half that strip.</summary>
    /// <param name="room">The room.</param>
    /// <param name="p">Its grid position.</param>
    /// <param name="s">The wall the notch is cut along (a free wall without a door).</param>
    public void Notch(int room, (int X, int Y) p, GridSide s)
    {
        var min = Corner(p);
        var max = min + new Vector3(width, depth, EstatePlan.Height);
        float qx = width / 4, qy = depth / 4, hx = width / 2, hy = depth / 2;
        cells[room].Boxes = s switch
        {
            GridSide.South => [(min with { Y = min.Y + qy }, max), (min, new Vector3(min.X + hx, min.Y + qy, max.Z))],
            GridSide.North => [(min, max with { Y = max.Y - qy }), (min with { Y = max.Y - qy }, new Vector3(min.X + hx, max.Y, max.Z))],
            GridSide.West => [(min with { X = min.X + qx }, max), (min, new Vector3(min.X + qx, min.Y + hy, max.Z))],
            _ => [(min, max with { X = max.X - qx }), (min with { X = max.X - qx }, new Vector3(max.X, min.Y + hy, max.Z))],
        };
    }

    /// <summary>Adds a portal pair between two cells through a point.</summary>
    /// <param name="a">A cell.</param>
    /// <param name="b">The other cell.</param>
    /// <param name="point">A point of the shared plane, building frame.</param>
    /// <param name="inwardA">The plane's normal pointing into <paramref name="a"/>.</param>
    public void Link(int a, int b, Vector3 point, Vector3 inwardA)
    {
        int ia = cells[a].Portals.Count, ib = cells[b].Portals.Count;
        cells[a].Portals.Add(Portal(inwardA, point, cells[b].Low, (ushort)ib));
        cells[b].Portals.Add(Portal(-inwardA, point, cells[a].Low, (ushort)ia));
    }

    /// <summary>Adds an exit portal to a cell and a building portal to it.</summary>
    /// <param name="cell">The cell.</param>
    /// <param name="point">A point of the door's plane.</param>
    /// <param name="outward">Outward normal.</param>
    /// <param name="valid">False to give the building portal the invalid marker.</param>
    public void Door(int cell, Vector3 point, Vector3 outward, bool valid)
    {
        doors.Add((cell, cells[cell].Portals.Count, valid));
        cells[cell].Portals.Add(Portal(-outward, point, CellPortal.Outside, 0xFFFF));
    }

    /// <summary>Returns the building (its portals in door order).</summary>
    /// <param name="origin">Its origin in its block's frame.</param>
    /// <returns>The building.</returns>
    public SceneBuilding Building(Vector3 origin) =>
        new(block, origin, [.. doors.Select(d => new SceneBldPortal(cells[d.Cell].Low, d.Valid ? (ushort)d.Portal : (ushort)0xFFFF))]);

    /// <summary>Returns the cells, each in its own frame, seeing its portal neighbours to a depth (0: every cell of the building).</summary>
    /// <param name="seeDepth">Visibility depth.</param>
    /// <returns>The cells.</returns>
    public List<SceneCell> Cells(int seeDepth)
    {
        var result = new List<SceneCell>();
        for (int i = 0; i < cells.Count; i++)
        {
            var c = cells[i];
            var inBlock = c.Place.InBlock(frame);
            var pieces = c.Boxes.Select(b => c.Place.ToLocal(b.Min, b.Max)).ToList();
            var portals = c.Portals.Select(p => p with { Plane = c.Place.ToLocal(p.Plane) }).ToList();
            result.Add(new SceneCell(Id(i), inBlock.Origin, inBlock.Rotation, pieces, portals, [.. Seen(i, seeDepth).Select(Id)]));
        }

        return result;
    }

    private IEnumerable<int> Seen(int from, int depth)
    {
        var dist = new Dictionary<int, int> { [from] = 0 };
        var queue = new Queue<int>([from]);
        while (queue.Count > 0)
        {
            int i = queue.Dequeue();
            foreach (var p in cells[i].Portals.Where(p => !p.IsExit))
            {
                int j = cells.FindIndex(c => c.Low == p.Other);
                if (j >= 0 && dist.TryAdd(j, dist[i] + 1))
                {
                    queue.Enqueue(j);
                }
            }
        }

        return dist.Where(kv => kv.Key != from && (depth <= 0 || kv.Value <= depth)).Select(kv => kv.Key).Order();
    }

    private ScenePortal Portal(Vector3 inward, Vector3 point, ushort other, ushort otherPortal)
    {
        bool flip = ((flips >> (flipIndex++ % 31)) & 1) != 0;
        return new ScenePortal(CellPlane.Through(flip ? inward : -inward, point), other, PortalSide: !flip, otherPortal);
    }

    private int Add(CellPlacement place, List<(Vector3 Min, Vector3 Max)> boxes)
    {
        cells.Add(new DraftCell((ushort)(baseLow + cells.Count), place) { Boxes = boxes });
        return cells.Count - 1;
    }

    private sealed record DraftCell(ushort Low, CellPlacement Place)
    {
        public List<(Vector3 Min, Vector3 Max)> Boxes { get; set; } = [];

        public List<ScenePortal> Portals { get; } = [];
    }
}
