"""The `light` estimator on every bundled closed-form stage, in both light-unit modes.

Each expected value is the reference registry's (``simulator.reference.cases``):
``simulator.reference.closed_forms`` (an independent numpy implementation of
the formulas in docs/REFERENCES.md), evaluated with the light parameters the
stage reader produced. A reading passes when
|estimate − truth| ≤ 4·stderr + 2e-6·|truth|: four standard errors is the
statistical bound (a fixed seed; a 6e-5 two-sided chance per reading of a
false alarm for a correct estimator), 2e-6 relative covers float32
arithmetic in the kernels, so that a zero-variance delta-light reading must
be exact to float32 precision. Each stage's config must also reach a
standard error under 0.5% of the value.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from simulator.reference import cases as C
from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.pipeline import collect_sensors, load_scene
from simulator.scene.model import SensorKind

CONFIGS = Path(__file__).resolve().parents[1] / "configs"
FLOAT32_SLACK = 2e-6


def expected(stage: str, scene, s, ch: int, cfg=None) -> float:
    """Closed-form reading of sensor ``s`` (channel 0 radiometric, 1
    photometric): the expected value of the reference case ``stage``
    (``cfg``: the config as read, light units included; default the case's own)."""
    case = C.case(stage)
    cfg = cfg or load_config(CONFIGS / case.config)
    return float(case.expected(C.CaseContext(cfg, scene, CONFIGS, [s]), s, ch))


#: the bundled reference stages (the chart suite) that verify traces with `light`
STAGES = [c.name for c in C.suite("chart") if "verify" in c.suites and c.method == "light"]


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
            truth = expected(stage, scene, s, ch, cfg)
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
