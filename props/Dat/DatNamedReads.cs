using System.Text;
using AcPhys.Formats;
using AcPhys.Formats.Dat;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>
/// The record readers read unnamed first and repeat a refused read with field paths spelled out (issue 26,
/// <see cref="ByteReader.Strictly{T}"/>): what a caller sees must be exactly what a reader that always names fields gives.
/// </summary>
public sealed class DatNamedReads(ITestOutputHelper output)
{
    private const int Seed = 0x26C;

    [Fact(DisplayName = "DAT-NAMED: a damaged record is refused with the always-named reader's message, byte for byte, and accepted exactly when it accepts (12,000 damaged records of 300 generated scenes, seed 0x26C)")]
    public void TwoPassReadsAnswerAsTheNamedReader()
    {
        var random = new Random(Seed);
        var records = DatTestSupport.Generated(150, 0xDA80).Concat(DatTestSupport.MultiPiece(150, 0xDA81))
            .SelectMany(s => DatSceneWriter.Write(s, "test", "memory").Records)
            .Where(r => r.Record.Type != RecordType.Environment || random.Next(4) == 0) // one Environment per scene: keep a quarter
            .ToArray();
        var outcomes = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < 12_000; i++)
        {
            var (record, original) = records[random.Next(records.Length)];
            var (damage, bytes) = Damage(original, random);
            string twoPass = Outcome(() => Read(record, bytes, named: null));
            string named = Outcome(() => Read(record, bytes, named: true));
            Assert.True(twoPass == named, $"seed {Seed}, damage {i} ({damage}) of {record.Type} {RecordIds.Text(record.Id)}: the reader gave {twoPass}; the always-named reader {named}");
            string key = $"{record.Type}: {(named.StartsWith("refused", StringComparison.Ordinal) ? "refused" : "accepted")}";
            outcomes[key] = outcomes.GetValueOrDefault(key) + 1;
        }

        foreach (var (key, n) in outcomes.OrderBy(e => e.Key, StringComparer.Ordinal))
        {
            output.WriteLine($"{key,-32} {n,6}");
        }

        // Every record type is both refused and accepted somewhere, so both branches of the comparison are exercised.
        foreach (var type in new[] { RecordType.Landblock, RecordType.LandblockInfo, RecordType.EnvCell, RecordType.Environment })
        {
            Assert.True(outcomes.GetValueOrDefault($"{type}: refused") > 20, $"too few refused {type} records: {outcomes.GetValueOrDefault($"{type}: refused")}");
            Assert.True(outcomes.GetValueOrDefault($"{type}: accepted") > 5, $"too few accepted {type} records: {outcomes.GetValueOrDefault($"{type}: accepted")}");
        }
    }

    // named null: the public two-pass read; true: a reader that names every field from the start.
    private static string Read(ManifestRecord r, byte[] bytes, bool? named) => r.Type switch
    {
        RecordType.Landblock => (named is { } n ? LandblockRecord.ReadFlat(bytes, r.Id, n) : LandblockRecord.ReadFlat(bytes, r.Id)).ToString(),
        RecordType.LandblockInfo => Describe(named is { } n ? LandblockInfoRecord.Read(bytes, r.Id, n) : LandblockInfoRecord.Read(bytes, r.Id)),
        RecordType.EnvCell => Describe(named is { } n ? EnvCellRecord.Read(bytes, r.Id, n) : EnvCellRecord.Read(bytes, r.Id)),
        RecordType.Environment => string.Join(";", (named is { } n ? EnvironmentCodec.Read(bytes, r.Id, n) : EnvironmentCodec.Read(bytes, r.Id)).Select(s => $"{s.Key}/{s.Vertices.Count}/{s.Polygons.Count}/{s.PortalPolygonIds.Count}")),
        _ => throw new InvalidOperationException($"no reader for {r.Type}"),
    };

    private static string Describe(LandblockInfoRecord r) => $"{r.Id}/{r.NumCells}/{r.Buildings.Count}";

    private static string Describe(EnvCellRecord r) => $"{r.Id}/{r.Flags}/{r.Portals.Count}/{r.VisibleCells.Count}/{r.Origin}";

    private static string Outcome(Func<string> read)
    {
        try
        {
            return "accepted " + read();
        }
        catch (InputFormatException e)
        {
            return "refused: " + e.Message;
        }
    }

    // A port's dat or a transfer can damage a record anywhere: one byte set, a count inflated, the end cut or extended.
    private static (string What, byte[] Bytes) Damage(byte[] original, Random random)
    {
        var bytes = (byte[])original.Clone();
        int at = random.Next(bytes.Length);
        switch (random.Next(5))
        {
            case 0:
                bytes[at] ^= (byte)(1 << random.Next(8));
                return ($"bit flipped at {at}", bytes);
            case 1:
                bytes[at] = 0xFF;
                return ($"0xFF at {at}", bytes);
            case 2:
                bytes[at] = (byte)random.Next(1, 4);
                return ($"small value at {at}", bytes);
            case 3:
                return ($"cut to {at} bytes", bytes[..at]);
            default:
                var longer = new StringBuilder().Append('x', random.Next(1, 9)).ToString();
                return ($"{longer.Length} bytes appended", [.. bytes, .. Encoding.ASCII.GetBytes(longer)]);
        }
    }
}
