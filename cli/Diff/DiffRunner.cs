using System.Diagnostics;
using AcPhys.Spec.Adapters;
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
        var classes = new Dictionary<string, (Divergence First, TCase Input, int Count)>(StringComparer.Ordinal);
        var inputs = new Dictionary<string, Dictionary<string, int>>(StringComparer.Ordinal);
        var order = new List<string>();
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
                    var spread = inputs.TryGetValue(d.Key, out var s) ? s : inputs[d.Key] = new(StringComparer.Ordinal);
                    spread[d.Input] = spread.GetValueOrDefault(d.Input) + 1;
                    if (classes.TryGetValue(d.Key, out var known))
                    {
                        classes[d.Key] = known with { Count = known.Count + 1 };
                    }
                    else
                    {
                        classes[d.Key] = (d, c, 1);
                        order.Add(d.Key);
                    }
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

        var ranked = order.Select((key, i) => (key, i)).OrderByDescending(k => classes[k.key].Count).ThenBy(k => k.i).Select(k => k.key).ToArray();
        var result = new List<DivergenceClass>(ranked.Length);
        for (int i = 0; i < ranked.Length; i++)
        {
            var (first, input, count) = classes[ranked[i]];
            var (example, divergence) = i < ShrunkClasses ? Shrink(check, impl, input, first) : (input, first);
            var spread = inputs[ranked[i]].OrderByDescending(kv => kv.Value).ThenBy(kv => kv.Key, StringComparer.Ordinal).Select(kv => (kv.Key, kv.Value)).ToArray();
            result.Add(new DivergenceClass(first.What, spread, count, example!, divergence.Message, i < ShrunkClasses));
        }

        return new DiffResult(check, seed) { Cases = seen, Divergent = divergent, Classes = result, Elapsed = stopwatch.Elapsed };
    }

    // Greedy shrinking with the domain's own shrinker: take the first smaller input that stays in the class, until
    // none does or the budget is spent. Deterministic: the shrinker's candidates come in a fixed order.
    private static (TCase Input, Divergence Divergence) Shrink<TCase>(DiffCheck<TCase> check, ICellPhysics impl, TCase input, Divergence divergence)
    {
        int spent = 0;
        bool smaller = true;
        while (smaller && spent < ShrinkBudget)
        {
            smaller = false;
            foreach (var candidate in check.Domain.Arbitrary.Shrinker(input))
            {
                if (++spent > ShrinkBudget)
                {
                    break;
                }

                if (check.Compare(impl, candidate) is Divergence d && d.Key == divergence.Key)
                {
                    (input, divergence, smaller) = (candidate, d, true);
                    break;
                }
            }
        }

        return (input, divergence);
    }
}
