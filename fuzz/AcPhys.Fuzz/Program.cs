using AcPhys.Fuzz;
using AcPhys.Fuzz.Targets;
using SharpFuzz;

// AcPhys.Fuzz TARGET [INPUT]            serve afl-fuzz on stdin (SharpFuzz fork server), or run INPUT once
// AcPhys.Fuzz replay TARGET FILE...     replay saved inputs; exit 1 if any crashes
// AcPhys.Fuzz seeds TARGET DIR          write the target's built-in seed inputs into DIR
// AcPhys.Fuzz dict TARGET FILE          write the target's afl-fuzz dictionary (-x) into FILE (nothing when it has none)
// AcPhys.Fuzz cmin TARGET SEEDS DIR...  add to SEEDS the inputs of DIR... that cover new tuples (afl-cmin's job)
// AcPhys.Fuzz bench TARGET [N] [DIR]    time the test alone on N random 17-byte inputs, or DIR's files round robin (no afl-fuzz, no
//                                       pipes), then the same inputs through the reference physics alone
// AcPhys.Fuzz warmup TARGET [MS]        run the --impl-cmd warm-up for MS ms, printing the mean time of every 100 inputs
// AcPhys.Fuzz list                      list targets
// TARGET may also come from ACPHYS_FUZZ_TARGET; the planted fault from ACPHYS_FAULT (unset or empty: correct core);
// a port instead of the reference from ACPHYS_IMPL (an adapter assembly, in process) or ACPHYS_IMPL_CMD (a protocol v1
// command line: one child for this process's life, restarted after it failed; ACPHYS_IMPL_TIMEOUT seconds per answer).
// Under afl-fuzz an ACPHYS_IMPL_CMD child is warmed for ACPHYS_FUZZ_WARMUP_MS (default 3000; 0: not) before the
// fork server starts (Warmup.cs).
const string Usage = "usage: AcPhys.Fuzz TARGET [INPUT] | replay TARGET FILE... | seeds TARGET DIR | dict TARGET FILE | cmin TARGET SEEDS DIR... | bench TARGET [N] [DIR] | warmup TARGET [MS] | list";

// SharpFuzz's probes need a map before any instrumented code runs; Fuzzer.Run swaps in afl-fuzz's shared memory.
PrivateMap.Attach();
ForkServerPipes.KeepFromChildren(); // before an --impl-cmd child can be started
var settings = AcPhys.Spec.Running.ToolEnvironment.Process; // the ACPHYS_* environment, read once
if (settings.WireProfile)
{
    AcPhys.Formats.Values.WireProfileSwitch.Enable();
}

string? fault = settings.Fault;
Subject subject;
try
{
    subject = PortSubject.FromEnvironment(settings) ?? Subject.Of(fault);
}
catch (Exception e) when (e is ArgumentException or AcPhys.Spec.Adapters.AdapterLoadException)
{
    Console.Error.WriteLine(e.Message);
    return 2;
}

var rest = new Queue<string>(args);
string? command = rest.Count > 0 ? rest.Dequeue() : settings.FuzzTarget;

