using System.Globalization;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>The validated options of one <c>verify</c> run.</summary>
internal sealed record VerifySettings
{
    /// <summary>Gets the budget, with the base seed this run uses filled in.</summary>
    public required Profile Profile { get; init; }

    /// <summary>Gets the base seed every invariant's seed is derived from.</summary>
    public required ulong BaseSeed { get; init; }

    /// <summary>Gets a value indicating whether the base seed was drawn fresh for this run (nightly) rather than fixed.</summary>
    public required bool FreshBaseSeed { get; init; }

    /// <summary>Gets a value indicating whether the base seed was given with <c>--base-seed</c>.</summary>
    public required bool ExplicitBaseSeed { get; init; }

    /// <summary>Gets the invariant IDs to run, in catalogue spelling (<c>--only</c> less <c>--except</c>); empty for all.</summary>
    public required IReadOnlyList<string> Only { get; init; }

    /// <summary>Gets the invariant IDs left out with <c>--except</c>, in catalogue spelling; empty when none.</summary>
    public IReadOnlyList<string> Except { get; init; } = [];

    /// <summary>Gets the invariant IDs given with <c>--only</c>, in catalogue spelling; empty when none.</summary>
    public IReadOnlyList<string> OnlyGiven { get; init; } = [];

    /// <summary>Gets the fixed seed for every invariant (<c>--seed</c>), if any.</summary>
    public Seed? FixedSeed { get; init; }

    /// <summary>Gets the planted fault switched on, if any.</summary>
    public PlantedFault? Fault { get; init; }

    /// <summary>Gets the pick policy the bundled reference runs with (<c>--pick</c>).</summary>
    public AcPhys.Core.PickPolicy Pick { get; init; }

    /// <summary>Gets the documented deviations of the bundled reference (<c>--fidelity</c>; retail by default).</summary>
    public (AcPhys.Core.IndoorFidelity Indoor, AcPhys.Core.OutdoorFidelity Outdoor) Fidelity { get; init; }

    /// <summary>Gets the mode of the bundled reference as a case file stores it and a replay line chooses it again (issue 41).</summary>
    public AcPhys.Formats.Corpus.CaseMode Mode => new(
        Pick == AcPhys.Core.PickPolicy.CurrentFirst ? AcPhys.Contract.PickNames.Of(Pick) : null,
        Impl.ReferenceChoice.FidelityWords(Fidelity),
        Fault?.Id);

    /// <summary>Gets the implementation under test (the bundled reference unless <c>--impl</c> / <c>--impl-cmd</c>).</summary>
    public Impl.ImplementationChoice Implementation { get; init; } = Impl.ImplementationChoice.Reference;

    /// <summary>Gets the <c>--cases</c> override of the profile's cases per invariant, if any.</summary>
    public int? CasesOverride { get; init; }

    /// <summary>Gets how many failure classes each failing invariant searches for (<c>--max-classes</c>).</summary>
    public int MaxClasses { get; init; } = AcPhys.Spec.Running.CatalogueRunner.MaxClasses;

    /// <summary>Gets how many invariants run at once (<c>--jobs</c>); null: one per processor where that is safe (<see cref="VerifyWorkers"/>).</summary>
    public int? Jobs { get; init; }

    /// <summary>Gets the JUnit XML file to write (<c>--junit</c>), if any.</summary>
    public string? JunitPath { get; init; }

    /// <summary>Gets the markdown summary file to write (<c>--markdown</c>), if any.</summary>
    public string? MarkdownPath { get; init; }

    /// <summary>Gets the fewest invariants that must be tested for the run to pass (<c>--min-tested</c>, default 1).</summary>
    public int MinTested { get; init; } = 1;

    /// <summary>Gets a value indicating whether only failures and the summary are printed.</summary>
    public bool Quiet { get; init; }

    /// <summary>Gets a value indicating whether the boundary-class distribution is printed.</summary>
    public bool ShowClasses { get; init; }

