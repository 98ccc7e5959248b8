using FsCheck;

namespace AcPhys.Spec.Cases;

/// <summary>Everything a runner needs to know about one kind of case: how to generate and shrink it, and which boundary classes it hits.</summary>
/// <typeparam name="TCase">The case type.</typeparam>
public interface ICaseDomain<TCase>
{
    /// <summary>Gets the generator with its shrinker.</summary>
    Arbitrary<TCase> Arbitrary { get; }

    /// <summary>Returns every boundary class tag of a case.</summary>
    /// <param name="c">The case.</param>
    /// <returns>The tags.</returns>
    IEnumerable<string> Classes(TCase c);

    /// <summary>Returns the one most boundary-like class, for FsCheck's distribution table.</summary>
    /// <param name="c">The case.</param>
    /// <returns>The tag.</returns>
    string Primary(TCase c);
}
