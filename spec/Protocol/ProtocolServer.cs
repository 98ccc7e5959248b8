using System.Text.Json;
using AcPhys.Core;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Protocol;

/// <summary>
/// Serves an <see cref="ICellPhysics"/> over protocol v1 (docs/protocol.md): one request per line in, one answer per
/// line out, in order. <c>acphys serve</c> runs it over the reference core so the out-of-process path is tested end to end.
/// </summary>
/// <param name="impl">The implementation to serve.</param>
public sealed class ProtocolServer(ICellPhysics impl)
{
    /// <summary>The answer to a <c>find_cell</c> with a scene, until scenes land (issue #4, branch <c>indoor</c>).</summary>
    public const string ScenesNotSupported = "scenes not supported yet";

    /// <summary>Reads requests until end of input, answering each on its own line.</summary>
    /// <param name="input">Requests.</param>
    /// <param name="output">Answers (flushed after each).</param>
    public void Serve(TextReader input, TextWriter output)
    {
        while (input.ReadLine() is string line)
        {
            if (line.Length == 0)
            {
                continue;
            }

            output.WriteLine(Answer(line));
            output.Flush();
        }
    }

    /// <summary>Answers one request line.</summary>
    /// <param name="line">The request.</param>
    /// <returns>The answer line: the op's result or <c>{"error": ...}</c>.</returns>
    public string Answer(string line)
    {
        try
        {
            using var doc = Wire.Parse(line);
            return Dispatch(doc.RootElement);
        }
        catch (WireException e)
        {
            return Error("malformed request: " + e.Message);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return Error($"{e.GetType().Name}: {e.Message}");
        }
    }

    private static string Error(string message) => Wire.Line(w => w.WriteString("error", message));

    private static string Ok(bool ok, Lcoord lcoord) => Wire.Line(w =>
    {
        w.WriteBoolean("ok", ok);
        w.WriteNumber("x", lcoord.X);
        w.WriteNumber("y", lcoord.Y);
    });

    private string Dispatch(JsonElement request)
    {
        string op = Wire.ReadString(request, "op");
        if (op == "hello")
        {
            return Hello(request);
        }

        var known = OpNames.Parse([op], out _);
        if (known == Op.None)
        {
            return Error($"unknown op \"{op}\"");
        }

        if ((impl.Ops & known) == 0)
        {
            return Error($"op \"{op}\" not offered by {impl.Name}");
        }

        switch (known)
        {
            case Op.BlockIdToLcoord:
                {
                    bool ok = impl.BlockIdToLcoord(Wire.ReadCell(request, "cell"), out var lc);
                    return Ok(ok, lc);
                }

            case Op.GidToLcoord:
                {
                    bool ok = impl.GidToLcoord(Wire.ReadCell(request, "cell"), out var lc);
                    return Ok(ok, lc);
                }

            case Op.LcoordToGid:
                {
                    var id = impl.LcoordToGid(Wire.ReadInt(request, "x"), Wire.ReadInt(request, "y"));
                    return Wire.Line(w => Wire.WriteCell(w, "cell", id));
                }

            case Op.InboundValidCellId:
                {
                    bool ok = impl.InboundValidCellId(Wire.ReadCell(request, "cell"));
                    return Wire.Line(w => w.WriteBoolean("ok", ok));
                }

            case Op.GetOutsideLcoord:
                {
                    bool ok = impl.GetOutsideLcoord(Wire.ReadCell(request, "cell"), Wire.ReadFloat(request, "x"), Wire.ReadFloat(request, "y"), out var lc);
                    return Ok(ok, lc);
                }

            case Op.AdjustToOutside:
                {
                    var r = impl.AdjustToOutside(Wire.ReadCell(request, "cell"), Wire.ReadFloat(request, "x"), Wire.ReadFloat(request, "y"));
                    return Wire.Line(w =>
                    {
                        w.WriteBoolean("ok", r.Ok);
                        Wire.WriteCell(w, "cell", r.Cell);
                        Wire.WriteFloat(w, "x", r.X);
                        Wire.WriteFloat(w, "y", r.Y);
                    });
                }

            case Op.OutsideCells:
                {
                    var cells = impl.OutsideCells(Wire.ReadCell(request, "cell"), Wire.ReadSpheres(request, "spheres"));
                    return Wire.Line(w => Wire.WriteCells(w, "cells", cells));
                }

            case Op.FindCell:
                {
                    if (Wire.Field(request, "scene").ValueKind != JsonValueKind.Null)
                    {
                        // Hook for scenes (issue #4): open land only until the scene format lands.
                        return Error(ScenesNotSupported);
                    }

                    var r = impl.FindCell(Wire.ReadCell(request, "cell"), Wire.ReadSpheres(request, "spheres"), Wire.ReadOptionalCell(request, "current"));
                    return Wire.Line(w =>
                    {
                        Wire.WriteCells(w, "cells", r.Cells);
                        if (r.Containing.IsNone)
                        {
                            w.WriteNull("containing");
                        }
                        else
                        {
                            Wire.WriteCell(w, "containing", r.Containing);
                        }
                    });
                }

            case Op.OutsideCellsParts:
                {
                    var cells = impl.OutsideCellsParts(PartWire.ReadParts(request, "parts"));
                    return Wire.Line(w => Wire.WriteCells(w, "cells", cells));
                }

            default:
                return Error($"unknown op \"{op}\"");
        }
    }

    private string Hello(JsonElement request)
    {
        if (request.TryGetProperty("protocol", out var p) && !(p.ValueKind == JsonValueKind.Number && p.TryGetInt32(out int v) && v == Wire.Version))
        {
            return Error($"protocol {Wire.Show(p)} not supported (this server speaks {Wire.Version})");
        }

        return Wire.Line(w =>
        {
            w.WriteNumber("protocol", Wire.Version);
            w.WriteString("name", impl.Name);
            w.WriteStartArray("ops");
            foreach (var name in OpNames.Names(impl.Ops))
            {
                w.WriteStringValue(name);
            }

            w.WriteEndArray();
            w.WriteString("pick", PickNames.Of(impl.Pick));
        });
    }
}
