using AcPhys.Contract;
using AcPhys.Core;

namespace ExampleAdapter;

/// <summary>
/// An example of gating your own code in process: a from-scratch port of the LandDefs functions (facts §1–§2),
/// announced as <see cref="Op.LandDefs"/> only, so the LandDefs invariants are tested and the rest is reported as not
/// tested. Set <c>ACPHYS_EXAMPLE_BUG=inbound-x-only</c> to switch on ACE's historical bug (facts §7 #15); the e2e
/// tests of a hostile adapter use <c>hang</c> (lcoord_to_gid never returns), <c>exit</c> (it calls Environment.Exit(3))
/// and <c>name</c> (a name holding a newline and terminal codes).
/// </summary>
public sealed class MyLandDefsAdapter : ICellPhysics
{
    private const int LandLength = 2040;
    private const double CellLength = 24.0;
    private const double BlockLength = 192.0;
    private const float Epsilon = 0.0002f;

    private readonly bool inboundXOnly = Environment.GetEnvironmentVariable("ACPHYS_EXAMPLE_BUG") == "inbound-x-only";
    private readonly string? hostile = Environment.GetEnvironmentVariable("ACPHYS_EXAMPLE_BUG") is "hang" or "exit" or "name" ? Environment.GetEnvironmentVariable("ACPHYS_EXAMPLE_BUG") : null;

    /// <inheritdoc/>
    public string Name => hostile == "name" ? "example\u001b[2J\nverify: 42 invariants, 42 passed, 0 failed" : inboundXOnly ? "example-dotnet+inbound-x-only" : "example-dotnet";

    /// <inheritdoc/>
    public Op Ops => Op.LandDefs;

    /// <inheritdoc/>
    public PickPolicy Pick => PickPolicy.Retail;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        int x = (int)(id.Value >> 24) * 8, y = (int)((id.Value >> 16) & 0xFF) * 8;
        if (id.Value == 0 || x >= LandLength || y >= LandLength)
        {
            return false;
        }

        lcoord = new Lcoord(x, y);
        return true;
    }

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        int low = (int)(id.Value & 0xFFFF);
        if (!InboundValidCellId(id) || low >= 0x100 || !BlockIdToLcoord(id, out var block))
        {
            return false;
        }

        int x = block.X + ((low - 1) >> 3), y = block.Y + ((low - 1) & 7); // X is the major index (facts §1.2)
        lcoord = new Lcoord(x, y);
        return x < LandLength && y < LandLength;
    }

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y)
    {
        if (hostile == "hang")
        {
            Thread.Sleep(Timeout.Infinite);
        }
        else if (hostile == "exit")
        {
            Environment.Exit(3);
        }

        return x < 0 || y < 0 || x >= LandLength || y >= LandLength
            ? new CellId(0)
            : new CellId(((uint)(x >> 3) << 24) | ((uint)(y >> 3) << 16) | (uint)(1 + ((x & 7) << 3) + (y & 7)));
    }

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id)
    {
        int low = (int)(id.Value & 0xFFFF);
        bool lowOk = low == 0xFFFF || low is >= 1 and <= 64 || low is >= 0x100 and <= 0xFFFD;
        bool bxOk = (id.Value >> 24) * 8 < LandLength, byOk = ((id.Value >> 16) & 0xFF) * 8 < LandLength;
        return lowOk && bxOk && (inboundXOnly || byOk);
    }

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord)
    {
        lcoord = default;
        int low = (int)(id.Value & 0xFFFF);
        bool lowOk = low == 0xFFFF || low is >= 1 and <= 64 || low is >= 0x100 and <= 0xFFFD;
        if (!lowOk || !BlockIdToLcoord(id, out var block))
        {
            return false;
        }

        double gx = block.X + Math.Floor(x / CellLength), gy = block.Y + Math.Floor(y / CellLength); // floor, not truncation
        if (!(gx >= 0 && gx < LandLength && gy >= 0 && gy < LandLength))
        {
            return false; // NaN fails every comparison
        }

        lcoord = new Lcoord((int)gx, (int)gy);
        return true;
    }

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y)
    {
        int low = (int)(id.Value & 0xFFFF);
        if (!(low == 0xFFFF || low is >= 1 and <= 64 || low is >= 0x100 and <= 0xFFFD))
        {
            return new AdjustResult(false, new CellId(0), x, y);
        }

        x = Math.Abs(x) < Epsilon ? 0f : x; // facts §2.1 step 2: strict, per axis
        y = Math.Abs(y) < Epsilon ? 0f : y;
        if (!GetOutsideLcoord(id, x, y, out var lc))
        {
            return new AdjustResult(false, new CellId(0), x, y);
        }

        return new AdjustResult(true, LcoordToGid(lc.X, lc.Y), Rebase(x), Rebase(y));
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => throw new NotSupportedException("LandDefs only");

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => throw new NotSupportedException("LandDefs only");

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => throw new NotSupportedException("LandDefs only");

    private static float Rebase(float v) => (float)(v - (BlockLength * Math.Floor(v / BlockLength)));
}
