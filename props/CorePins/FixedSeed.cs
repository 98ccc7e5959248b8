using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// FsCheck settings of the mutation-killing properties: a fixed seed per property and a fixed number of cases in
/// every profile, so the set of mutants a property kills is the same on every run and every machine (never luck).
/// The properties are FsCheck.Xunit tests carrying them through <see cref="FixedSeedPropertyAttribute"/>.
/// </summary>
internal static class FixedSeed
{
    /// <summary>Cases per property: the <c>mutation</c> profile's budget (spec/Running/Profile.cs).</summary>
    public const int Cases = 1000;

    /// <summary>The gamma of every seed (odd, as FsCheck requires).</summary>
    public const ulong Gamma = 0x9E3779B97F4A7C15UL;

    /// <summary>Gets bytes biased to the map edge: 0x00, 0x01, 0x7F, 0x80, 0xFD, 0xFE, 0xFF, else any byte.</summary>
    public static Gen<byte> Bytes { get; } = Gen.Frequency(
        (1, Gen.Elements<byte>(0x00, 0x01, 0x7F, 0x80, 0xFD, 0xFE, 0xFF)),
        (1, Gen.Choose(0, 255).Select(i => (byte)i)));

    /// <summary>Gets raw 32-bit values over the whole range, with 0, 1 and the top values often.</summary>
    public static Gen<uint> Uints { get; } = Gen.Frequency(
        (1, Gen.Elements(0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu)),
        (4, Gen.Choose(int.MinValue, int.MaxValue).Select(i => unchecked((uint)i))));

    /// <summary>Gets pairs of raw 32-bit values that are often equal or one apart (where &lt; and &lt;= differ).</summary>
    public static Gen<(uint A, uint B)> NearPairs { get; } =
        Gen.Zip(Uints, Gen.Frequency(
            (2, Gen.Elements(-1L, 0L, 1L)),
            (1, Gen.Choose(int.MinValue, int.MaxValue).Select(i => (long)i))))
        .Select(t => (t.Item1, unchecked((uint)(t.Item1 + t.Item2))));

    /// <summary>Zips three generators into a value tuple.</summary>
    /// <typeparam name="T1">First type.</typeparam>
    /// <typeparam name="T2">Second type.</typeparam>
    /// <typeparam name="T3">Third type.</typeparam>
    /// <param name="a">First generator.</param>
    /// <param name="b">Second generator.</param>
    /// <param name="c">Third generator.</param>
    /// <returns>The zipped generator.</returns>
    public static Gen<(T1, T2, T3)> Zip<T1, T2, T3>(Gen<T1> a, Gen<T2> b, Gen<T3> c) =>
        Gen.Zip(Gen.Zip(a, b), c, (ab, z) => (ab.Item1, ab.Item2, z));
}
