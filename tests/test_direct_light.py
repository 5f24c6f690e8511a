"""The `light` estimator on every bundled closed-form stage, in both light-unit modes.

Each expected value comes from ``simulator.reference.closed_forms`` (an independent
numpy implementation of the formulas in docs/REFERENCES.md), evaluated with the
light parameters the stage reader produced. A reading passes when
|estimate − truth| ≤ 4·stderr + 2e-6·|truth|: four standard errors is the
statistical bound (a fixed seed; a 6e-5 two-sided chance per reading of a
false alarm for a correct estimator), 2e-6 relative covers float32
arithmetic in the kernels, so that a zero-variance delta-light reading must
be exact to float32 precision. Each stage's config must also reach a
standard error under 0.5% of the value.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.reference import closed_forms as cf
from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.pipeline import collect_sensors, load_scene
from simulator.scene.model import LightKind, SensorKind, patch_width_axis

CONFIGS = Path(__file__).resolve().parents[1] / "configs"
FLOAT32_SLACK = 2e-6


def _light(scene, kind):
    (light,) = [l for l in scene.lights if l.kind == kind]
    return light


def _patch_vertices(s):
    right = patch_width_axis(s.up, s.normal)
    w, h = s.size
    c = s.position
    return np.array([c - right * w / 2 - s.up * h / 2, c + right * w / 2 - s.up * h / 2,
                     c + right * w / 2 + s.up * h / 2, c - right * w / 2 + s.up * h / 2])  # fmt: skip


def expected(stage: str, scene, s, ch: int) -> float:
    """Closed-form reading of sensor ``s`` (channel 0 radiometric, 1 photometric)."""
    if stage == "point":
        l = _light(scene, LightKind.POINT)
        I = l.emission[ch]
        if s.kind == SensorKind.PATCH:  # mean irradiance = I·Ω / area
            return cf.point_flux_through_polygon(I, l.position, _patch_vertices(s)) / (s.size[0] * s.size[1])
        return cf.point_irradiance(I, l.position, s.position, s.normal)
    if stage == "sphere":
        l = _light(scene, LightKind.SPHERE)
        if s.kind == SensorKind.RADIANCE:  # the 5° cone lies inside the 14.5° disc the sphere subtends
            return l.emission[ch]
        return cf.sphere_irradiance(l.emission[ch], l.position, l.radius, s.position, s.normal)
    if stage == "rect":
        l = _light(scene, LightKind.RECT)
        if s.kind == SensorKind.RADIANCE:  # the 5° cone lies inside the rectangle
            return l.emission[ch]
        verts = cf.rect_light_vertices(l.position, l.frame[:, 0], l.frame[:, 1], l.width, l.height)
        return cf.polygon_irradiance(l.emission[ch], verts, s.position, s.normal, one_sided_normal=-l.frame[:, 2])
    if stage == "disk":
        l = _light(scene, LightKind.DISK)
        h = l.position[2] - s.position[2]
        a = math.hypot(*(s.position[:2] - l.position[:2]))
        if a == 0.0:
            return cf.disk_irradiance_on_axis(l.emission[ch], l.radius, h, tilt=math.acos(s.normal[2]))
        return cf.disk_irradiance_parallel(l.emission[ch], l.radius, h, a)
    if stage == "distant_occluder":
        l = _light(scene, LightKind.DISTANT)
        shadowed = abs(s.position[0]) < 0.5 and abs(s.position[1]) < 0.5  # under the 1 m square
        return 0.0 if shadowed else l.emission[ch] * max(0.0, float(np.dot(s.normal, l.frame[:, 2])))
    if stage == "dome":
        l = _light(scene, LightKind.DOME)
        if s.kind == SensorKind.RADIANCE:
            return l.emission[ch]
        return cf.dome_irradiance(l.emission[ch], math.acos(s.normal[2]))
    raise AssertionError(stage)


STAGES = ["point", "sphere", "rect", "disk", "distant_occluder", "dome"]


@pytest.mark.parametrize("units", ["photometric", "radiometric"])
@pytest.mark.parametrize("stage", STAGES)
def test_light_estimator_matches_closed_form(stage, units):
    """Every reading of the stage's config agrees with its closed form within
    4 standard errors, and the standard error is under 0.5% of the value."""
    cfg = dataclasses.replace(load_config(CONFIGS / f"{stage}.toml"), light_units=units)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    res = Engine(scene, sensors).run("light", samples=cfg.simulation.samples, seed=cfg.simulation.seed)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            truth = expected(stage, scene, s, ch)
            est, se = res.mean[i, ch], res.stderr[i, ch]
            bound = 4.0 * se + FLOAT32_SLACK * abs(truth) + 1e-12
            assert abs(est - truth) <= bound, f"{stage}/{s.name}[{ch}]: {est} vs {truth} ± {se}"
            if truth > 0:
                assert se < 0.005 * truth, f"{stage}/{s.name}[{ch}]: stderr {se / truth:.2%} ≥ 0.5%"


@pytest.mark.parametrize("stage", ["point", "distant_occluder"])
def test_delta_lights_read_exactly_with_zero_variance(stage):
    """A point light and an angle-0 distant light have one direction each: the
    estimator is a constant, so unoccluded irradiance sensors read the closed
    form to float32 precision with a standard error of exactly 0."""
    cfg = load_config(CONFIGS / f"{stage}.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind == SensorKind.IRRADIANCE]
    res = Engine(scene, sensors).run("light", samples=64, seed=3)
    for i, s in enumerate(sensors):
        assert res.stderr[i, 0] == 0.0 and res.stderr[i, 1] == 0.0, s.name
        truth = expected(stage, scene, s, 1)
        assert abs(res.mean[i, 1] - truth) <= FLOAT32_SLACK * truth + 1e-12, s.name
