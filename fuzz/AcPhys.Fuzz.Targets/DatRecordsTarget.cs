using AcPhys.Formats;
using AcPhys.Formats.Dat;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>dat-records</c> parser target: bytes → the record reader (docs/dat-scenes.md). The first byte picks the
/// record type (EnvCell, Environment, LandblockInfo, Landblock); the rest is the record, whose id is taken from its
/// own first 4 bytes. Only <see cref="InputFormatException"/> may escape; an accepted record must write back to the same bytes.
/// </summary>
public sealed class DatRecordsTarget : FuzzTarget
{
    /// <inheritdoc/>
    public override string Name => "dat-records";

    /// <inheritdoc/>
    public override string Description => "the dat record reader on one record (type byte + record bytes); only InputFormatException may escape";

    /// <inheritdoc/>
    public override TargetKind Kind => TargetKind.Parser;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = BuildSeeds();

    /// <inheritdoc/>
    public override IReadOnlyList<string> Dictionary => ["LEAF", "PORT", "nnPB", "NnPB", "nNpB", "\x01\x00\x00\x0D", "\xFE\xFF", "\xFF\xFF"];

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data =>
        {
            try
            {
                Run(data);
            }
            catch (InputFormatException)
            {
                // a clean rejection is the reader doing its job
            }
        };
    }

    /// <summary>Encodes one record as an input of this target.</summary>
    /// <param name="type">The record type.</param>
    /// <param name="record">The record bytes.</param>
    /// <returns>The input.</returns>
    public static byte[] Input(RecordType type, byte[] record) => [(byte)type, .. record];

    private static void Run(ReadOnlySpan<byte> data)
    {
        if (data.Length < 5)
        {
            return;
        }

        var record = data[1..].ToArray();
        uint id = BitConverter.ToUInt32(record, 0);
        switch ((RecordType)(data[0] % 4))
        {
            case RecordType.EnvCell:
                Same(EnvCellRecord.Read(record, id).Write(), record);
                break;
            case RecordType.Environment:
                var structs = EnvironmentCodec.Read(record, id);
                foreach (var s in structs)
                {
                    _ = CellStructPieces.Of(s.CellBsp, "fuzz");
                }

                break;
            case RecordType.LandblockInfo:
                _ = LandblockInfoRecord.Read(record, id).Write();
                break;
            default:
                LandblockRecord.ReadFlat(record, id);
                break;
        }
    }

    private static void Same(byte[] written, byte[] read)
    {
        if (!written.AsSpan().SequenceEqual(read))
        {
            throw new RoundTripException("dat-records: an accepted EnvCell does not write back to the same bytes");
        }
    }

    private static Dictionary<string, byte[]> BuildSeeds()
    {
        var scenes = new Dictionary<string, AcPhys.Contract.Scene>
        {
            ["cottage"] = AcPhys.Spec.Scenes.SceneKit.Cottage(new AcPhys.Spec.Scenes.CottagePlan((192.0 * 0x40) + 50, (192.0 * 0x41) + 60, 0.5f, 3, 6, 5, 0x5A, BackDoor: true, Storey: true)),
            ["dungeon"] = AcPhys.Spec.Scenes.SceneKit.Dungeon(new AcPhys.Spec.Scenes.DungeonPlan((192.0 * 0x20) + 150, (192.0 * 0x21) + 30, 4, 8, 1, 0x33)),
        };
        var seeds = new Dictionary<string, byte[]>();
        foreach (var (name, scene) in scenes)
        {
            foreach (var (record, bytes) in DatSceneWriter.Write(scene, name, name).Records.Where(r => r.Record.Type != RecordType.Landblock).Take(4))
            {
                seeds[$"{name}-{record.File}"] = Input(record.Type, bytes);
            }
        }

        seeds["landblock"] = Input(RecordType.Landblock, LandblockRecord.WriteFlat(0x4041FFFF, hasObjects: true));
        return seeds;
    }
}