    /// <summary>Validates the raw option values.</summary>
    /// <param name="profileName">The <c>--profile</c> value.</param>
    /// <param name="only">The <c>--only</c> values (each may hold several comma-separated IDs).</param>
    /// <param name="seed">The <c>--seed</c> value.</param>
    /// <param name="baseSeed">The <c>--base-seed</c> value.</param>
    /// <param name="fault">The <c>--fault</c> value.</param>
    /// <param name="except">The <c>--except</c> values: invariants left out (e.g. the conformance ones, to see what the independent invariants catch).</param>
    /// <param name="scope">The <c>--scope</c> value: retail, hardening or all (default).</param>
    /// <returns>The settings.</returns>
    /// <exception cref="UsageException">A value is unknown or malformed.</exception>
    public static VerifySettings Parse(string? profileName, string[]? only, string? seed, string? baseSeed, string? fault, string[]? except = null, string? scope = null)
    {
        var profile = AcPhys.Spec.Running.Profile.Find(profileName ?? "pr")
            ?? throw new UsageException($"unknown profile '{profileName}' (known: pr, nightly; the default comes from ACPHYS_PROFILE when set)");

        Seed? fixedSeed = null;
        if (seed is not null)
        {
            if (!Seed.TryParse(seed, out var parsed))
            {
                throw new UsageException($"malformed seed '{seed}': expected seed,gamma[,size] (decimal or 0x-hex, gamma odd), e.g. 12345,67891");
            }

            fixedSeed = parsed;
        }

        ulong? explicitBase = null;
        if (baseSeed is not null)
        {
            if (fixedSeed is not null)
            {
                throw new UsageException("--seed and --base-seed exclude each other (--seed fixes every invariant's seed; --base-seed derives them)");
            }

            explicitBase = ParseU64(baseSeed) ?? throw new UsageException($"malformed base seed '{baseSeed}': expected an unsigned 64-bit integer (decimal or 0x-hex)");
        }

        PlantedFault? planted = null;
        if (fault is not null)
        {
            planted = PlantedFaults.Find(fault)
                ?? throw new UsageException($"unknown fault '{fault}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
        }

        ulong runBase = explicitBase ?? profile.BaseSeed ?? Seed.Fresh().Value;
        var onlyGiven = ResolveIds(only, "--only");
        var left = ResolveIds(except, "--except");
        var run = left.Count == 0 ? onlyGiven
            : [.. (onlyGiven.Count == 0 ? InvariantCatalogue.All.Select(i => i.Id) : onlyGiven).Where(id => !left.Contains(id))];
        if (left.Count > 0 && run.Count == 0)
        {
            throw new UsageException("--except leaves no invariant to run");
        }

        if (scope is not null && scope != "all")
        {
            var wanted = scope switch
            {
                "retail" => Scope.Retail,
                "hardening" => Scope.Hardening,
                _ => throw new UsageException($"unknown scope '{Brief(scope)}' (known: retail, hardening, all)"),
            };
            run = [.. (run.Count == 0 ? InvariantCatalogue.All.Select(i => i.Id) : run).Where(id => InvariantScope.Of(id)?.Scope == wanted)];
            if (run.Count == 0)
            {
                throw new UsageException($"--scope {scope} leaves no invariant to run");
            }
        }

        return new VerifySettings
        {
            Profile = profile with { BaseSeed = runBase },
            BaseSeed = runBase,
            FreshBaseSeed = explicitBase is null && profile.BaseSeed is null,
            ExplicitBaseSeed = explicitBase is not null,
            Only = run,
            OnlyGiven = onlyGiven,
            Except = left,
            FixedSeed = fixedSeed,
            Fault = planted,
        };
    }

    private static List<string> ResolveIds(string[]? values, string option)
    {
        var ids = new List<string>();
        if (values is null || values.Length == 0)
        {
            return ids;
        }

        foreach (var raw in values.SelectMany(v => v.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries)))
        {
            var invariant = InvariantCatalogue.Find(raw)
                ?? throw new UsageException($"unknown invariant '{raw}' (known: {string.Join(", ", InvariantCatalogue.All.Select(i => i.Id))})");

            if (!ids.Contains(invariant.Id))
            {
                ids.Add(invariant.Id);
            }
        }

        if (ids.Count == 0)
        {
            throw new UsageException($"{option} needs at least one invariant ID (see: acphys invariants)");
        }

        return ids;
    }

    private static ulong? ParseU64(string text)
    {
        text = text.Trim();
        bool ok = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
            ? ulong.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ulong v)
            : ulong.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out v);
        return ok ? v : null;
    }

    private static string Brief(string text) => text.Length <= 40 ? text : text[..39] + "…";
}
