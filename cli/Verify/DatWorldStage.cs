using System.CommandLine;
using System.Globalization;
using AcPhys.Cli.Commands;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Dat.Container;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// <c>verify --cell-dat FILE --portal-dat FILE</c>: the gate over a dat world (<see cref="DatWorldGate"/>), after the
/// catalogue; with <c>--dat-block 0xAABB</c> that block alone and no catalogue (the replay of a finding). Parses and
/// prints; the work is the library's.
/// </summary>
internal sealed class DatWorldStage
{
    private readonly Option<string?> cell = new("--cell-dat") { Description = "A cell database (client_cell_1.dat): also walk scenes of real buildings and dungeons sampled from it (docs/dat-container.md). Needs --portal-dat.", HelpName = "FILE" };
    private readonly Option<string?> portal = new("--portal-dat") { Description = "The portal database (client_portal.dat) beside --cell-dat.", HelpName = "FILE" };
    private readonly Option<string?> block = new("--dat-block") { Description = "Walk only this landblock of the dat world, and skip the catalogue (the replay of a dat-world finding).", HelpName = "0xAABB" };
    private readonly Option<string?> positions = new("--positions") { Description = "Real indoor positions to check against the dat world (tab-separated, columns obj_cell_id x y z kind; default: ../shared/data/retail-positions.tsv beside the checkout, when present). Reported by reason; not a gate.", HelpName = "FILE" };
    private readonly Option<int?> blocks = new("--dat-blocks") { Description = $"How many landblocks to sample (default: {DatWorldGate.PrBlocks} in pr, {DatWorldGate.NightlyBlocks} in nightly).", HelpName = "N" };

    /// <summary>Gets the options, to add to the verify command.</summary>
    public IEnumerable<Option> All => [cell, portal, block, blocks, positions];

    /// <summary>Reads the options.</summary>
    /// <param name="parse">The parse result.</param>
    /// <returns>The request, or null when no dat world was given.</returns>
    /// <exception cref="UsageException">Only one of the two files, a malformed block, a count out of range.</exception>
    public Request? Read(ParseResult parse)
    {
        string? c = parse.GetValue(cell), p = parse.GetValue(portal), b = parse.GetValue(block);
        int? n = parse.GetValue(blocks);
        if (c is null && p is null)
        {
            return b is null && n is null ? null : throw new UsageException("--dat-block and --dat-blocks need --cell-dat and --portal-dat");
        }

        if (c is null || p is null)
        {
            throw new UsageException("--cell-dat and --portal-dat go together (a cell database and its portal database)");
        }

        LandblockId? one = null;
        if (b is not null)
        {
            one = ScenePlace.TryParseBlock(b, out var parsed) ? parsed : throw new UsageException($"--dat-block {b}: expected a landblock on the map, 0xAABB");
        }

        if (n is < 1 or > 100_000)
        {
            throw new UsageException($"--dat-blocks must be between 1 and 100,000 (got {n})");
        }

        string? file = parse.GetValue(positions);
        if (file is not null && !File.Exists(file))
        {
            throw new UsageException($"--positions {file}: no such file");
        }

        return new Request(c, p, one, n, file ?? DefaultPositions());
    }

    /// <summary>Runs the gate and prints it.</summary>
    /// <param name="request">The request.</param>
    /// <param name="settings">The verify settings (profile, fault, implementation: for the replay line).</param>
    /// <param name="impl">The implementation under test.</param>
    /// <returns>True when nothing was violated.</returns>
    public static bool Run(Request request, VerifySettings settings, ICellPhysics impl)
    {
        using var world = SceneFromDat.OpenWorld(request.Cell, request.Portal, "--cell-dat", "--portal-dat");
        var candidates = DatWorldGate.Candidates(world);
        List<LandblockId> sample;
        if (request.Block is { } one)
        {
            if (!world.Cell.Contains(SceneExtraction.LandblockRecordId(one)))
            {
                throw new UsageException($"--dat-block {one}: {request.Cell} holds no Landblock record of it");
            }

            sample = [one];
        }
        else
        {
            int count = request.Blocks ?? (settings.Profile.Name == "nightly" ? DatWorldGate.NightlyBlocks : DatWorldGate.PrBlocks);
            sample = DatWorldGate.Sample(candidates, count);
        }

        var started = System.Diagnostics.Stopwatch.StartNew();
        var result = DatWorldGate.Run(world, impl, sample, candidates.Count);
        started.Stop();
        Console.WriteLine();
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"dat world: {world.Cell.Name} ({world.Cell.Count} objects), {world.Portal.Name} ({world.Portal.Count} objects)"));
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"dat world: {result.Sampled.Count} of {result.Candidates} landblocks with buildings or env cells ({string.Join(", ", result.Sampled)}); {result.Refused.Count} refused; {result.Cells} env cells; {result.Walks} walks judged by every scene invariant and FIND-CELL-CONFORMANCE; {result.Findings.Count} violated; {started.Elapsed.TotalSeconds:0.0} s"));
        foreach (var (b, why) in result.Refused)
        {
            Console.WriteLine($"  refused {b}: {why}");
        }

        foreach (var f in result.Findings)
        {
            Console.WriteLine($"FAIL  {f}");
            Console.WriteLine($"replay     {Replay(request, f.Block, settings)}");
        }

        if (result.Walks == 0 && result.Findings.Count == 0)
        {
            Console.WriteLine("dat world: no walk was judged (no sampled block held an env cell with a portal a walk can cross)");
        }

        if (request.Block is null && request.Positions is { } tsv)
        {
            // The real-data check (docs/dat-container.md): reported by reason, as the outdoor rows are; not a gate.
            var rows = IndoorPositionsFile.Read(tsv, out int skipped);
            var check = IndoorPositionCheck.Run(world, impl, rows);
            Console.WriteLine($"indoor positions ({tsv}): {check}{(skipped > 0 ? $"; {skipped} rows did not parse" : string.Empty)}");
            foreach (var (row, got) in check.Disagreements.Take(5))
            {
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  {row.Cell} at ({row.Position.X}, {row.Position.Y}, {row.Position.Z}): find_cell names {got}"));
            }
        }

        return result.Findings.Count == 0;
    }

    private static string? DefaultPositions()
    {
        try
        {
            string path = Path.Combine(Fuzz.RepoRoot.Find(), "..", "shared", "data", "retail-positions.tsv");
            return File.Exists(path) ? Path.GetFullPath(path) : null;
        }
        catch (UsageException)
        {
            return null; // not inside a checkout: no default
        }
    }

    private static string Replay(Request request, LandblockId block, VerifySettings settings)
    {
        var words = new List<string> { ReplayLine.Program, "verify", "--cell-dat", request.Cell, "--portal-dat", request.Portal, "--dat-block", block.ToString() };
        words.AddRange(settings.Mode.Words()); // --pick, --fidelity, --fault: every option that changes the verdict (issue 41)
        words.AddRange(settings.Implementation.Words());
        return string.Join(' ', words.Select(ReplayLine.Quote));
    }

    /// <summary>A dat-world request.</summary>
    /// <param name="Cell">The cell database.</param>
    /// <param name="Portal">The portal database.</param>
    /// <param name="Block">One block to walk (no catalogue), or null to sample.</param>
    /// <param name="Blocks">The sample size, or null for the profile's.</param>
    /// <param name="Positions">The real positions file, or null.</param>
    internal sealed record Request(string Cell, string Portal, LandblockId? Block, int? Blocks, string? Positions);
}
