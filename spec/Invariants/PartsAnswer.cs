using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

/// <summary>One parts query of a walk and its answer.</summary>
/// <param name="Index">The walk step it stands for.</param>
/// <param name="Parts">The parts (the first is the anchor).</param>
/// <param name="Answer">The answer.</param>
/// <param name="Stale">Under a declared ace-keeps-stale-cells, the cells of the walk's previous answer of the same kind (ACE keeps them, facts §7 #6); null otherwise.</param>
internal sealed record PartsAnswer(int Index, Part[] Parts, FindCellResult Answer, IReadOnlySet<CellId>? Stale);
