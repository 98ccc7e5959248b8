using System.Globalization;
using FsCheck.Xunit;

namespace AcPhys.Props.Support;

/// <summary>
/// An FsCheck.Xunit <see cref="PropertyAttribute"/> with the CI seed: under the pr profile (<c>ACPHYS_PROFILE=pr</c>, the
/// default) every run replays the profile's fixed base seed; under nightly FsCheck draws a fresh seed and prints it.
/// A failure prints FsCheck's own <c>Falsifiable, after N tests (K shrinks) (seed,gamma)</c> (and, after more than one
/// test, <c>Replay directly at failing step with (seed,gamma,size)</c>); putting the first pair in
/// <see cref="PropertyAttribute.Replay"/> (<c>Replay = "(seed,gamma)"</c>) reproduces the run exactly, in any profile.
/// </summary>
[AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
public sealed class CiPropertyAttribute : PropertyAttribute
{
    /// <summary>Initializes a new instance of the <see cref="CiPropertyAttribute"/> class with the profile's seed.</summary>
    public CiPropertyAttribute()
    {
        if (PropertyRun.Profile.BaseSeed is ulong seed)
        {
            // FsCheck's gamma must be odd.
            Replay = string.Create(CultureInfo.InvariantCulture, $"({seed},{0x9E3779B97F4A7C15UL})");
        }
    }
}
