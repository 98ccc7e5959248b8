namespace AcPhys.Cli.Diff;

/// <summary>
/// How one input's answers differ. <paramref name="What"/>, the divergence class that <c>acphys diff</c> counts, says
/// which op and in what way (cells missing in another block, extra cells, another order, ok against fail): two inputs
/// in one class most likely share a root cause. The input's boundary class is kept beside it, not in it, so one root
/// cause met on many kinds of input stays one class (with its inputs' spread shown).
/// </summary>
/// <param name="What">The op and the shape of the difference.</param>
/// <param name="Input">The input's primary boundary class (the generator's own tag).</param>
/// <param name="Message">Both answers, for the report.</param>
internal readonly record struct Divergence(string What, string Input, string Message)
{
    /// <summary>Gets the class key: inputs with equal keys are counted together and shrunk without leaving it.</summary>
    public string Key => What;
}
