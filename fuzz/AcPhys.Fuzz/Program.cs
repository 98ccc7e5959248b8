using AcPhys.Fuzz;
using AcPhys.Fuzz.Runtime;

// AcPhys.Fuzz TARGET [INPUT]          serve afl-fuzz (INPUT is afl's @@ file; stdin without it), or run INPUT once
// AcPhys.Fuzz replay TARGET FILE...   replay saved inputs; exit 1 if any crashes
// AcPhys.Fuzz list                    list targets
// TARGET may also come from ACPHYS_FUZZ_TARGET; the planted fault from ACPHYS_FAULT (unset or empty: correct core).
const string Usage = "usage: AcPhys.Fuzz TARGET [INPUT] | AcPhys.Fuzz replay TARGET FILE... | AcPhys.Fuzz list";

string? fault = Environment.GetEnvironmentVariable("ACPHYS_FAULT") is { Length: > 0 } f ? f : null;
var rest = new Queue<string>(args);
string? command = rest.Count > 0 ? rest.Dequeue() : Environment.GetEnvironmentVariable("ACPHYS_FUZZ_TARGET");

switch (command)
{
    case null or "-h" or "--help":
        Console.Error.WriteLine(Usage);
        return command is null ? 2 : 0;

    case "list":
        foreach (var t in Targets.All)
        {
            Console.WriteLine($"{t.Name,-8} {t.Description}");
        }

        return 0;

    case "replay":
        {
            if (rest.Count < 2 || Targets.Find(rest.Dequeue()) is not { } target)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            var test = target.Create(fault);
            int crashes = 0;
            foreach (string file in rest)
            {
                crashes += Fuzzer.RunOnce(file, test, Console.Out);
            }

            Console.WriteLine($"replayed {rest.Count} input(s): {crashes} crash(es)");
            return crashes == 0 ? 0 : 1;
        }

    default:
        {
            if (Targets.Find(command) is not { } target)
            {
                Console.Error.WriteLine($"unknown target '{command}'; try: list");
                return 2;
            }

            return Fuzzer.Run(target.Create(fault), rest.Count > 0 ? rest.Dequeue() : null);
        }
}
