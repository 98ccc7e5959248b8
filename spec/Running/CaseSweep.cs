using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Running;

/// <summary>
/// Hands every generated case of a domain to a visitor, exactly as <see cref="CatalogueRunner"/> would generate them
/// from the same seed (FsCheck's size ramp included), but without stopping at a failure or shrinking: for runs that
/// count every case, such as <c>acphys diff</c>'s divergence classes.
/// </summary>
public static class CaseSweep
{
    /// <summary>Visits <paramref name="cases"/> generated cases in order.</summary>
    /// <param name="domain">The domain.</param>
    /// <param name="cases">How many cases.</param>
    /// <param name="seed">The seed.</param>
    /// <param name="visit">Called once per case; returns false to skip the rest (they are still generated, not visited).</param>
    /// <typeparam name="TCase">The case type.</typeparam>
    public static void Each<TCase>(ICaseDomain<TCase> domain, int cases, Seed seed, Func<TCase, bool> visit)
    {
        bool going = true;
        bool Body(TCase c)
        {
            going = going && visit(c);
            return true;
        }

        FsCheck.Check.One(ConfigFor("sweep", cases, seed, new CapturingRunner(null)), Prop.ForAll(domain.Arbitrary, (Func<TCase, bool>)Body));
    }

    /// <summary>The FsCheck configuration of a run of <paramref name="cases"/> cases from a seed: one place, so a sweep and <see cref="CatalogueRunner"/> generate the same cases.</summary>
    /// <param name="name">The run's name.</param>
    /// <param name="cases">How many cases (discards allowed up to as many).</param>
    /// <param name="seed">The seed (with a size to replay one case).</param>
    /// <param name="runner">The runner that receives the result.</param>
    /// <returns>The configuration.</returns>
    internal static Config ConfigFor(string name, int cases, Seed seed, IRunner runner)
    {
        var config = Config.Quick.WithName(name).WithMaxTest(cases).WithMaxRejected(cases).WithRunner(runner);
        return seed.Size is int size ? config.WithReplay(seed.Value, seed.Gamma, size) : config.WithReplay(seed.Value, seed.Gamma);
    }
}
