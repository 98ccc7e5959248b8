namespace AcPhys.Protocol.Messages;

/// <summary>A planted bug of a world-frame shim (<c>acphys serve --world-frame --world-frame-fault</c>): the suite must fail it.</summary>
public enum WorldFrameFault
{
    /// <summary>The shim converts as docs/protocol.md "World frame" says.</summary>
    None,

    /// <summary>The block origin is taken as (192 · block y, 192 · block x): the id's two block bytes read the wrong way round.</summary>
    SwappedBlockAxes,
}
