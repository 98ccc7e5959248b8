using System.Text;
using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Spec.Capture;

namespace AcPhys.Props.Capture;

/// <summary>Checks capture text through the tool's reader and checker, in memory.</summary>
internal static class CaptureRunner
{
    /// <summary>Checks a capture.</summary>
    /// <param name="text">The capture.</param>
    /// <param name="pick">The declared pick.</param>
    /// <param name="format">The format.</param>
    /// <param name="options">The importer's options.</param>
    /// <returns>The report.</returns>
    public static CaptureReport Check(string text, PickPolicy pick = PickPolicy.Retail, CaptureFormat format = CaptureFormat.Native, CaptureOptions? options = null)
    {
        using var reader = CaptureReaders.Open(new MemoryStream(Encoding.UTF8.GetBytes(text)), "test.capture", format, options ?? new CaptureOptions(null, null));
        return new CaptureChecker(CaptureChecker.OutdoorOnly(pick, default)).Check(reader);
    }
}
