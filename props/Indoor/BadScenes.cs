using System.Text.Json.Nodes;
using AcPhys.Formats;
using AcPhys.Formats.Scenes;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>Scene files are validated on load and refused whole; every message names the JSON path and the problem.</summary>
public sealed class BadScenes
{
    private static readonly string Valid = SceneJson.Write(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.3f, 2, 6f, 6f, 5, true, true)));

    public static TheoryData<string, string, string> Cases => new()
    {
        // label, JSON edit (applied by Edit), expected message fragment
        { "not JSON", "truncate", "$: not JSON" },
        { "missing blocks", "remove blocks", "$.blocks: missing" },
        { "block not hex", "blocks[0]=\"A9B4\"", "$.blocks[0]: expected a block id" },
        { "block off the map", "blocks[0]=\"0xFFB4\"", "$.blocks[0]: block 0xFFB4 is off the map" },
        { "duplicate block", "blocks[1]=\"0xA9B4\"", "$.blocks[1]: duplicate block 0xA9B4" },
        { "cell id not an env cell", "cells[0].id=\"0xA9B40013\"", "$.cells[0].id: 0xA9B40013 is not an env cell id" },
        { "duplicate cell id", "cells[1].id=\"0xA9B40100\"", "$.cells[1].id: duplicate cell 0xA9B40100" },
        { "cell in an undeclared block", "cells[0].id=\"0x10100100\"", "lies in block 0x1010, which the scene does not declare" },
        { "non-unit quaternion", "cells[0].frame.rotation=[1,0,0,0.1]", "$.cells[0].frame.rotation: quaternion (W, X, Y, Z) has length" },
        { "degenerate plane", "cells[0].portals[0].plane.n=[0,0,0]", "$.cells[0].portals[0].plane.n: degenerate plane" },
        { "non-finite plane", "cells[0].portals[0].plane.d=1e39", "$.cells[0].portals[0].plane.d: number overflows float32" },
        { "unknown cell in a portal", "cells[0].portals[1].other=\"0x0150\"", "$.cells[0].portals[1].other: unknown cell 0xA9B40150" },
        { "portal to itself", "cells[0].portals[1].other=\"0x0100\"", "$.cells[0].portals[1].other: a portal of 0xA9B40100 leads to itself" },
        { "portal other not an env low word", "cells[0].portals[1].other=\"0x0013\"", "$.cells[0].portals[1].other: 0x0013 is not an env cell low word" },
        { "portalSide not a boolean", "cells[0].portals[0].portalSide=1", "$.cells[0].portals[0].portalSide: expected true or false" },
        { "unknown visible cell", "cells[0].visible[0]=\"0xA9B40177\"", "$.cells[0].visible[0]: unknown cell 0xA9B40177" },
        { "visible cell in an undeclared block", "cells[0].visible[0]=\"0x10100100\"", "$.cells[0].visible[0]: unknown cell 0x10100100" },
        { "degenerate box", "cells[0].pieces[0].box.max=[0,6,3]", "$.cells[0].pieces[0].box: degenerate box" },
        { "unbounded plane piece", "cells[0].pieces[0]={\"planes\":[{\"n\":[1,0,0],\"d\":0},{\"n\":[0,1,0],\"d\":0},{\"n\":[0,0,1],\"d\":0},{\"n\":[-1,0,0],\"d\":5}]}", "$.cells[0].pieces[0].planes: the planes bound no finite volume" },
        { "no pieces", "cells[0].pieces=[]", "$.cells[0].pieces: a cell needs at least one piece" },
        { "unknown cell behind a building portal", "buildings[0].portals[0].cell=\"0x0160\"", "$.buildings[0].portals[0].cell: unknown cell 0xA9B40160" },
        { "building in an undeclared block", "buildings[0].block=\"0x1010\"", "$.buildings[0].block: block 0x1010 is not declared" },
        { "two buildings on one land cell", "buildings[1]=copy0", "$.buildings[1].origin: land cell 0xA9B40013 already holds building 0" },
        { "otherPortal out of range", "cells[0].portals[0].otherPortal=70000", "$.cells[0].portals[0].otherPortal: expected an integer 0..65535" },
    };

    [Theory(DisplayName = "A bad scene is refused whole with its JSON path and what is wrong")]
    [MemberData(nameof(Cases))]
    public void BadSceneIsRefused(string label, string edit, string expected)
    {
        string json = Edit(Valid, edit);
        var e = Assert.Throws<InputFormatException>(() => SceneJson.Read(json, "bad.json"));
        Assert.StartsWith("bad.json: ", e.Message);
        Assert.True(e.Message.Contains(expected, StringComparison.Ordinal), $"{label}: got \"{e.Message}\"");
    }

    [Fact(DisplayName = "A key given twice in a scene is refused with its path (it once kept the last silently)")]
    public void DuplicateKeyIsRefused()
    {
        int open = Valid.IndexOf('{', StringComparison.Ordinal);
        string json = Valid[..(open + 1)] + "\"blocks\":[]," + Valid[(open + 1)..]; // a second "blocks", before the real one
        var e = Assert.Throws<InputFormatException>(() => SceneJson.Read(json, "bad.json"));
        Assert.Contains("bad.json: $.blocks: duplicate key", e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A written scene reads back to the same text")]
    public void RoundTrip()
    {
        var scene = SceneJson.Read(Valid, "valid.json");
        Assert.Equal(Valid, SceneJson.Write(scene));
        Assert.Equal(3, scene.Cells.Count);
    }

    private static string Edit(string json, string edit)
    {
        if (edit == "truncate")
        {
            return json[..(json.Length / 2)];
        }

        var root = JsonNode.Parse(json)!.AsObject();
        if (edit.StartsWith("remove ", StringComparison.Ordinal))
        {
            root.Remove(edit["remove ".Length..]);
            return root.ToJsonString();
        }

        int eq = edit.IndexOf('=', StringComparison.Ordinal);
        string path = edit[..eq], value = edit[(eq + 1)..];
        var steps = path.Split('.');
        JsonNode node = root;
        for (int i = 0; i < steps.Length - 1; i++)
        {
            node = Step(node, steps[i]);
        }

        var replacement = value == "copy0" ? root["buildings"]![0]!.DeepClone() : JsonNode.Parse(value);
        string last = steps[^1];
        int bracket = last.IndexOf('[', StringComparison.Ordinal);
        if (bracket < 0)
        {
            node[last] = replacement;
        }
        else
        {
            var array = node[last[..bracket]]!.AsArray();
            int index = int.Parse(last[(bracket + 1)..^1], System.Globalization.CultureInfo.InvariantCulture);
            if (index < array.Count)
            {
                array[index] = replacement;
            }
            else
            {
                array.Add(replacement);
            }
        }

        return root.ToJsonString();
    }

    private static JsonNode Step(JsonNode node, string step)
    {
        int bracket = step.IndexOf('[', StringComparison.Ordinal);
        if (bracket < 0)
        {
            return node[step]!;
        }

        return node[step[..bracket]]![int.Parse(step[(bracket + 1)..^1], System.Globalization.CultureInfo.InvariantCulture)]!;
    }
}
