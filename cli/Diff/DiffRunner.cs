using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Diff;

/// <summary>
/// Runs a differential check over every generated input (issue #18: not just the first divergence): each diverging
/// input is counted in its class, and the first input of each class is then shrunk without leaving the class, so the
/// report holds one minimal example per root cause and how often each cause showed.
/// </summary>
internal static class DiffRunner
{
    /// <summary>How many classes (most frequent first) are shrunk; the rest keep the first input seen.</summary>
    public const int ShrunkClasses = 16;

    // Comparisons one class's shrink may spend: bounds the wire time of a slow implementation.
    private const int ShrinkBudget = 2_000;

    /// <summary>Runs the check.</summary>
    /// <param name="check">The check.</param>
    /// <param name="impl">The implementation.</param>
    /// <param name="cases">How many inputs.</param>
    /// <param name="seed">The seed.</param>
    /// <typeparam name="TCase">The input type.</typeparam>
    /// <returns>The classes with their counts.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static DiffResult Run<TCase>(DiffCheck<TCase> check, ICellPhysics impl, int cases, Seed seed)
    {
        if (check.WhyNotCompared(impl) is string why)
        {
            return new DiffResult(check, seed) { NotComparedReason = why };
        }

        var stopwatch = Stopwatch.StartNew();
        // One tally per class, in the order classes were first seen (the tie-break of the ranking below).
        var classes = new Dictionary<string, Tally<TCase>>(StringComparer.Ordinal);
        int seen = 0, divergent = 0;
        AdapterFailureException? failure = null;
        CaseSweep.Each(check.Domain, cases, seed, c =>
        {
            try
            {
                seen++;
                if (check.Compare(impl, c) is Divergence d)
                {
                    divergent++;
                    if (!classes.TryGetValue(d.Key, out var tally))
                    {
                        classes[d.Key] = tally = new Tally<TCase>(d, c, classes.Count);
                    }

                    tally.Count++;
                    tally.Inputs[d.Input] = tally.Inputs.GetValueOrDefault(d.Input) + 1;
                }

                return true;
            }
            catch (AdapterFailureException e)
            {
                failure = e;
                return false;
            }
        });

        if (failure is not null)
        {
            throw failure;
        }

        var ranked = classes.Values.OrderByDescending(t => t.Count).ThenBy(t => t.Order).ToArray();
        var result = new List<DivergenceClass>(ranked.Length);
        for (int i = 0; i < ranked.Length; i++)
        {
            var t = ranked[i];
            var (example, divergence) = i < ShrunkClasses ? Shrink(check, impl, t.Input, t.First) : (t.Input, t.First);
            var spread = t.Inputs.OrderByDescending(kv => kv.Value).ThenBy(kv => kv.Key, StringComparer.Ordinal).Select(kv => (kv.Key, kv.Value)).ToArray();
            result.Add(new DivergenceClass(t.First.What, spread, t.Count, example!, divergence.Message, i < ShrunkClasses));
        }

        return new DiffResult(check, seed) { Cases = seen, Divergent = divergent, Classes = result, Elapsed = stopwatch.Elapsed };
    }

    // Greedy shrinking (GreedyShrink) with the domain's own shrinker: the smaller input must stay in the class.
    private static (TCase Input, Divergence Divergence) Shrink<TCase>(DiffCheck<TCase> check, ICellPhysics impl, TCase input, Divergence divergence)
    {
        var last = divergence;
        bool SameClass(TCase candidate)
        {
            if (check.Compare(impl, candidate) is Divergence d && d.Key == divergence.Key)
            {
                last = d;
                return true;
            }

            return false;
        }

        var shrunk = GreedyShrink.Run(input, check.Domain.Arbitrary.Shrinker, SameClass, ShrinkBudget);
        return (shrunk, last);
    }

    // What one class has seen so far: its first divergence and input, how many inputs, over which input classes.
    private sealed class Tally<TCase>(Divergence first, TCase input, int order)
    {
        public Divergence First { get; } = first;

        public TCase Input { get; } = input;

        public int Order { get; } = order;

        public int Count { get; set; }

        public Dictionary<string, int> Inputs { get; } = new(StringComparer.Ordinal);
    }
}
