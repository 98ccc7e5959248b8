using System.Text;

namespace RecordAdapter;

/// <summary>The entry point: one request line in, one answer line out (flushed), until end of input.</summary>
internal static class Program
{
    private static int Main()
    {
        Server server;
        try
        {
            server = new Server(Environment.GetEnvironmentVariable("ACPHYS_EXAMPLE_BUG"));
        }
        catch (InputException e)
        {
            Console.Error.WriteLine("record-adapter: " + e.Message);
            return 2;
        }

        var utf8 = new UTF8Encoding(encoderShouldEmitUTF8Identifier: false);
        using var input = new StreamReader(Console.OpenStandardInput(), utf8);
        using var output = new StreamWriter(Console.OpenStandardOutput(), utf8) { NewLine = "\n" };
        while (input.ReadLine() is { } line)
        {
            if (string.IsNullOrWhiteSpace(line))
            {
                continue;
            }

            output.WriteLine(server.Answer(line));
            output.Flush();
        }

        return 0;
    }
}
