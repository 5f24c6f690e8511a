"""A luminaire's output as its data sheet gives it: lumens, or watts and an efficacy.

Two ways to state it on a Sphere, Rect, Disk or Cylinder light (either one, not both)::

    float probesim:flux_lm = 3000              # the luminaire's total output, lm
    float probesim:power_W = 25                # or: its electrical power, W,
    float probesim:efficacy_lm_per_W = 120     # times its efficacy, lm/W (3000 lm)

The light then emits exactly that many lumens as traced: its emission is
Φ / G, with G the light's own geometric integral (its area and its shaping:
cone, focus, IES profile; :mod:`simulator.scene.light_flux`). So a 3,000 lm
0.6 × 0.6 m RectLight has L = 3000 / (π · 0.36) = 2,652.6 cd/m², and a cone
or an IES file changes where those lumens go, not how many there are. For an
IES-shaped light the file gives only the shape (its candelas scaled to the
stated lumens, whatever the file's own lamp lumens or ``shaping:ies:normalize``);
``probesim:ies:absolute`` (the file's own candelas) is the other way to give
an output, and may not be combined with these. The light's ``color`` (or
``colorTemperature``, ``probesim:spectrum``) gives its colour only: the
lumens are the stated ones. In a radiometric run (``light_units =
"radiometric"``) the lumens are still lumens; the radiant twin follows from
the light's spectrum.

Refused, with one line naming the prim: a negative or non-finite value;
both ways at once; watts without an efficacy (or an efficacy alone); any
of them together with an authored ``intensity``, ``exposure`` or
``normalize = 1`` (each states the output a second time); on a distant or
dome light (no finite flux) or on a mesh light (not read there).
"""

from __future__ import annotations

import math

from pxr import Usd, UsdLux

from simulator.scene.light_flux import flux_per_emission
from simulator.scene.model import Light
from simulator.scene.usd.context import _Context, _get
from simulator.scene.usd.legacy import lux_attr

__all__ = ["FLUX_ATTR", "POWER_ATTR", "EFFICACY_ATTR", "OUTPUT_ATTRS", "stated_output", "apply_stated_output"]

#: total luminous flux of the luminaire, lm
FLUX_ATTR = "probesim:flux_lm"
#: electrical power, W (with :data:`EFFICACY_ATTR`)
POWER_ATTR = "probesim:power_W"
#: luminous efficacy of the luminaire, lm per electrical W (with :data:`POWER_ATTR`)
EFFICACY_ATTR = "probesim:efficacy_lm_per_W"
OUTPUT_ATTRS = (FLUX_ATTR, POWER_ATTR, EFFICACY_ATTR)
_ABSOLUTE = "probesim:ies:absolute"


def _authored(ctx: _Context, prim: Usd.Prim, name: str) -> float | None:
    """A non-negative finite number the prim authors under ``name``; None when not authored."""
    attr = prim.GetAttribute(name)
    if not attr or not attr.HasAuthoredValue():
        return None
    value = _get(ctx, attr)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ctx.error(prim, f"{name} must be a number, not a {attr.GetTypeName()}")
    value = float(value)
    if not (math.isfinite(value) and value >= 0):
        raise ctx.error(prim, f"{name} must be a non-negative number, not {value:g}")
    return value


def stated_output(ctx: _Context, prim: Usd.Prim, what: str = "light") -> dict | None:
    """The output the prim states as lumens or watts × efficacy, checked; None when it states neither.

    Parameters
    ----------
    what : str
        ``"light"`` (a UsdLux light) or ``"mesh light"`` (refused: not read there).

    Returns
    -------
    dict or None
        ``{"flux_lm": Φ}``, or ``{"power_W": P, "efficacy_lm_per_W": η, "flux_lm": P·η}``.

    Raises
    ------
    UserError
        ``<stage>: <prim>: ...``, one line: see the module docstring.
    """
    flux, power, efficacy = (_authored(ctx, prim, n) for n in OUTPUT_ATTRS)
    if flux is None and power is None and efficacy is None:
        return None
    if what != "light":
        raise ctx.error(prim, f"{'/'.join(OUTPUT_ATTRS)} are read on Sphere, Rect, Disk and Cylinder lights, "
                              f"not on a {what}: give its intensity")
    if flux is not None and (power is not None or efficacy is not None):
        raise ctx.error(prim, f"both {FLUX_ATTR} and {POWER_ATTR}/{EFFICACY_ATTR}: state the output once")
    if (power is None) != (efficacy is None):
        given, missing = (POWER_ATTR, EFFICACY_ATTR) if efficacy is None else (EFFICACY_ATTR, POWER_ATTR)
        raise ctx.error(prim, f"{given} needs {missing} (lumens = W × lm/W)")
    api = UsdLux.LightAPI(prim)
    given = FLUX_ATTR if flux is not None else POWER_ATTR
    for attr in (api.GetIntensityAttr(), api.GetExposureAttr()):
        a = lux_attr(ctx, prim, attr)
        if a and a.HasAuthoredValue():
            raise ctx.error(prim, f"both {given} and {a.GetName()} state the light's output: keep one "
                                  f"({given} sets the lumens it emits)")
    n = lux_attr(ctx, prim, api.GetNormalizeAttr())
    if n and n.HasAuthoredValue() and bool(n.Get(ctx.time)):
        raise ctx.error(prim, f"both {given} and {n.GetName()} = 1: the lumens are already the light's total; "
                              f"remove {n.GetName()}")
    absolute = prim.GetAttribute(_ABSOLUTE)
    if absolute and absolute.HasAuthoredValue() and bool(absolute.Get(ctx.time)):
        raise ctx.error(prim, f"both {given} and {_ABSOLUTE} (the IES file's own candelas) state the output: keep one")
    if flux is not None:
        return {"flux_lm": flux}
    return {"power_W": power, "efficacy_lm_per_W": efficacy, "flux_lm": power * efficacy}


def apply_stated_output(ctx: _Context, prim: Usd.Prim, light: Light, stated: dict, spectrum) -> None:
    """Set ``light.emission`` so that the light emits ``stated["flux_lm"]`` lumens as traced.

    The photometric emission is Φ / G (cd/m², or cd for a point light; G from
    :func:`simulator.scene.light_flux.flux_per_emission`, after the light's
    size and shaping are read); its radiometric twin follows from the light's
    spectrum, whatever the run's ``light_units``.

    Raises
    ------
    UserError
        On a distant or dome light (no finite flux), or a shaping that sends nothing out (G = 0).
    """
    g = flux_per_emission(light)
    if g is None:
        raise ctx.error(prim, f"{FLUX_ATTR}: a {light.kind.name.title()} light has no finite flux: give its intensity")
    if not g > 0:
        raise ctx.error(prim, f"{FLUX_ATTR}: the light's shaping sends nothing out (cone angle 0?), so no "
                              "emission gives its lumens")
    luminous = stated["flux_lm"] / g
    w_per_lm, one = ctx.emission(1.0, spectrum)
    light.emission = (luminous * w_per_lm / one, luminous) if luminous > 0 else (0.0, 0.0)
