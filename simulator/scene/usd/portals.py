"""UsdLux PortalLights: the rectangles through which a DomeLight is sampled.

A PortalLight (UsdLux: "a rectangular portal in the local XY plane that
guides sampling of a dome light") is read as a
:class:`~simulator.scene.model.Portal`: its world centre and frame, and
``inputs:width`` × ``inputs:height`` times the transform's X and Y scales.
It passes the dome's light toward its local −Z.

Which dome a portal serves is the DomeLight's (and DomeLight_1's)
``portals`` relationship, which the schema declares ("optional portals to
guide light sampling"): a dome is sampled through the PortalLights it
targets, and a PortalLight that no dome targets is ignored with a warning.
A portal only guides sampling, so leaving one out changes no reading, only
its noise. A portal's own light inputs (intensity, colour, ...) are not
read: it emits nothing itself (authored ones are named in the summary
warning).
"""

from __future__ import annotations

import math

from pxr import Sdf, Usd, UsdLux

from simulator.scene.model import Light, Portal
from simulator.scene.usd.legacy import lux_attr, lux_get
from simulator.scene.usd.context import _Context, _get
from simulator.scene.usd.transforms import _axis_scales, _frame, _world_affine

#: a PortalLight's LightAPI inputs and the value at which they change nothing
_INERT_INPUTS = {
    "inputs:intensity": 1.0, "inputs:exposure": 0.0, "inputs:color": (1.0, 1.0, 1.0),
    "inputs:enableColorTemperature": False, "inputs:diffuse": 1.0, "inputs:specular": 1.0,
}  # fmt: skip


def is_portal(prim: Usd.Prim) -> bool:
    """True for a UsdLux PortalLight prim."""
    return prim.IsA(UsdLux.PortalLight)


def read_portal(ctx: _Context, prim: Usd.Prim) -> Portal | None:
    """One PortalLight in world metres (None, with a warning, for a zero size).

    Raises
    ------
    UserError
        A negative or non-finite width or height, or a degenerate transform.
    """
    portal = UsdLux.PortalLight(prim)
    a, t = _world_affine(ctx, prim)
    scales = _axis_scales(a)
    size = []
    for what, attr in (("width", portal.GetWidthAttr()), ("height", portal.GetHeightAttr())):
        v = float(lux_get(ctx, prim, attr))
        if not (math.isfinite(v) and v >= 0):
            raise ctx.error(prim, f"PortalLight {what} must be a non-negative number, not {v:g}")
        size.append(v)
    width, height = size[0] * float(scales[0]), size[1] * float(scales[1])
    if width <= 0.0 or height <= 0.0:
        ctx.warn(f"{prim.GetPath()}: PortalLight has zero size ({width:g} m x {height:g} m); ignored")
        return None
    for name, inert in _INERT_INPUTS.items():
        attr = lux_attr(ctx, prim, name)
        if attr and attr.HasAuthoredValue() and _get(ctx, attr) != inert:
            ctx.ignored[f"{name} of a PortalLight"] += 1
    return Portal(str(prim.GetPath()), t, _frame(ctx, prim, a), width, height)


def attach_portals(ctx: _Context, stage: Usd.Stage, domes: list[tuple[Light, Usd.Prim]], portals: dict[str, Portal]) -> None:
    """Give each dome the portals its ``portals`` relationship targets.

    ``portals``: the PortalLights read, by prim path. A target that is read
    is attached; one that is a PortalLight but was not read (inactive,
    invisible, zero size) is left out; a portal no dome targets is warned
    about, once per prim.

    Raises
    ------
    UserError
        A target that is not on the stage or is not a PortalLight (naming
        the dome and the target).
    """
    used: set[str] = set()
    for light, prim in domes:
        rel = prim.GetRelationship("portals")
        targets = rel.GetForwardedTargets() if rel else []
        mine = []
        for path in targets:
            target = stage.GetPrimAtPath(Sdf.Path(path))
            if not target:
                raise ctx.error(prim, f"portals target {path} is not on the stage")
            if not is_portal(target):
                raise ctx.error(prim, f"portals target {path} is a {target.GetTypeName() or 'typeless prim'}, not a PortalLight")
            key = str(target.GetPath())
            if key in portals and key not in {p.name for p in mine}:
                mine.append(portals[key])
                used.add(key)
        light.portals = tuple(mine)
    for name in portals:
        if name not in used:
            ctx.warn(f"{name}: PortalLight is in no DomeLight's portals relationship; ignored "
                     "(a portal only guides a dome's sampling: add it to the dome's portals)")
