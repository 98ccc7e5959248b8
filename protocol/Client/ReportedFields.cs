using AcPhys.Contract;

namespace AcPhys.Protocol.Client;

/// <summary>
/// Which optional fields a child's find_cell answers carry: unknown until its first answer (a guess cannot be made
/// before, so that query is asked and awaited), then fixed.
/// </summary>
internal sealed class ReportedFields
{
    private int state = -1; // -1 unknown; else bit 0: loaded, bit 1: hits_interior_cell

    public void Learn(FindCellResult answer) =>
        Interlocked.CompareExchange(ref state, (answer.Loaded is null ? 0 : 1) | (answer.HitsInteriorCell is null ? 0 : 2), -1);

    public bool ReportsAll => Volatile.Read(ref state) == 3;

    public FindCellResult Project(FindCellResult guess)
    {
        int known = Volatile.Read(ref state);
        return known < 0
            ? throw new InvalidOperationException("the implementation's optional find_cell fields are not known yet")
            : known == 3 ? guess
            : guess with { Loaded = (known & 1) != 0 ? guess.Loaded : null, HitsInteriorCell = (known & 2) != 0 ? guess.HitsInteriorCell : null };
    }
}
