namespace AcPhys.Fuzz.Runtime;

/// <summary>
/// Marks an assembly whose IL has been rewritten by AcPhys.Fuzz.Instrument. The instrumenter skips marked
/// assemblies, so running it twice over the same files is harmless.
/// </summary>
/// <param name="blocks">The number of coverage probes inserted.</param>
[AttributeUsage(AttributeTargets.Assembly, AllowMultiple = false)]
public sealed class InstrumentedAttribute(int blocks) : Attribute
{
    /// <summary>Gets the number of coverage probes inserted.</summary>
    public int Blocks { get; } = blocks;
}
