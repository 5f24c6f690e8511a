"""UsdLux inputs under their legacy names: ``intensity`` where ``inputs:intensity`` is not authored.

UsdLux gave its light attributes the ``inputs:`` prefix (``inputs:intensity``,
``inputs:shaping:cone:angle``, ``inputs:texture:file``, ...) when lights
became connectable shaders (USD 21.05); stages written before then author
the same attributes without it (``intensity``, ``shaping:cone:angle``,
``texture:file``). pxr reads those as custom attributes and gives the
schema attribute its fallback, so a legacy ``intensity = 500`` would read
as 1. The rule here: the ``inputs:`` name wins where it is authored (a
value or time samples); otherwise its legacy name is read where *that* is
authored; otherwise the schema's fallback. Each legacy attribute read is
counted once per prim for the summary warning line.

A schema attribute of an API the prim does not apply (``ShapingAPI``
inputs on a light without it) has no fallback on the prim: the fallback is
then taken from the API's prim definition, so reading never meets None.
"""

from __future__ import annotations

from pxr import Usd

from simulator.scene.usd.context import _Context, _get

__all__ = ["lux_attr", "lux_get", "LEGACY_PREFIX"]

#: the prefix UsdLux added to its inputs (USD 21.05); a legacy name is the input name without it
LEGACY_PREFIX = "inputs:"

# the applied APIs whose fallbacks an unapplied input falls back to, in the order they are tried
_APIS = ("LightAPI", "ShapingAPI", "ShadowAPI", "MeshLightAPI")


def lux_attr(ctx: _Context, prim: Usd.Prim, name_or_attr: str | Usd.Attribute) -> Usd.Attribute:
    """The attribute to read for a UsdLux input: its ``inputs:`` name where that is authored, else its
    legacy name where that is (counted in ``ctx.legacy``), else the ``inputs:`` attribute (its fallback).

    Parameters
    ----------
    name_or_attr : str or Usd.Attribute
        The input's schema name (``"inputs:texture:file"``) or its schema attribute
        (``UsdLux.LightAPI(prim).GetIntensityAttr()``).
    """
    name = name_or_attr if isinstance(name_or_attr, str) else name_or_attr.GetName()
    attr = prim.GetAttribute(name)
    if not name.startswith(LEGACY_PREFIX) or (attr and attr.HasAuthoredValue()):
        return attr
    old = prim.GetAttribute(name[len(LEGACY_PREFIX):])
    if old and old.HasAuthoredValue():
        ctx.legacy.setdefault(old.GetName(), {})[str(prim.GetPath())] = None
        return old
    return attr


def lux_get(ctx: _Context, prim: Usd.Prim, name_or_attr: str | Usd.Attribute):
    """The value of a UsdLux input at the run's time (:func:`lux_attr`, read as :func:`~.context._get`
    reads it); the schema fallback where nothing is authored, None only for an input no schema has."""
    attr = lux_attr(ctx, prim, name_or_attr)
    value = _get(ctx, attr) if attr else None
    if value is not None:
        return value
    name = name_or_attr if isinstance(name_or_attr, str) else name_or_attr.GetName()
    registry = Usd.SchemaRegistry()
    for api in _APIS:
        definition = registry.FindAppliedAPIPrimDefinition(api)
        if definition is not None and name in definition.GetPropertyNames():
            return definition.GetAttributeFallbackValue(name)
    return None
