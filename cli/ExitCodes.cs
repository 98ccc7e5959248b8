namespace AcPhys.Cli;

/// <summary>The process exit codes of <c>acphys</c> (docs/cli.md).</summary>
internal static class ExitCodes
{
    /// <summary>Everything held (or the command just printed something).</summary>
    public const int Ok = 0;

    /// <summary>An invariant was violated.</summary>
    public const int Violated = 1;

    /// <summary>Usage or tool error: bad option, unknown ID, malformed input, an implementation that could not answer.</summary>
    public const int ToolError = 2;

    /// <summary>An output path (<c>-o</c>, <c>--junit</c>, <c>--markdown</c>, <c>--json</c>) cannot be written; checked before the work starts.</summary>
    public const int OutputError = 3;

    /// <summary>Nothing was violated but fewer invariants were tested than <c>verify --min-tested</c> (default 1): a run that tested nothing is never a pass.</summary>
    public const int TooFewTested = 4;

    /// <summary>A dat container given on the command line cannot be read (truncated, a broken chain or directory, a refused record): the message names the file, the object and the offset (docs/dat-container.md).</summary>
    public const int BadDat = 5;

    /// <summary><c>fuzz --impl</c>: the in-process port did not return on a seed or a finding outside afl-fuzz (seeds, triage, minimising) within the campaign's limit: HANG, the campaign stopped.</summary>
    public const int PortHung = 6;

    /// <summary>An internal error of the tool (a bug, never bad input): one line on stderr, the stack trace with <c>ACPHYS_DEBUG=1</c> (sysexits EX_SOFTWARE).</summary>
    public const int InternalError = 70;

    /// <summary>Interrupted by SIGINT (Ctrl-C): 128 + 2.</summary>
    public const int Interrupted = 130;

    /// <summary>Terminated by SIGTERM: 128 + 15.</summary>
    public const int Terminated = 143;
}
