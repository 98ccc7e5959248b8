using System.Globalization;
using AcPhys.Cli.Impl;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Capture;

namespace AcPhys.Cli.Capture;

/// <summary>The validated options of <c>acphys capture check</c>.</summary>
/// <param name="File">The capture.</param>
/// <param name="Format">Its format.</param>
/// <param name="Options">The importer's options (world origin, radius).</param>
/// <param name="Pick">The declared pick (the bundled reference's; an implementation declares its own).</param>
/// <param name="Fidelity">The declared deviations.</param>
/// <param name="Implementation">The implementation re-asked at every frame, or the reference (the log is judged).</param>
/// <param name="Quiet">No progress and no finding details beyond the first of each cause.</param>
/// <param name="Minimise">The folder minimised walks go to, or null.</param>
internal sealed record CaptureSettings(string File, CaptureFormat Format, CaptureOptions Options, PickPolicy Pick, (IndoorFidelity Indoor, OutdoorFidelity Outdoor) Fidelity, ImplementationChoice Implementation, bool Quiet, string? Minimise)
{
    /// <summary>Gets the user's dat files (<c>--cell-dat</c>, <c>--portal-dat</c>), or null: indoor frames are then not judged.</summary>
    public (string Cell, string Portal)? Dats { get; init; }

    /// <summary>Validates the words given.</summary>
    /// <param name="file">FILE.</param>
    /// <param name="format">--format.</param>
    /// <param name="origin">--world-origin.</param>
    /// <param name="radius">--radius.</param>
    /// <param name="pick">--pick.</param>
    /// <param name="fidelity">--fidelity.</param>
    /// <param name="implementation">--impl / --impl-cmd / --timeout.</param>
    /// <param name="quiet">--quiet.</param>
    /// <param name="minimise">--minimise.</param>
    /// <param name="cellDat">--cell-dat.</param>
    /// <param name="portalDat">--portal-dat.</param>
    /// <returns>The settings.</returns>
    /// <exception cref="UsageException">A bad option or a missing file.</exception>
    public static CaptureSettings Parse(string file, string? format, string? origin, string? radius, string? pick, string? fidelity, ImplementationChoice implementation, bool quiet, string? minimise, string? cellDat = null, string? portalDat = null)
    {
        if (Directory.Exists(file))
        {
            throw new UsageException($"{file}: is a directory; give one capture file");
        }

        if (!System.IO.File.Exists(file))
        {
            throw new UsageException($"{(file.Length == 0 ? "''" : file)}: no such file");
        }

        if (!CaptureFormats.TryParse(format, out var f))
        {
            throw new UsageException($"unknown --format '{AcPhys.Formats.Values.InputQuote.Line(format!, 40)}' (known: {string.Join(", ", CaptureFormats.Names)})");
        }

        LandblockId? block = null;
        if (origin is not null)
        {
            if (f != CaptureFormat.Acdream)
            {
                throw new UsageException("--world-origin applies to --format acdream (a native capture says its frame in its header: # frame: block|world)");
            }

            string hex = origin.StartsWith("0x", StringComparison.OrdinalIgnoreCase) ? origin[2..] : string.Empty;
            if (hex.Length != 4 || !ushort.TryParse(hex, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ushort v) || !new LandblockId(v).IsOnMap)
            {
                throw new UsageException($"malformed --world-origin '{AcPhys.Formats.Values.InputQuote.Line(origin, 40)}': expected a landblock on the map, 0x and 4 hex digits (0xAABB, AA and BB at most FE), e.g. 0xA9B4");
            }

            block = new LandblockId(v);
        }
        else if (f == CaptureFormat.Acdream)
        {
            throw new UsageException("--format acdream needs --world-origin 0xAABB: the landblock whose south-west corner is the client's world (0, 0)");
        }

        float? r = null;
        if (radius is not null)
        {
            if (!double.TryParse(radius, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) || !double.IsFinite(d) || d < 0 || d > 1000)
            {
                throw new UsageException($"malformed --radius '{AcPhys.Formats.Values.InputQuote.Line(radius, 40)}': expected the body's radius in metres, a number from 0 to 1000");
            }

            r = (float)d;
        }

        if (implementation.IsExternal && (pick is not null || fidelity is not null))
        {
            throw new UsageException("--pick and --fidelity declare the bundled reference's mode; with --impl / --impl-cmd the implementation declares its own in hello");
        }

        if (!PickNames.TryParse(pick, out var policy))
        {
            throw new UsageException($"unknown pick policy '{AcPhys.Formats.Values.InputQuote.Line(pick!, 40)}' (known: retail, current-first)");
        }

        if (minimise is not null)
        {
            OutputPath.CheckFolder("--minimise", minimise);
            OutputPath.CheckDistinct([("--minimise", minimise)], [file]);
        }

        (string, string)? dats = null;
        if (cellDat is not null || portalDat is not null)
        {
            if (cellDat is null || portalDat is null)
            {
                throw new UsageException("--cell-dat and --portal-dat go together (a cell database and its portal database)");
            }

            if (implementation.IsExternal)
            {
                throw new UsageException("--cell-dat/--portal-dat judge the log's indoor frames; with --impl / --impl-cmd indoor frames are not re-asked yet (check the log without --impl)");
            }

            foreach (var (option, path) in new[] { ("--cell-dat", cellDat), ("--portal-dat", portalDat) })
            {
                if (!System.IO.File.Exists(path))
                {
                    throw new UsageException($"{option} {(path.Length == 0 ? "''" : path)}: no such file");
                }
            }

            dats = (cellDat, portalDat);
        }

        return new CaptureSettings(file, f, new CaptureOptions(block, r), policy, ReferenceChoice.ParseFidelity(fidelity), implementation, quiet, minimise) { Dats = dats };
    }

    /// <summary>Returns the <c>--pick</c> / <c>--fidelity</c> words of the declared mode, for the stored case.</summary>
    /// <returns>The mode, or null for retail.</returns>
    public AcPhys.Formats.Corpus.CaseMode? Mode()
    {
        var words = ReferenceChoice.FidelityWords(Fidelity);
        var mode = new AcPhys.Formats.Corpus.CaseMode(Pick == PickPolicy.CurrentFirst ? PickNames.Of(Pick) : null, words, null);
        return mode.IsRetail ? null : mode;
    }
}
