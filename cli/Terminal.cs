using Spectre.Console;

namespace AcPhys.Cli;

/// <summary>
/// The two Spectre consoles of the tool: results on stdout, progress and errors on stderr. Redirected output gets a
/// wide fixed width so tables do not wrap in CI logs (override with <c>ACPHYS_WIDTH</c>) and no colour; on a terminal
/// colour follows Spectre's detection (<c>NO_COLOR</c> is honoured).
/// </summary>
internal static class Terminal
{
    private const int RedirectedWidth = 200;

    /// <summary>Gets the console for results (stdout).</summary>
    public static IAnsiConsole Out { get; } = Create(Console.Out, Console.IsOutputRedirected);

    /// <summary>Gets the console for progress (stderr).</summary>
    public static IAnsiConsole Err { get; } = Create(Console.Error, Console.IsErrorRedirected);

    /// <summary>Gets a value indicating whether a live progress display on stderr makes sense.</summary>
    public static bool ShowsProgress => !Console.IsErrorRedirected && Err.Profile.Capabilities.Interactive;

    /// <summary>Writes one plain line to stdout (never wrapped: replay lines must stay copy-pastable).</summary>
    /// <param name="text">The text.</param>
    public static void Line(string text = "") => Console.Out.WriteLine(text);

    /// <summary>Writes a one-line error to stderr.</summary>
    /// <param name="verb">The command, e.g. <c>verify</c>, or null for the tool itself.</param>
    /// <param name="message">The message.</param>
    public static void Error(string? verb, string message) =>
        Console.Error.WriteLine(verb is null ? $"acphys: {message}" : $"acphys {verb}: {message}");

    /// <summary>Shows the cursor again if a live display was interrupted while it was hidden.</summary>
    public static void RestoreCursor()
    {
        if (!Console.IsErrorRedirected && Err.Profile.Capabilities.Ansi)
        {
            Console.Error.Write("\u001b[?25h\n");
        }
    }

    private static IAnsiConsole Create(TextWriter writer, bool redirected)
    {
        var settings = new AnsiConsoleSettings { Out = new AnsiConsoleOutput(writer) };
        if (redirected)
        {
            // Logs and pipes get plain text, whatever TERM says.
            settings.Ansi = AnsiSupport.No;
            settings.ColorSystem = ColorSystemSupport.NoColors;
            settings.Interactive = InteractionSupport.No;
        }

        var console = AnsiConsole.Create(settings);
        if (redirected)
        {
            console.Profile.Width = AcPhys.Spec.Running.ToolEnvironment.Process.Width ?? RedirectedWidth;
        }

        return console;
    }
}
