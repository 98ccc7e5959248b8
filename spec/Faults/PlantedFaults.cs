using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Faults;

/// <summary>The catalogue of planted faults and a factory for adapters that carry them.</summary>
public static class PlantedFaults
{
    /// <summary>Truncation toward zero instead of floor in get_outside_lcoord.</summary>
    public static readonly PlantedFault TruncFloor = new(
        "trunc-floor",
        "get_outside_lcoord truncates x/24 toward zero instead of flooring",
        "facts §6.2: negative block-local coordinates are normal near west/south edges; (int)(x/24) maps x = −0.5 into cell 0 of the same block instead of the previous block.",
        ["OUTSIDE-LCOORD-GEOMETRY", "ADJUST-GEOMETRY", "ADJUST-RANGE"]);

    /// <summary>NaN converted to an int before the range check.</summary>
    public static readonly PlantedFault NanAsZero = new(
        "nan-as-zero",
        "get_outside_lcoord converts to int before the range test, so NaN becomes lcoord 0",
        "issue #2: since .NET 9 (int)float.NaN is 0 on x64 (saturating conversions), so a port that range-tests the int accepts NaN as column 0.",
        ["NONFINITE-REJECTED", "OUTSIDE-LCOORD-GEOMETRY", "ADJUST-GEOMETRY"]);

    /// <summary>Map edge off by one.</summary>
    public static readonly PlantedFault MapEdge2040 = new(
        "map-edge-2040",
        "in_bounds tests ≤ 2040 instead of < 2040",
        "facts §6.3: lcoord 2040 is off the map (block byte 0xFF); an off-by-one range test manufactures ids in block 0xFF.",
        ["MAP-EDGE", "OUTSIDE-LCOORD-GEOMETRY"]);

    /// <summary>Sign-extended block_y byte.</summary>
    public static readonly PlantedFault SignExtendBlockY = new(
        "sign-extend-by",
        "block_y read as a signed byte",
        "seed (#106 commit): a decompiler rendered block_y as int8_t; blocks 0x80..0xFE then get negative lcoords.",
        ["LCOORD-ROUNDTRIP", "LCOORD-BLOCK", "OUTSIDE-LCOORD-GEOMETRY"]);

    /// <summary>Dropped 192 m block-length constant in the re-base.</summary>
    public static readonly PlantedFault DropBlockLength = new(
        "drop-block-length",
        "AdjustToOutside re-bases with v − ⌊v/192⌋ (the 192 m factor dropped)",
        "seed (#106 commit): a decompiler dropped the 192f BlockLength constant from the re-base.",
        ["ADJUST-RANGE", "ADJUST-PRESERVES-POSITION"]);

    /// <summary>Missing EPS snap.</summary>
    public static readonly PlantedFault NoEpsSnap = new(
        "no-eps-snap",
        "AdjustToOutside does not snap |v| < EPS to 0",
        "facts §2.1 step 2, §6.4: without the snap −0.0001 moves to the previous block and a tiny negative re-bases to exactly 192.",
        ["ADJUST-GEOMETRY", "ADJUST-RANGE"]);

    /// <summary>ACE's X-only inbound_valid_cellid.</summary>
    public static readonly PlantedFault InboundXOnly = new(
        "inbound-x-only",
        "inbound_valid_cellid checks block X only (ACE)",
        "facts §7 #15: ACE tests only bx; retail tests bx and by, so 0x00FF0001 is valid in ACE.",
        ["MAP-EDGE"]);

    /// <summary>Gets every planted fault.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } =
        [TruncFloor, NanAsZero, MapEdge2040, SignExtendBlockY, DropBlockLength, NoEpsSnap, InboundXOnly];

    /// <summary>Finds a fault by id.</summary>
    /// <param name="id">The fault id.</param>
    /// <returns>The fault, or null.</returns>
    public static PlantedFault? Find(string id) => All.FirstOrDefault(f => string.Equals(f.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>Returns the reference implementation with the named fault switched on.</summary>
    /// <param name="id">The fault id.</param>
    /// <returns>The faulty adapter.</returns>
    /// <exception cref="ArgumentException">No fault has that id.</exception>
    public static ICellPhysics Create(string id)
    {
        var fault = Find(id) ?? throw new ArgumentException(
            $"unknown fault '{id}'; known: {string.Join(", ", All.Select(f => f.Id))}", nameof(id));
        return new FaultyLandDefs(fault);
    }
}