switch (command)
{
    case null or "-h" or "--help":
        Console.Error.WriteLine(Usage);
        return command is null ? 2 : 0;

    case "list":
        foreach (var t in FuzzTargets.All)
        {
            Console.WriteLine($"{t.Name,-10} {t.Kind.ToString().ToLowerInvariant(),-8} {t.Description}");
        }

        return 0;

    case "seeds":
        {
            if (rest.Count != 2 || FuzzTargets.Find(rest.Dequeue()) is not { } target)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            string dir = Directory.CreateDirectory(rest.Dequeue()).FullName;
            foreach (var (name, bytes) in target.Seeds)
            {
                File.WriteAllBytes(Path.Combine(dir, name), bytes);
            }

            Console.WriteLine($"wrote {target.Seeds.Count} seed(s) to {dir}");
            return 0;
        }

    case "dict":
        {
            if (rest.Count != 2 || FuzzTargets.Find(rest.Dequeue()) is not { } target)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            // afl dictionary lines: name="value", with \ and " escaped and non-printables as \xNN.
            var lines = target.Dictionary.Select((token, i) => $"t{i}=\"{string.Concat(token.Select(Escape))}\"");
            File.WriteAllLines(rest.Dequeue(), lines);
            return 0;
        }

    case "cmin":
        {
            if (rest.Count < 3 || FuzzTargets.Find(rest.Dequeue()) is not { } target || Create(target, Subject.Reference) is not { } test)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            string seeds = rest.Dequeue();
            Cmin.Run(test, seeds, rest, Console.Out);
            return 0;
        }

    case "bench":
        {
            if (rest.Count is < 1 or > 3 || FuzzTargets.Find(rest.Dequeue()) is not { } target || Create(target, subject) is not { } test)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            int n = rest.Count > 0 ? int.Parse(rest.Dequeue(), System.Globalization.CultureInfo.InvariantCulture) : 1_000_000;
            string? folder = rest.Count > 0 ? rest.Dequeue() : null;
            if (folder is not null && !Directory.Exists(folder))
            {
                Console.Error.WriteLine($"bench: no input folder '{folder}'");
                return 2;
            }

            var inputs = folder is null ? null : Bench.Inputs(folder);
            var (perInput, crashes) = Bench.Run(test, n, inputs);
            string from = inputs is null ? "random 17-byte inputs" : $"the {inputs.Count} files of {folder} round robin";
            Console.WriteLine($"{target.Name}: {n} inputs ({from}), {perInput.TotalMicroseconds:F2} us/input, {crashes} crash(es)");
            if (target.CreatePhysicsOnly() is { } physics)
            {
                // The same inputs through the reference's physics alone (issue 51): the limit the target is measured against.
                var (limit, _) = Bench.Run(physics, n, inputs);
                Console.WriteLine($"{target.Name}: physics only (the reference, no judging) {limit.TotalMicroseconds:F2} us/input; the target runs at {100 * limit / perInput:F1} % of that limit");
            }
            return 0;
        }

    case "warmup":
        {
            if (rest.Count is < 1 or > 2 || FuzzTargets.Find(rest.Dequeue()) is not { } target || Create(target, subject) is not { } test)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            int ms = rest.Count > 0 ? int.Parse(rest.Dequeue(), System.Globalization.CultureInfo.InvariantCulture) : AcPhys.Spec.Running.ToolEnvironment.DefaultFuzzWarmupMs;
            int ran = Warmup.Run(test, target, TimeSpan.FromMilliseconds(ms), (n, mean) => Console.WriteLine($"{n,7} {mean.TotalMicroseconds,10:F1} us/input"));
            Console.WriteLine($"{target.Name}: {ran} warm-up inputs in {ms} ms");
            return 0;
        }

    case "replay":
        {
            if (rest.Count < 2 || FuzzTargets.Find(rest.Dequeue()) is not { } target)
            {
                Console.Error.WriteLine(Usage);
                return 2;
            }

            if (Create(target, subject) is not { } test)
            {
                return 2;
            }

            int crashes = 0;
            foreach (string file in rest)
            {
                crashes += Replay.Run(file, test, Console.Out);
            }

            Console.WriteLine($"replayed {rest.Count} input(s): {crashes} crash(es)");
            return crashes == 0 ? 0 : 1;
        }

    default:
        {
            if (FuzzTargets.Find(command) is not { } target)
            {
                Console.Error.WriteLine($"unknown target '{command}'; try: list");
                return 2;
            }

            if (Create(target, subject) is not { } test)
            {
                return 2;
            }

            if (rest.Count > 0)
            {
                // One input from a file (afl's @@, a saved case): an exception escapes, as in a crash under afl-fuzz.
                test(File.ReadAllBytes(rest.Dequeue()));
                return 0;
            }

            // Under afl-fuzz (__AFL_SHM_ID set) SharpFuzz serves inputs from stdin until afl-fuzz goes away; otherwise
            // it runs stdin once. An exception escaping the test is reported to afl-fuzz as a crash. Targets whose
            // inputs can outlast the timeout run out of process: afl-fuzz kills the timed-out child, not the server.
            Action<Stream> serve = Replay.FromStream(test);
            if (subject.IsExternal && !target.MayHang && settings.ImplCommand is not null
                && Environment.GetEnvironmentVariable("__AFL_SHM_ID") is { Length: > 0 })
            {
                // The child is started; warm it (and this process's wire code) before afl-fuzz's first timed input. Not
                // for a target run out of process: its child belongs to SharpFuzz's worker, restarted mid-campaign.
                if (settings.FuzzWarmup is not { } budget)
                {
                    Console.Error.WriteLine(settings.Problem(AcPhys.Spec.Running.ToolEnvironment.FuzzWarmupVariable));
                    return 2;
                }

                Warmup.Run(test, target, budget);
            }

            if (target.MayHang)
            {
                Fuzzer.OutOfProcess.Run(serve);
            }
            else
            {
                Fuzzer.Run(serve);
            }

            return 0;
        }
}

static Action<ReadOnlySpan<byte>>? Create(FuzzTarget target, Subject subject)
{
    try
    {
        return PortSubject.Refusal(target, subject) is { } why ? throw new ArgumentException(why) : target.CreateTest(subject);
    }
    catch (Exception e) when (e is ArgumentException or AcPhys.Spec.Adapters.AdapterLoadException or AcPhys.Contract.AdapterFailureException)
    {
        Console.Error.WriteLine(e.Message);
        return null;
    }
}

static string Escape(char c) => c switch
{
    '\\' => "\\\\",
    '"' => "\\\"",
    < ' ' or > '~' => $"\\x{(int)c:X2}",
    _ => c.ToString(),
};
