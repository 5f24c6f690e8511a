"""Surface materials: UsdPreviewSurface albedo, emission and opacity, displayColor, greys.

A gprim's bound ``UsdPreviewSurface`` gives its Lambertian albedo
(``diffuseColor``), its front-face emitted radiance (``emissiveColor``) and
whether it is there at all (``opacity`` 0 removes it). Inputs are followed
through connections to authored constants; with no usable material,
``primvars:displayColor`` or the UsdPreviewSurface default is the albedo.
Colours become luminance greys (BT.709 Y), and one summary warning names
the prims whose colour was not grey.
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd, UsdGeom, UsdShade

from simulator.units import luminance_grey
from simulator.scene.usd.context import _Context, _get, _name_list, _not_uniform

#: UsdPreviewSurface's fallback diffuseColor (0.18, 0.18, 0.18), used when nothing is authored
DEFAULT_ALBEDO = 0.18

# UsdPreviewSurface input fallbacks (from its specification).
_PREVIEW_DEFAULTS = {
    "diffuseColor": (DEFAULT_ALBEDO,) * 3,
    "emissiveColor": (0.0, 0.0, 0.0),
    "opacity": 1.0,
}


def _surface(ctx: _Context, prim: Usd.Prim) -> tuple[float, tuple[float, float]] | None:
    """``(albedo, emission pair)`` of a gprim, or None when opacity 0 removes it."""
    inputs = _material_inputs(ctx, prim)
    if inputs is None:
        rgb, source = _display_color(ctx, prim)
        inputs = {"diffuseColor": (rgb, source), "emissiveColor": (_PREVIEW_DEFAULTS["emissiveColor"], ""),
                  "opacity": (1.0, "")}
    opacity = float(inputs["opacity"][0])
    if opacity <= 0.0:
        ctx.warn(f"{prim.GetPath()}: opacity 0; left out (it blocks no light)")
        return None
    if opacity < 1.0:
        ctx.warn(f"{prim.GetPath()}: partial opacity {opacity:g} treated as opaque")
    albedo = _albedo(ctx, prim, inputs)
    rgb, source = inputs["emissiveColor"]
    radiance = _grey(ctx, prim, rgb)
    if not (math.isfinite(radiance) and radiance >= 0.0):
        raise ctx.error(prim, f"emission {radiance:g} from {source} must be a non-negative number")
    return albedo, ctx.emission(radiance)


def _albedo(ctx: _Context, prim: Usd.Prim, inputs: dict) -> float:
    """Grey ``diffuseColor`` of material inputs, which must lie in [0, 1) (energy conservation)."""
    rgb, source = inputs["diffuseColor"]
    albedo = _grey(ctx, prim, rgb)
    if not (math.isfinite(albedo) and 0.0 <= albedo < 1.0):
        raise ctx.error(prim, f"albedo {albedo:g} from {source} must be in [0, 1) (energy conservation)")
    return albedo


def _grey(ctx: _Context, prim: Usd.Prim, rgb) -> float:
    """Luminance grey of a colour (or a scalar); remember prims whose colour was not grey."""
    c = np.atleast_1d(np.asarray(rgb, float))
    if c.size == 1:
        return float(c[0])
    if _not_uniform(np.ptp(c), float(np.max(np.abs(c)))):
        ctx.coloured[str(prim.GetPath())] = None
    return luminance_grey(c)


def _finish_warnings(ctx: _Context) -> None:
    """One summary warning for every colour that was reduced to grey."""
    if ctx.coloured:
        ctx.warn(f"coloured albedo/emission/light colour reduced to luminance grey: {_name_list(list(ctx.coloured))}")


def _material_inputs(ctx: _Context, prim: Usd.Prim) -> dict | None:
    """The bound UsdPreviewSurface's inputs as ``{name: (value, where)}``, None without a usable material."""
    material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial(UsdShade.Tokens.full)
    if not material:
        return None
    key = str(material.GetPath())
    if key not in ctx.materials:
        ctx.materials[key] = _preview_surface_inputs(ctx, material)
    return ctx.materials[key]


def _preview_surface_inputs(ctx: _Context, material: UsdShade.Material) -> dict | None:
    """Read diffuseColor/emissiveColor/opacity off a material's UsdPreviewSurface."""
    shader, _, _ = material.ComputeSurfaceSource()
    if not shader or shader.GetShaderId() != "UsdPreviewSurface":
        ctx.warn(f"{material.GetPath()}: surface is not a UsdPreviewSurface; using displayColor or the default albedo")
        return None
    return {name: _input_value(ctx, shader, name, default) for name, default in _PREVIEW_DEFAULTS.items()}


def _input_value(ctx: _Context, shader: UsdShade.Shader, name: str, default):
    """Value of a shader input, through connections to an authored constant; else the default.

    ``GetValueProducingAttributes`` follows connections through NodeGraph and
    Material interface inputs. A shader output at the end (e.g. a texture)
    is not a constant: warn and use the UsdPreviewSurface default.
    """
    inp = shader.GetInput(name)
    where = f"{shader.GetPath()}.inputs:{name}"
    if not inp:
        return default, f"{where} (default)"
    for attr in inp.GetValueProducingAttributes():
        if UsdShade.Output.IsOutput(attr):
            ctx.warn(f"{where}: connected to {attr.GetPath()}, which is not a constant; using the default")
            return default, f"{where} (default)"
        value = _get(ctx, attr)
        if value is not None:
            return value if isinstance(value, tuple) else float(value), str(attr.GetPath())
    return default, f"{where} (default)"


def _display_color(ctx: _Context, prim: Usd.Prim):
    """``primvars:displayColor`` as albedo when authored (mean of many values), else the default grey."""
    pv = UsdGeom.Gprim(prim).GetDisplayColorPrimvar()
    if pv and pv.HasAuthoredValue():
        values = np.asarray(pv.ComputeFlattened(ctx.time) or [], float).reshape(-1, 3)
        if len(values):
            if len(values) > 1 and np.ptp(values, axis=0).max() > 0:
                ctx.warn(f"{prim.GetPath()}: varying displayColor averaged to one albedo")
            return tuple(values.mean(axis=0)), f"{prim.GetPath()}.primvars:displayColor"
    return _PREVIEW_DEFAULTS["diffuseColor"], "the default albedo"
