using System.Text;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Corpus;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>corpus</c> parser target: bytes → <see cref="CorpusJson.Read"/>, the one reader of corpus files of both
/// kinds (land and walk entries) and of failure files (<see cref="FailureFile"/> writes corpus entries).
/// </summary>
public sealed class CorpusFileTarget : ParserTarget
{
    /// <inheritdoc/>
    public override string Name => "corpus";

    /// <inheritdoc/>
    public override string Description => "CorpusJson.Read (corpus and failure files, land and walk entries); only InputFormatException may escape";

    /// <inheritdoc/>
    protected override CorpusEntry? Read(ReadOnlySpan<byte> data) => CorpusJson.Read(Encoding.UTF8.GetString(data), "fuzz");
}
