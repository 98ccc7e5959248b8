using System.Buffers.Binary;
using AcPhys.Contract;
using AcPhys.Formats.Dat;

namespace AcPhys.Props.Dat;

/// <summary>
/// Issue #29, record fidelity: a Landblock record says hasObjects 1 whenever its LandblockInfo is written, because ACE
/// reads a LandblockInfo only when the flag is 1 (dat-records.md, Landblock); our reader honours the flag as ACE does.
/// </summary>
public sealed class LandblockHasObjects
{
    [Fact(DisplayName = "dat-records.md Landblock: every exported Landblock says hasObjects 1 exactly when its block's LandblockInfo is written")]
    public void HasObjectsMarksEveryWrittenLandblockInfo()
    {
        int withInfo = 0, withBuildings = 0;
        foreach (var scene in Scenes())
        {
            var export = DatSceneWriter.Write(scene, "test", "memory");
            var infos = export.Records.Where(r => r.Record.Type == RecordType.LandblockInfo).Select(r => r.Record.Id >> 16).ToHashSet();
            foreach (var (record, bytes) in export.Records.Where(r => r.Record.Type == RecordType.Landblock))
            {
                uint flag = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(4));
                bool info = infos.Contains(record.Id >> 16);
                Assert.True(flag == (info ? 1u : 0u), $"Landblock {RecordIds.Text(record.Id)}: hasObjects {flag}, LandblockInfo {(info ? "written" : "not written")}");
                withInfo += info ? 1 : 0;
            }

            withBuildings += scene.Buildings.Count > 0 ? 1 : 0;
        }

        Assert.True(withInfo > 0 && withBuildings > 0, $"{withInfo} landblocks with a LandblockInfo, {withBuildings} scenes with buildings: the check saw nothing");
    }

    [Fact(DisplayName = "dat-records.md Landblock: a reader that honours hasObjects (ours, as ACE) sees every building of an exported scene, and none of a block whose flag is cleared")]
    public void AFaithfulReaderSeesEveryBuilding()
    {
        int checkedBuildings = 0;
        foreach (var scene in Scenes().Where(s => s.Buildings.Count > 0))
        {
            var export = DatSceneWriter.Write(scene, "test", "memory");
            var bytes = export.Records.ToDictionary(r => r.Record, r => r.Bytes);
            var back = DatSceneReader.Read(export.Manifest, r => bytes[r]);
            Assert.Equal(scene.Buildings.Count, back.Buildings.Count);
            checkedBuildings += back.Buildings.Count;

            // Clear the flag of one loaded block with buildings: its buildings disappear, as they do for ACE.
            if (!scene.Buildings.Any(b => scene.Blocks.Contains(b.Block)))
            {
                continue;
            }

            var block = scene.Buildings.Select(b => b.Block).First(scene.Blocks.Contains);
            var landblock = export.Records.Single(r => r.Record.Type == RecordType.Landblock && r.Record.Id >> 16 == block.Value);
            var cleared = (byte[])landblock.Bytes.Clone();
            BinaryPrimitives.WriteUInt32LittleEndian(cleared.AsSpan(4), 0);
            var hidden = DatSceneReader.Read(export.Manifest, r => r == landblock.Record ? cleared : bytes[r]);
            Assert.Equal(scene.Buildings.Count(b => b.Block != block), hidden.Buildings.Count);
        }

        Assert.True(checkedBuildings > 0, "no scene with a building in a loaded block was checked");
    }

    private static IEnumerable<Scene> Scenes() =>
        DatTestSupport.CorpusSceneWalks.Select(x => x.Entry.SceneWalk!.Scene).Concat(DatTestSupport.Generated(200, 2929));
}
