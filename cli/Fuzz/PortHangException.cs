namespace AcPhys.Cli.Fuzz;

/// <summary>An in-process port did not finish one case within the campaign's limit outside afl-fuzz (<see cref="PortWatch"/>).</summary>
internal sealed class PortHangException : Exception
{
    /// <summary>Initializes a new instance of the <see cref="PortHangException"/> class.</summary>
    /// <param name="input">The seed or file the case came from.</param>
    /// <param name="data">Its bytes, or null when the case is not one input.</param>
    /// <param name="limit">The limit it passed.</param>
    public PortHangException(string input, byte[]? data, TimeSpan limit)
        : base(string.Create(System.Globalization.CultureInfo.InvariantCulture, $"the port did not return within {limit.TotalSeconds:0.###} s on {input}"))
    {
        Input = input;
        Bytes = data;
        Limit = limit;
    }

    /// <summary>Gets how the input is named.</summary>
    public string Input { get; }

    /// <summary>Gets the input's bytes, or null.</summary>
    public byte[]? Bytes { get; }

    /// <summary>Gets the limit.</summary>
    public TimeSpan Limit { get; }
}
