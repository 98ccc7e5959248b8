using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace ExamplePort;

/// <summary>
/// An example port under the gate: LandDefs and the outdoor cell sets written from the facts (§1–§4), announcing the
/// six LandDefs ops, <c>outside_cells</c> and <c>find_cell</c> and nothing else. <c>ACPHYS_PORT_BUG</c> switches on
/// one of its seeded bugs (<see cref="Bug"/>).
/// </summary>
public sealed class ExamplePort : ICellPhysics
{
    private readonly Bug bug;
    private readonly Grid grid;
    private readonly Outdoor outdoor;

    /// <summary>Initializes a new instance with the bug <c>ACPHYS_PORT_BUG</c> names, if any.</summary>
    public ExamplePort()
        : this(Bugs.FromEnvironment())
    {
    }

    /// <summary>Initializes a new instance with a given bug.</summary>
    /// <param name="bug">The bug.</param>
    public ExamplePort(Bug bug)
    {
        this.bug = bug;
        grid = new Grid(bug);
        outdoor = new Outdoor(grid, bug);
    }

    /// <inheritdoc/>
    public string Name => bug == Bug.None ? "example-port" : "example-port+" + Bugs.Names.First(n => n.Value == bug).Key;

    /// <inheritdoc/>
    public Op Ops => Op.LandDefs | Op.OutsideCells | Op.FindCell;

    /// <inheritdoc/>
    public PickPolicy Pick => PickPolicy.Retail;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => Out(grid.BlockOrigin(id), out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => Out(grid.CellLcoord(id), out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => grid.CellAt(x, y);

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => bug == Bug.Hang && id.Value == Bugs.HangCell ? Bugs.Forever() : grid.InboundValid(id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => Out(grid.ColumnUnder(id, x, y), out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y)
    {
        var (ok, cell, ax, ay) = grid.Reseat(id, x, y);
        return new AdjustResult(ok, cell, ax, ay);
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, Vector3.Zero, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => outdoor.Cells(cell, origin, spheres);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, Vector3.Zero, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current)
    {
        if ((cell.Value & 0xFFFF) >= 0x100)
        {
            // Indoor by its low word (env cells and the block id 0xFFFF, facts §1.1): seeded as itself, and on open land
            // it is not loaded, so nothing is reached from it and nothing is picked (facts §4 steps 3-4).
            return new FindCellResult([cell], default) { Loaded = [false], HitsInteriorCell = true };
        }

        var cells = outdoor.Cells(cell, origin, spheres);
        bool loaded = grid.CellLcoord(cell) is not null; // every block is loaded on open land
        var containing = loaded && spheres.Count > 0 ? outdoor.Pick(cell, cells, spheres[0].Center) : default;
        return new FindCellResult(cells, containing) { Loaded = [.. cells.Select(_ => true)], HitsInteriorCell = false };
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => throw new NotSupportedException("not ported: outside_cells_parts");

    private static bool Out(Lcoord? value, out Lcoord lcoord)
    {
        lcoord = value ?? default;
        return value is not null;
    }
}
