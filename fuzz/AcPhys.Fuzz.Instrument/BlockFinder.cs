using Mono.Cecil.Cil;

namespace AcPhys.Fuzz.Instrument;

/// <summary>Finds the first instruction of every basic block of a method body.</summary>
internal static class BlockFinder
{
    /// <summary>
    /// Returns the block starts: the method entry, every branch, switch and <c>leave</c> target, the fall-through
    /// of every conditional branch and switch, and every catch, filter and finally/fault handler start.
    /// </summary>
    /// <param name="body">A method body.</param>
    /// <returns>The distinct block starts in IL order, minus those where a probe would be invalid IL.</returns>
    public static List<Instruction> FindStarts(MethodBody body)
    {
        var starts = new HashSet<Instruction>();
        if (body.Instructions.Count == 0)
        {
            return [];
        }

        starts.Add(body.Instructions[0]);
        foreach (var instruction in body.Instructions)
        {
            switch (instruction.Operand)
            {
                case Instruction target:
                    starts.Add(target);
                    break;
                case Instruction[] targets:
                    starts.UnionWith(targets);
                    break;
            }

            if (instruction.OpCode.FlowControl == FlowControl.Cond_Branch && instruction.Next is not null)
            {
                starts.Add(instruction.Next);
            }
        }

        foreach (var handler in body.ExceptionHandlers)
        {
            starts.Add(handler.HandlerStart);
            if (handler.FilterStart is not null)
            {
                starts.Add(handler.FilterStart);
            }
        }

        return body.Instructions.Where(i => starts.Contains(i) && CanProbe(i)).ToList();
    }

    // A probe may not split a prefix from its instruction, nor a "tail." call from its "ret".
    private static bool CanProbe(Instruction instruction) =>
        instruction.Previous is not { OpCode.OpCodeType: OpCodeType.Prefix }
        && !(instruction.OpCode.Code == Code.Ret && instruction.Previous?.Previous is { OpCode.Code: Code.Tail });
}
