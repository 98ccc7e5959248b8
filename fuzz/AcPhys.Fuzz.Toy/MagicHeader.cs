namespace AcPhys.Fuzz.Toy;

/// <summary>
/// A deliberately buggy toy parser for proving the fuzzing pipeline: it throws only for inputs starting with the
/// four bytes "AC!P". Blind random inputs hit that with probability 2^-32; coverage feedback finds it in seconds,
/// because every matched byte opens a new edge.
/// </summary>
public static class MagicHeader
{
    /// <summary>Parses a header and returns its kind (0 to 4: how many magic bytes matched).</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The number of leading magic bytes matched.</returns>
    /// <exception cref="InvalidOperationException">The planted bug: the full magic "AC!P".</exception>
    public static int Parse(ReadOnlySpan<byte> data)
    {
        if (data.Length < 4)
        {
            return 0;
        }

        if (data[0] == (byte)'A')
        {
            if (data[1] == (byte)'C')
            {
                if (data[2] == (byte)'!')
                {
                    if (data[3] == (byte)'P')
                    {
                        throw new InvalidOperationException("toy bug: magic header AC!P reached");
                    }

                    return 3;
                }

                return 2;
            }

            return 1;
        }

        return 0;
    }
}
