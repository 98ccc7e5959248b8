namespace AcPhys.Spec.Scenes;

/// <summary>A wall side of a grid room, in the building frame.</summary>
public enum GridSide
{
    /// <summary>−y.</summary>
    South,

    /// <summary>+y.</summary>
    North,

    /// <summary>−x.</summary>
    West,

    /// <summary>+x.</summary>
    East,
}

/// <summary>The room grid of an estate: where each room sits, which rooms share a wall (a portal unless sealed), which walls are free.</summary>
internal static class EstateGrid
{
    private static readonly (int X, int Y)[] RowAt = [(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)];
    private static readonly (int X, int Y)[] BranchAt = [(0, 0), (1, 0), (2, 0), (1, 1), (1, -1), (2, 1)];
    private static readonly (int X, int Y)[] RingAt = [(0, 0), (1, 0), (1, 1), (0, 1), (2, 0), (2, 1)];

    /// <summary>Returns the grid positions of the rooms; dropping the last room keeps the others connected.</summary>
    /// <param name="layout">The layout.</param>
    /// <param name="rooms">How many rooms.</param>
    /// <returns>Positions, room i at index i.</returns>
    public static (int X, int Y)[] Positions(EstateLayout layout, int rooms) =>
        [.. (layout switch { EstateLayout.Branch => BranchAt, EstateLayout.Ring => RingAt, _ => RowAt }).Take(rooms)];

    /// <summary>Returns the room pairs sharing a wall (a &lt; b), in a fixed order.</summary>
    /// <param name="at">Positions.</param>
    /// <returns>The pairs and the side of room a the wall is on.</returns>
    public static List<(int A, int B, GridSide Side)> Links((int X, int Y)[] at)
    {
        var links = new List<(int, int, GridSide)>();
        for (int a = 0; a < at.Length; a++)
        {
            for (int b = a + 1; b < at.Length; b++)
            {
                if (SideTo(at[a], at[b]) is { } side)
                {
                    links.Add((a, b, side));
                }
            }
        }

        return links;
    }

    /// <summary>Returns the shared walls that are portal pairs: <see cref="Links"/> without the sealed ones.</summary>
    /// <param name="at">Positions.</param>
    /// <param name="sealedWalls">Bit k: link k is sealed.</param>
    /// <returns>The open pairs, in <see cref="Links"/> order.</returns>
    public static List<(int A, int B, GridSide Side)> OpenLinks((int X, int Y)[] at, int sealedWalls) =>
        [.. Links(at).Where((_, k) => k >= 31 || ((sealedWalls >> k) & 1) == 0)];

    /// <summary>Returns the free walls of a room (no room behind them), in preference order south, north, west, east.</summary>
    /// <param name="at">Positions.</param>
    /// <param name="room">The room.</param>
    /// <returns>The free sides.</returns>
    public static IEnumerable<GridSide> FreeSides((int X, int Y)[] at, int room) =>
        new[] { GridSide.South, GridSide.North, GridSide.West, GridSide.East }.Where(s => !at.Contains(Step(at[room], s)));

    /// <summary>Returns the opposite side.</summary>
    /// <param name="s">A side.</param>
    /// <returns>Its opposite.</returns>
    public static GridSide Opposite(GridSide s) => s switch { GridSide.South => GridSide.North, GridSide.North => GridSide.South, GridSide.West => GridSide.East, _ => GridSide.West };

    /// <summary>Returns the grid position across a side.</summary>
    /// <param name="p">A position.</param>
    /// <param name="s">A side.</param>
    /// <returns>The neighbouring position.</returns>
    public static (int X, int Y) Step((int X, int Y) p, GridSide s) => s switch
    {
        GridSide.South => (p.X, p.Y - 1),
        GridSide.North => (p.X, p.Y + 1),
        GridSide.West => (p.X - 1, p.Y),
        _ => (p.X + 1, p.Y),
    };

    /// <summary>Returns the shortest room path from one room to another over open shared walls (breadth-first, links in order).</summary>
    /// <param name="at">Positions.</param>
    /// <param name="sealedWalls">Bit k: link k is sealed (not passable).</param>
    /// <param name="from">Start room.</param>
    /// <param name="to">End room.</param>
    /// <param name="avoid">A room not to pass through (−1 for none).</param>
    /// <returns>The rooms, from first to last, or null when unreachable.</returns>
    public static List<int>? Path((int X, int Y)[] at, int sealedWalls, int from, int to, int avoid)
    {
        var links = OpenLinks(at, sealedWalls);
        var back = new Dictionary<int, int> { [from] = from };
        var queue = new Queue<int>([from]);
        while (queue.Count > 0)
        {
            int r = queue.Dequeue();
            if (r == to)
            {
                var path = new List<int> { r };
                while (path[0] != from)
                {
                    path.Insert(0, back[path[0]]);
                }

                return path;
            }

            foreach (var (a, b, _) in links)
            {
                int next = a == r ? b : b == r ? a : -1;
                if (next >= 0 && next != avoid && back.TryAdd(next, r))
                {
                    queue.Enqueue(next);
                }
            }
        }

        return null;
    }

    private static GridSide? SideTo((int X, int Y) a, (int X, int Y) b) =>
        (b.X - a.X, b.Y - a.Y) switch
        {
            (0, -1) => GridSide.South,
            (0, 1) => GridSide.North,
            (-1, 0) => GridSide.West,
            (1, 0) => GridSide.East,
            _ => null,
        };
}
