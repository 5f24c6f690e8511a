"""UsdLuxShapingAPI on point, sphere, disk and rect lights.

Reads ``inputs:shaping:cone:angle``, ``inputs:shaping:cone:softness``,
``inputs:shaping:focus``, ``inputs:shaping:focusTint`` (as luminance grey),
``inputs:shaping:ies:file`` (IES LM-63 or EULUMDAT, by suffix) and
``inputs:shaping:ies:normalize`` into a
:class:`~simulator.scene.model.LightShaping`; its docstring gives the factor
applied to the emission toward each direction. Two probesim attributes
serve lighting engineers, who work in absolute candela:

- ``bool probesim:ies:absolute = 1`` (point lights only): the light emits
  exactly the file's candelas (× its multipliers) × the light loss factor;
  its intensity, exposure and colour are then not used;
- ``float probesim:lightLossFactor`` (default 1): the light loss factor of
  absolute mode, in (0, 1] usually (lamp lumen depreciation, dirt, ...).

Not read, and named in a warning where authored: ``shaping:ies:angleScale``
≠ 0 (its semantics are left open by UsdLux), and shaping on distant, dome
and cylinder lights.
"""

from __future__ import annotations

import math
import os

from pxr import Usd, UsdLux

from simulator.errors import UserError
from simulator.scene.model import Light, LightKind, LightShaping
from simulator.scene.photometry import read_photometry
from simulator.scene.usd.legacy import lux_get
from simulator.scene.usd.context import _Context
from simulator.scene.usd.materials import _grey

__all__ = ["read_shaping", "has_shaping"]

#: kinds shaping applies to (after a SphereLight becomes POINT)
SHAPED_KINDS = (LightKind.POINT, LightKind.SPHERE, LightKind.DISK, LightKind.RECT)
_ABSOLUTE = "probesim:ies:absolute"
_LLF = "probesim:lightLossFactor"


def has_shaping(prim: Usd.Prim) -> bool:
    """ShapingAPI applied, or any ``inputs:shaping:*`` (or legacy ``shaping:*``) / probesim IES attribute authored."""
    if prim.HasAPI(UsdLux.ShapingAPI):
        return True
    return any(
        a.GetName().startswith(("inputs:shaping:", "shaping:")) or a.GetName() in (_ABSOLUTE, _LLF)
        for a in prim.GetAuthoredAttributes()
    )


def read_shaping(ctx: _Context, prim: Usd.Prim, light: Light) -> None:
    """Set ``light.shaping`` from the prim (a no-op for unshaped prims); in
    absolute mode also set ``light.emission`` to 1 cd (the factor carries
    the candelas)."""
    if not has_shaping(prim):
        return
    if light.kind not in SHAPED_KINDS:
        ctx.warn(f"{prim.GetPath()}: UsdLuxShapingAPI on a {light.kind.name.title()} light ignored")
        return
    api = UsdLux.ShapingAPI(prim)
    angle = float(lux_get(ctx, prim, api.GetShapingConeAngleAttr()))
    softness = float(lux_get(ctx, prim, api.GetShapingConeSoftnessAttr()))
    focus = float(lux_get(ctx, prim, api.GetShapingFocusAttr()))
    for name, v in (("shaping:cone:angle", angle), ("shaping:cone:softness", softness), ("shaping:focus", focus)):
        if not math.isfinite(v):
            raise ctx.error(prim, f"{name} must be finite, not {v:g}")
    if angle < 0:
        raise ctx.error(prim, f"shaping:cone:angle must be ≥ 0 degrees, not {angle:g}")
    tint = _grey(ctx, prim, lux_get(ctx, prim, api.GetShapingFocusTintAttr()))
    sh = LightShaping(
        cone_angle_rad=math.radians(min(angle, 180.0)),
        cone_softness=min(max(softness, 0.0), 1.0),
        focus=max(focus, 0.0),
        focus_tint=min(max(float(tint), 0.0), 1.0),
    )
    scale = float(lux_get(ctx, prim, api.GetShapingIesAngleScaleAttr()))
    if scale != 0.0:
        ctx.warn(f"{prim.GetPath()}: shaping:ies:angleScale {scale:g} ignored (read as 0)")
    asset = lux_get(ctx, prim, api.GetShapingIesFileAttr())
    absolute_attr = prim.GetAttribute(_ABSOLUTE)
    sh.absolute = bool(absolute_attr.Get(ctx.time)) if absolute_attr and absolute_attr.HasAuthoredValue() else False
    llf_attr = prim.GetAttribute(_LLF)
    if llf_attr and llf_attr.HasAuthoredValue():
        sh.light_loss_factor = float(llf_attr.Get(ctx.time))
        if not (math.isfinite(sh.light_loss_factor) and sh.light_loss_factor > 0):
            raise ctx.error(prim, f"{_LLF} must be a positive number, not {sh.light_loss_factor:g}")
    if asset and asset.path:
        if not asset.resolvedPath:
            raise ctx.error(prim, f"shaping:ies:file {asset.path!r} not found")
        try:
            sh.ies = read_photometry(os.path.abspath(asset.resolvedPath))
        except UserError as e:
            raise ctx.error(prim, f"shaping:ies:file: {e}") from None
        peak = sh.ies.max_candela()
        if peak <= 0:
            raise ctx.error(prim, f"shaping:ies:file {asset.path!r} has no candela above 0")
        normalize = bool(lux_get(ctx, prim, api.GetShapingIesNormalizeAttr()))
        if sh.absolute:
            if light.kind != LightKind.POINT:
                raise ctx.error(prim, f"{_ABSOLUTE} needs a point-like light (a SphereLight with treatAsPoint or radius 0)")
            sh.ies_scale = sh.light_loss_factor
            # 1 cd, and its radiometric twin (W/sr) by the run's spectrum, whatever light_units says
            w, cd = ctx.emission(1.0)
            light.emission = (w / cd, 1.0)
        elif normalize:
            sh.ies_scale = 4.0 * math.pi / sh.ies.total_lumens()
        else:
            sh.ies_scale = 1.0 / peak
    elif sh.absolute:
        raise ctx.error(prim, f"{_ABSOLUTE} needs a shaping:ies:file")
    light.shaping = sh
