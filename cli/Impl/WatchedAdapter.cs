using System.Diagnostics;
using System.Globalization;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Cli.Impl;

/// <summary>
/// An <c>--impl</c> adapter (in process) under the same rules as an <c>--impl-cmd</c> child (issue 28): a call that does
/// not return within <c>--timeout</c> stops the run with exit 2 and names the operation; an <c>Environment.Exit</c>
/// inside a call is reported as the adapter's and exits 2; its name is escaped. Calls are only counted, never moved to
/// another thread, so the adapter sees the same threads and exceptions as before.
/// </summary>
internal sealed class WatchedAdapter : ICellPhysics, IDisposable
{
    private readonly ICellPhysics inner;
    private readonly TimeSpan timeout;
    private readonly Thread watchdog;
    private readonly CancellationTokenSource stop = new();
    private long completed;
    private int inside;
    private string current = "its constructor";

    private WatchedAdapter(ICellPhysics inner, TimeSpan timeout, string name)
    {
        this.inner = inner;
        this.timeout = timeout;
        Name = name;
        watchdog = new Thread(Watch) { IsBackground = true, Name = "acphys --impl watchdog" };
    }

    /// <inheritdoc/>
    public string Name { get; }

    /// <inheritdoc/>
    public Op Ops => inner.Ops;

    /// <inheritdoc/>
    public PickPolicy Pick => inner.Pick;

    /// <inheritdoc/>
    public IndoorFidelity Indoor => inner.Indoor;

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor => inner.Outdoor;

