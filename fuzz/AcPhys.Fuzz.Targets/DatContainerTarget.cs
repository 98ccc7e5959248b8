using AcPhys.Formats.Dat;
using AcPhys.Formats.Dat.Container;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>dat-container</c> parser target: bytes → a dat container in memory (docs/dat-container.md): header, the whole
/// directory, then every listed object (at most <see cref="MaxObjects"/>) through its block chain. Only
/// <see cref="DatContainerException"/> may escape; an accepted container, written again by the writer, must read back
/// the same objects.
/// </summary>
public sealed class DatContainerTarget : FuzzTarget
{
    /// <summary>The most objects one input fetches (each costs at most the input's length).</summary>
    public const int MaxObjects = 256;

    /// <inheritdoc/>
    public override string Name => "dat-container";

    /// <inheritdoc/>
    public override string Description => "the dat container reader (header, directory B-tree, block chains) on one container image; only DatContainerException may escape";

    /// <inheritdoc/>
    public override TargetKind Kind => TargetKind.Parser;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = BuildSeeds();

    /// <inheritdoc/>
    public override IReadOnlyList<string> Dictionary => ["\x00\x01\x00\x00", "\x00\x04\x00\x00", "\xB4\x06\x00\x00", "\x3D\x00\x00\x00", "\x3E\x00\x00\x00", "\xFF\xFF\xFF\xFF", "\xFE\xFF", "\xFF\xFF"];

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data =>
        {
            try
            {
                Run(data.ToArray());
            }
            catch (DatContainerException)
            {
                // a clean rejection is the reader doing its job
            }
        };
    }

    private static void Run(byte[] data)
    {
        List<(uint Id, byte[] Bytes)> objects;
        uint blockSize;
        using (var c = DatContainer.Open(new MemoryBlockSource(data, "fuzz")))
        {
            blockSize = c.Header.BlockSize;
            objects = [.. c.Ids.Take(MaxObjects).Select(id => (id, c.Read(id)))];
        }

        var again = DatContainerWriter.ToBytes(objects, DatSet.Cell, blockSize);
        using var back = DatContainer.Open(new MemoryBlockSource(again, "rewritten"));
        if (back.Count != objects.Count || objects.Any(o => !back.Read(o.Id).AsSpan().SequenceEqual(o.Bytes)))
        {
            throw new RoundTripException("dat-container: the objects of an accepted container do not come back from the writer's container");
        }
    }

    private static Dictionary<string, byte[]> BuildSeeds()
    {
        var cottage = AcPhys.Spec.Scenes.SceneKit.Cottage(new AcPhys.Spec.Scenes.CottagePlan((192.0 * 0x40) + 50, (192.0 * 0x41) + 60, 0.5f, 3, 6, 5, 0x5A, BackDoor: true, Storey: false));
        var records = DatSceneWriter.Write(cottage, "cottage", "cottage").Records;
        var filler = Enumerable.Range(0, 70).Select(i => ((uint)(0x01000000 + i), new byte[i % 5])).ToList();
        return new Dictionary<string, byte[]>
        {
            ["cottage-cell-256"] = DatContainerWriter.ToBytes(records.Where(r => !r.Record.PortalDat && r.Record.Type != RecordType.Landblock).Select(r => (r.Record.Id, r.Bytes)), DatSet.Cell, 256),
            ["two-level-directory-128"] = DatContainerWriter.ToBytes(filler, DatSet.Portal, 128),
            ["empty-64"] = DatContainerWriter.ToBytes([], DatSet.Cell, 64),
        };
    }
}
