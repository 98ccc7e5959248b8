using AcPhys.Formats.Corpus;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// A fuzz target: a name, its seeds, the test afl-fuzz drives, and how a crash is classified and minimised.
/// Every concrete subclass in this assembly is a target (<see cref="FuzzTargets.All"/> finds them by reflection),
/// so adding a target is adding one file.
/// </summary>
public abstract class FuzzTarget
{
    /// <summary>Gets the name given on the command line (<c>--target</c>).</summary>
    public abstract string Name { get; }

    /// <summary>Gets one line for listings.</summary>
    public abstract string Description { get; }

    /// <summary>Gets what the target exercises.</summary>
    public abstract TargetKind Kind { get; }

    /// <summary>Gets the built-in seed inputs, by file name.</summary>
    public abstract IReadOnlyDictionary<string, byte[]> Seeds { get; }

    /// <summary>Gets tokens for afl-fuzz's <c>-x</c> dictionary (empty: none).</summary>
    public virtual IReadOnlyList<string> Dictionary => [];

    /// <summary>
    /// Gets a value indicating whether an input can run past afl-fuzz's timeout. The harness then serves afl-fuzz with
    /// SharpFuzz's out-of-process fork server (a timeout kills a child, not the server); otherwise in-process (faster).
    /// </summary>
    public virtual bool MayHang => false;

    /// <summary>Gets a value indicating whether the target can run against a planted fault.</summary>
    public bool TakesFaults => Kind == TargetKind.Physics;

    /// <summary>Builds the test: it throws on a bug, returns on a pass.</summary>
    /// <param name="fault">A planted fault id, or null for the correct core.</param>
    /// <returns>The test.</returns>
    /// <exception cref="ArgumentException">The fault is unknown, or the target takes no faults.</exception>
    public abstract Action<ReadOnlySpan<byte>> CreateTest(string? fault);

    /// <summary>
    /// Builds the physics-only limit of the test (issue 51): the same inputs decoded and run through the reference's
    /// physics once, with no invariant judged — what a test of this target cannot beat. Null for a target with no physics.
    /// </summary>
    /// <returns>The limit, or null.</returns>
    public virtual Action<ReadOnlySpan<byte>>? CreatePhysicsOnly() => null;

    /// <summary>
    /// Returns an input as a corpus entry without running any implementation (a physics target's decoded case), or
    /// null when the target has no stored case format: how an input that hangs a port is kept and replayed.
    /// </summary>
    /// <param name="input">The input.</param>
    /// <param name="title">The entry's title.</param>
    /// <param name="origin">Where the input came from.</param>
    /// <returns>The entry, or null.</returns>
    public virtual CorpusEntry? AsEntry(byte[] input, string title, string origin) => null;

    /// <summary>Runs one input again and says what fails, or null when it passes.</summary>
    /// <param name="input">The input.</param>
    /// <param name="fault">The planted fault the campaign ran, or null.</param>
    /// <returns>The finding, or null.</returns>
    public virtual Finding? Classify(byte[] input, string? fault)
    {
        var test = CreateTest(fault);
        try
        {
            test(input);
            return null;
        }
#pragma warning disable CA1031 // Classifying any escaping exception is the point.
        catch (Exception e)
#pragma warning restore CA1031
        {
            return new Finding(e.GetType().Name, Signatures.Of(e), e.Message, null);
        }
    }

    /// <summary>Builds the test against a subject (the reference, a planted fault, or a port).</summary>
    /// <param name="subject">The implementation under test.</param>
    /// <returns>The test.</returns>
    /// <exception cref="ArgumentException">A port was given to a target that fuzzes no implementation.</exception>
    public virtual Action<ReadOnlySpan<byte>> CreateTest(Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        NoPort(subject);
        return CreateTest(subject.Fault);
    }

    /// <summary>Runs one input again against a subject and says what fails, or null when it passes.</summary>
    /// <param name="input">The input.</param>
    /// <param name="subject">The implementation under test.</param>
    /// <returns>The finding, or null.</returns>
    public virtual Finding? Classify(byte[] input, Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        NoPort(subject);
        return Classify(input, subject.Fault);
    }

    /// <summary>Shrinks a finding of a subject to a minimal stored case, or returns null when the target has no case format.</summary>
    /// <param name="finding">A finding of this target.</param>
    /// <param name="subject">The implementation the campaign ran.</param>
    /// <param name="origin">Where the input came from.</param>
    /// <returns>The entry, or null.</returns>
    public virtual CorpusEntry? Minimise(Finding finding, Subject subject, string origin)
    {
        ArgumentNullException.ThrowIfNull(subject);
        NoPort(subject);
        return Minimise(finding, subject.Fault, origin);
    }

    /// <summary>Shrinks a finding to a minimal stored case, or returns null when the target has no case format.</summary>
    /// <param name="finding">A finding of this target.</param>
    /// <param name="fault">The planted fault the campaign ran, or null.</param>
    /// <param name="origin">Where the input came from (written into the entry's <c>seed</c> field).</param>
    /// <returns>The entry (title, invariant, case, the fault in <c>catches</c>), or null.</returns>
    public virtual CorpusEntry? Minimise(Finding finding, string? fault, string origin) => null;

    /// <summary>Says why the target cannot fuzz a port, or null when it can (physics targets whose invariants the port is testable for).</summary>
    /// <param name="impl">The port.</param>
    /// <returns>The reason, or null.</returns>
    public virtual string? WhyNotFuzzable(AcPhys.Contract.ICellPhysics impl) =>
        $"target {Name} fuzzes the suite's own readers, not an implementation (--impl / --impl-cmd take a physics target: land, walk, scene, parts)";

    /// <summary>Gets the invariants of this target an implementation is tested for (none for targets that fuzz no implementation).</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The invariant IDs.</returns>
    public virtual IReadOnlyList<string> TestedFor(AcPhys.Contract.ICellPhysics impl) => [];

    /// <summary>Rejects a port for targets that fuzz no implementation (parsers, smoke).</summary>
    /// <param name="subject">The subject.</param>
    /// <exception cref="ArgumentException">A port was given.</exception>
    protected void NoPort(Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        if (subject.IsExternal)
        {
            throw new ArgumentException($"target {Name} fuzzes the suite's own readers, not an implementation (--impl / --impl-cmd take a physics target)", nameof(subject));
        }
    }

    /// <summary>Rejects a fault id for targets that take none.</summary>
    /// <param name="fault">The fault id.</param>
    /// <exception cref="ArgumentException">A fault was given.</exception>
    protected void NoFault(string? fault)
    {
        if (fault is not null)
        {
            throw new ArgumentException($"target {Name} takes no planted fault (got '{fault}')", nameof(fault));
        }
    }
}