    /// <summary>Loads the adapter of an assembly (<see cref="AdapterLoader"/>) and watches it from its constructor on.</summary>
    /// <param name="path">The assembly.</param>
    /// <param name="timeout">The most one call may take.</param>
    /// <returns>The watched adapter.</returns>
    public static WatchedAdapter Load(string path, TimeSpan timeout)
    {
        var probe = new Probe(timeout);
        probe.Enter("its constructor");
        ICellPhysics loaded;
        string name;
        try
        {
            loaded = AdapterLoader.Load(path);
            probe.Enter("Name");
            name = AcPhys.Formats.Values.InputQuote.Line(loaded.Name ?? Path.GetFileName(path), 120);
        }
        finally
        {
            probe.Dispose();
        }

        var adapter = new WatchedAdapter(loaded, timeout, name);
        AppDomain.CurrentDomain.ProcessExit += adapter.OnProcessExit;
        adapter.watchdog.Start();
        return adapter;
    }

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord)
    {
        Enter(Op.BlockIdToLcoord);
        try
        {
            return inner.BlockIdToLcoord(id, out lcoord);
        }
        finally
        {
            Exit();
        }
    }

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord)
    {
        Enter(Op.GidToLcoord);
        try
        {
            return inner.GidToLcoord(id, out lcoord);
        }
        finally
        {
            Exit();
        }
    }

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => Call(Op.LcoordToGid, () => inner.LcoordToGid(x, y));

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => Call(Op.InboundValidCellId, () => inner.InboundValidCellId(id));

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord)
    {
        Enter(Op.GetOutsideLcoord);
        try
        {
            return inner.GetOutsideLcoord(id, x, y, out lcoord);
        }
        finally
        {
            Exit();
        }
    }

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y) => Call(Op.AdjustToOutside, () => inner.AdjustToOutside(id, x, y));

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => Call(Op.OutsideCells, () => inner.OutsideCells(cell, spheres));

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Call(Op.FindCell, () => inner.FindCell(cell, spheres, current));

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Call(Op.OutsideCellsParts, () => inner.OutsideCellsParts(parts));

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) =>
        Call(Op.FindCellScene, () => inner.FindCell(scene, cell, spheres, current));

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        Call(Op.FindCellTransition, () => inner.FindCell(scene, cell, spheres, current, loadCells));

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) =>
        Call(Op.OutsideCells, () => inner.OutsideCells(cell, origin, spheres));

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
        Call(Op.FindCell, () => inner.FindCell(cell, origin, spheres, current));

    /// <inheritdoc/>
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) =>
        Call(loadCells ? Op.FindCellPartsTransition : Op.FindCellPartsScene, () => inner.FindCellParts(scene, parts, loadCells));

    /// <inheritdoc/>
    public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        inner.Indoor.AceKeepsStaleCells
            ? Call("find_cell_parts_walk", () => inner.FindCellPartsWalk(scene, queries, loadCells)) // its array lives for the walk (facts §7 #6): asked whole
            : [.. queries.Select(q => FindCellParts(scene, q, loadCells))]; // query by query, each watched with its own timeout

    /// <inheritdoc/>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) =>
        inner.Indoor.AceKeepsStaleCells
            ? Call("find_cell_walk", () => inner.FindCellWalk(walk)) // its array lives for the walk (facts §7 #6): asked whole
            : WalkThread.AskEach(this, walk); // query by query, each watched with its own timeout

    /// <inheritdoc/>
    public void Dispose()
    {
        stop.Cancel();
        AppDomain.CurrentDomain.ProcessExit -= OnProcessExit;
        if (inner is IDisposable owned)
        {
            owned.Dispose();
        }
    }

    // Named by the protocol's own table, so a hang message names an op that exists (issue 52: it said block_id_to_lcoord).
    private T Call<T>(Op op, Func<T> body) => Call(OpNames.Name(op), body);

    private T Call<T>(string op, Func<T> body)
    {
        Enter(op);
        try
        {
            return body();
        }
        finally
        {
            Exit();
        }
    }

    private void Enter(Op op) => Enter(OpNames.Name(op));

    private void Enter(string op)
    {
        current = op;
        Interlocked.Increment(ref inside);
    }

    private void Exit()
    {
        Interlocked.Decrement(ref inside);
        Interlocked.Increment(ref completed);
    }

    // A call in progress and no call finished for the timeout: the adapter hangs.
    private void Watch()
    {
        long seen = -1;
        long since = Stopwatch.GetTimestamp();
        while (!stop.Token.WaitHandle.WaitOne(100))
        {
            long now = Interlocked.Read(ref completed);
            if (now != seen || Volatile.Read(ref inside) == 0)
            {
                seen = now;
                since = Stopwatch.GetTimestamp();
                continue;
            }

            if (Stopwatch.GetElapsedTime(since) > timeout)
            {
                Guard.Abort(Hung(Name, current, timeout));
                return;
            }
        }
    }

    private static string Hung(string name, string op, TimeSpan timeout) => string.Create(
        CultureInfo.InvariantCulture,
        $"the implementation could not answer: '{name}' (--impl) did not return from {op} within {timeout.TotalSeconds:0.###} s (--timeout); the run was stopped");

    private void OnProcessExit(object? sender, EventArgs e)
    {
        if (!Guard.Returned && Volatile.Read(ref inside) > 0)
        {
            Exited(Name, current);
        }
    }

    private static void Exited(string name, string op)
    {
        // An Environment.Exit inside the adapter would otherwise end the run with the adapter's own code and no word
        // (issue 28: exit 3 read as "output unwritable"). It cannot be stopped; it is named and becomes exit 2.
        Console.Error.WriteLine(string.Create(
            CultureInfo.InvariantCulture,
            $"acphys: the implementation could not answer: '{name}' (--impl) ended the process (Environment.Exit({Environment.ExitCode})) inside {op}; reported as exit {ExitCodes.ToolError}"));
        Environment.ExitCode = ExitCodes.ToolError;
    }

    // Watches the load (constructor, Name) the same way, before the adapter exists.
    private sealed class Probe : IDisposable
    {
        private readonly TimeSpan timeout;
        private readonly CancellationTokenSource done = new();
        private string op = "its constructor";

        public Probe(TimeSpan timeout)
        {
            this.timeout = timeout;
            AppDomain.CurrentDomain.ProcessExit += OnExit;
            new Thread(() =>
            {
                if (!done.Token.WaitHandle.WaitOne(this.timeout))
                {
                    Guard.Abort(Hung("--impl adapter", op, this.timeout));
                }
            })
            { IsBackground = true, Name = "acphys --impl load watchdog" }.Start();
        }

        public void Enter(string what) => op = what;

        public void Dispose()
        {
            done.Cancel();
            AppDomain.CurrentDomain.ProcessExit -= OnExit;
        }

        private void OnExit(object? sender, EventArgs e)
        {
            if (!Guard.Returned && !done.IsCancellationRequested)
            {
                Exited("--impl adapter", op);
            }
        }
    }
}
