using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Client;

/// <summary>The <c>hello</c> handshake: what the child states (operations, declarations) and negotiates (capabilities).</summary>
public sealed partial class ProcessAdapter
{
    /// <summary>Starts the implementation and performs the <c>hello</c> handshake.</summary>
    /// <param name="commandLine">The command line (run through <c>/bin/sh -c</c>, or <c>cmd /c</c> on Windows).</param>
    /// <param name="options">Timeout and stderr handling.</param>
    /// <returns>The adapter.</returns>
    /// <exception cref="AdapterFailureException">It could not be started or did not complete the handshake.</exception>
    public static ProcessAdapter Start(string commandLine, ProcessAdapterOptions? options = null)
    {
        options ??= new ProcessAdapterOptions();
        var child = LineProcess.Start(commandLine, options.StderrSink, options.MaxLineBytes);
        try
        {
            string answer = child.Exchange(
                Wire.Line(w =>
                {
                    w.WriteString("op", "hello");
                    w.WriteNumber("protocol", Wire.Version);
                }),
                "hello",
                options.Timeout > options.HandshakeTimeout ? options.Timeout : options.HandshakeTimeout);
            using var doc = ParseAnswer(answer, "hello", commandLine);
            var hello = doc.RootElement;
            if (hello.TryGetProperty("error", out var error))
            {
                throw new AdapterFailureException($"'{commandLine}' refused the handshake: {Wire.Show(error)}");
            }

            try
            {
                int protocol = Wire.ReadInt(hello, "protocol");
                if (protocol != Wire.Version)
                {
                    throw new AdapterFailureException($"'{commandLine}' speaks protocol {protocol}; this tool speaks {Wire.Version}");
                }

                // The name is the implementation's text: escaped and cut once here, so every report quotes it safely (issue 28).
                string name = InputQuote.Line(hello.TryGetProperty("name", out _) ? Wire.ReadString(hello, "name") : commandLine, 120);
                var opsField = Wire.Field(hello, "ops");
                if (opsField.ValueKind != JsonValueKind.Array || opsField.EnumerateArray().Any(e => e.ValueKind != JsonValueKind.String))
                {
                    throw new WireException("field \"ops\" must be an array of op names");
                }

                var ops = CapabilityNames.Parse(opsField.EnumerateArray().Select(e => e.GetString()!), out var capabilities, out var unknown);
                string? pickName = hello.TryGetProperty("pick", out var p) && p.ValueKind != JsonValueKind.Null ? Wire.ReadString(hello, "pick") : null;
                if (!PickNames.TryParse(pickName, out var pick))
                {
                    throw new WireException($"unknown pick \"{pickName}\" (known: retail, current-first)");
                }

                var declared = hello.TryGetProperty("fidelity", out var fid) && fid.ValueKind != JsonValueKind.Null ? fid : default;
                if (declared.ValueKind != JsonValueKind.Undefined && (declared.ValueKind != JsonValueKind.Array || declared.EnumerateArray().Any(e => e.ValueKind != JsonValueKind.String)))
                {
                    throw new WireException("field \"fidelity\" must be an array of deviation names");
                }

                var names = declared.ValueKind == JsonValueKind.Array ? declared.EnumerateArray().Select(e => e.GetString()!).ToArray() : [];
                if (!FidelityNames.TryParse(names, out var indoor, out var outdoor, out var bad))
                {
                    throw new WireException($"unknown fidelity \"{Wire.Brief(bad!, 60)}\" (known: {string.Join(", ", FidelityNames.Known)})");
                }

                string frame = hello.TryGetProperty("frame", out var f) && f.ValueKind != JsonValueKind.Null ? Wire.ReadString(hello, "frame") : "block";
                if (frame is not ("block" or WorldFrame.Name))
                {
                    throw new WireException($"unknown frame \"{Wire.Brief(frame, 40)}\" (known: block, world)");
                }

                if (indoor.AceKeepsStaleCells && SceneQueryKinds.OffersScenes(ops) && ((capabilities & Capability.FindCellWalk) == 0 || frame == WorldFrame.Name))
                {
                    // The stale array lives for one walk (facts §7 #6; docs/conformance.md, "Declared modes"): a port asked
                    // query by query cannot tell where a walk begins, so its answers could not be judged.
                    throw new AdapterFailureException($"'{commandLine}' declares ace-keeps-stale-cells but is asked query by query ({(frame == WorldFrame.Name ? "world frame" : "no find_cell_walk")}): the stale array lives for one walk, so a port declaring it must announce find_cell_walk in the block frame (docs/conformance.md, \"Declared modes\")");
                }

                if (indoor.AceKeepsStaleCells && (ops & (Op.FindCellPartsScene | Op.FindCellPartsTransition)) != 0 && ((capabilities & Capability.FindCellPartsWalk) == 0 || frame == WorldFrame.Name))
                {
                    // The parts list's stale array lives for one walk as the sphere list's does (facts §7 #6).
                    throw new AdapterFailureException($"'{commandLine}' declares ace-keeps-stale-cells but would be asked its parts queries one by one ({(frame == WorldFrame.Name ? "world frame" : "no find_cell_parts_walk")}): the stale array lives for one walk, so a port declaring it that offers find_cell_parts_scene or find_cell_parts_transition must announce find_cell_parts_walk in the block frame (docs/conformance.md, \"Declared modes\")");
                }

                return new ProcessAdapter(child, options.Timeout, name, ops, capabilities, pick, unknown) { Indoor = indoor, Outdoor = outdoor, InWorldFrame = frame == WorldFrame.Name };
            }
            catch (WireException e)
            {
                throw new AdapterFailureException($"'{commandLine}' answered the handshake with something that is not protocol v1: {e.Message}. Answer: {Wire.Brief(answer, 200)}", e);
            }
        }
        catch
        {
            child.Dispose();
            throw;
        }
    }
}
