namespace AcPhys.Spec.Adapters;

/// <summary>An <c>--impl</c> assembly could not be loaded or holds no usable adapter class (a usage error, exit 2).</summary>
public sealed class AdapterLoadException : Exception
{
    /// <summary>Initializes a new instance of the <see cref="AdapterLoadException"/> class.</summary>
    public AdapterLoadException()
    {
    }

    /// <summary>Initializes a new instance of the <see cref="AdapterLoadException"/> class.</summary>
    /// <param name="message">What went wrong, naming the assembly.</param>
    public AdapterLoadException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance of the <see cref="AdapterLoadException"/> class.</summary>
    /// <param name="message">What went wrong, naming the assembly.</param>
    /// <param name="inner">The cause.</param>
    public AdapterLoadException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
