"""Stage-authored sensors: prims with ``probesim:sensor:kind``.

A sensor sits at its prim's world origin and faces down the prim's local -Z
axis, like a USD camera; the table of attributes is in
:mod:`simulator.scene.usd` ("Stage-authored sensors"). Sensors are
measurement points, not rendered things: visibility and purpose do not hide
them.
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd

from simulator.scene.model import DEFAULT_GLARE_RESOLUTION, DEFAULT_PROBE_RESOLUTION, MODEL_KINDS, SENSOR_KINDS, Sensor, SensorKind
from simulator.scene.usd.context import _Context, _get
from simulator.scene.usd.transforms import _axis_scales, _unit, _world_affine

#: namespace of the attributes that make a prim a sensor
SENSOR_ATTR_PREFIX = "probesim:sensor:"




def _is_sensor(prim: Usd.Prim) -> bool:
    """True for a prim with ``probesim:sensor:kind`` (whatever its type, visibility or purpose)."""
    return prim.HasAttribute(SENSOR_ATTR_PREFIX + "kind")


def _read_sensor(ctx: _Context, prim: Usd.Prim) -> Sensor:
    """A stage-authored sensor: at the prim's world origin, facing its world -Z."""
    kind_name = str(_sensor_attr(ctx, prim, "kind", None)).strip().lower()
    if kind_name not in SENSOR_KINDS:
        raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}kind {kind_name!r} is not one of {', '.join(SENSOR_KINDS)}")
    kind = SENSOR_KINDS[kind_name]
    a, t = _world_affine(ctx, prim)
    normal = _unit(-a[:, 2])
    up = None if normal is None else _unit(a[:, 1] - np.dot(a[:, 1], normal) * normal)
    if normal is None or up is None:
        raise ctx.error(prim, "transform is degenerate (zero scale); cannot orient the sensor")
    sensor = Sensor(
        name=str(_sensor_attr(ctx, prim, "name", str(prim.GetPath()))),
        kind=kind, position=t, normal=normal, up=up, source=str(prim.GetPath()),
    )
    model = str(_sensor_attr(ctx, prim, "model", "") or "").strip()
    if model:  # a sensor model: a bundled name, or a .toml relative to the stage file
        if kind not in MODEL_KINDS:
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}model: only an irradiance or a patch sensor takes a model")
        from pathlib import Path

        from simulator.errors import UserError
        from simulator.sensor_models.model import load_model

        try:
            sensor.model = load_model(model, Path(ctx.path).parent, f"{SENSOR_ATTR_PREFIX}model")
        except UserError as e:
            raise ctx.error(prim, str(e)) from None
    if kind == SensorKind.RADIANCE:
        half = float(_sensor_attr(ctx, prim, "halfAngleDeg", 0.0))
        if not (math.isfinite(half) and 0.0 <= half <= 90.0):
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}halfAngleDeg must be in [0, 90], not {half:g}")
        sensor.half_angle = math.radians(half)
    elif kind == SensorKind.PATCH:
        size = _sensor_attr(ctx, prim, "size", None)
        if size is None or len(size) != 2:
            raise ctx.error(prim, f"a patch sensor needs {SENSOR_ATTR_PREFIX}size = (width, height)")
        scales = _axis_scales(a)  # includes metersPerUnit
        w, h = float(size[0] * scales[0]), float(size[1] * scales[1])
        if not (math.isfinite(w) and math.isfinite(h) and w > 0 and h > 0):
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}size must be positive, not {tuple(size)}")
        sensor.size = (w, h)
    elif kind in (SensorKind.PROBE, SensorKind.GLARE):
        default = DEFAULT_PROBE_RESOLUTION if kind == SensorKind.PROBE else DEFAULT_GLARE_RESOLUTION
        res = _sensor_attr(ctx, prim, "resolution", default)
        if len(res) != 2 or int(res[0]) < 1 or int(res[1]) < 1:
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}resolution must be two positive integers, not {tuple(res)}")
        sensor.resolution = (int(res[0]), int(res[1]))
    if kind == SensorKind.GLARE:
        sensor.glare = _glare_settings(ctx, prim)
    return sensor


def _glare_settings(ctx: _Context, prim: Usd.Prim):
    """A glare prim's settings: ``probesim:sensor:evalglare`` (evalglare's source options) and
    ``probesim:sensor:dgpStderr`` (the standard error of DGP it traces to)."""
    from simulator.glare.sources import GlareSettings, parse_evalglare_options

    try:
        opts = parse_evalglare_options(str(_sensor_attr(ctx, prim, "evalglare", "")))
    except ValueError as e:
        raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}evalglare: {e}") from None
    target = float(_sensor_attr(ctx, prim, "dgpStderr", 0.005))
    if not (math.isfinite(target) and 0.0 < target < 1.0):
        raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}dgpStderr must be between 0 and 1, not {target:g}")
    return GlareSettings(dgp_stderr=target, **opts)


def _sensor_attr(ctx: _Context, prim: Usd.Prim, name: str, default):
    """Value of ``probesim:sensor:<name>`` if authored, else ``default`` (None default: required)."""
    attr = prim.GetAttribute(SENSOR_ATTR_PREFIX + name)
    value = _get(ctx, attr) if attr and attr.HasAuthoredValue() else None
    if value is None:
        if default is None and name == "kind":
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}kind has no value")
        return default
    return value
