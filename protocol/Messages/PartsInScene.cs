using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Protocol.Messages;

/// <summary>A parts query in a scene (<c>find_cell_parts_scene</c>, <c>find_cell_parts_transition</c>): the scene, once resolved, and the parts.</summary>
/// <param name="Scene">The scene; null as the row reads the request (the server resolves <c>scene_id</c> or <c>scene</c> and sets it).</param>
/// <param name="Parts">The parts; the first is the anchor.</param>
public sealed record PartsInScene(Scene? Scene, IReadOnlyList<Part> Parts);
