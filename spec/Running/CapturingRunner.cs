using FsCheck;
using Microsoft.FSharp.Collections;
using Microsoft.FSharp.Core;

namespace AcPhys.Spec.Running;

/// <summary>An FsCheck runner that keeps the result instead of printing it, and optionally forwards text to a sink.</summary>
internal sealed class CapturingRunner(Action<string>? sink) : IRunner
{
    public TestResult? Result { get; private set; }

    public void OnStartFixture(Type t)
    {
    }

    public void OnArguments(int ntest, FSharpList<object> args, FSharpFunc<int, FSharpFunc<FSharpList<object>, string>> every)
    {
    }

    public void OnShrink(FSharpList<object> args, FSharpFunc<FSharpList<object>, string> everyShrink)
    {
    }

    public void OnFinished(string name, TestResult testResult)
    {
        Result = testResult;
        sink?.Invoke(Runner.onFinishedToString(name, testResult));
    }
}
