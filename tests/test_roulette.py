"""The Russian roulette threshold: a rule per scene, and unbiased at any value.

A path's throughput β never falls below the threshold t: below it the path
survives with probability β/t and is lifted back to t (E[β'] = β), so t
changes only the noise and the cost of a reading, never its mean. The
engine sets t = min(0.1, 0.2·(1 − ρ̄)), at least 0.01, ρ̄ the scene's
area-weighted albedo (engine.methods, where the measurements behind the
rule are).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from simulator.commands.verify import _load_case, default_configs_dir, expected_values
from simulator.engine.driver import Engine
from simulator.engine.methods import RR_THRESHOLD_MAX, RR_THRESHOLD_MIN, mean_albedo, rr_threshold_rule
from simulator.reference.cases import case
from simulator.scene.model import SensorKind


def _furnace(rho: str):
    c = dataclasses.replace(case("furnace ρ=0.5"), variants=(("reflectance", rho),))
    _, scene, sensors, _ = _load_case(c, default_configs_dir())
    return c, scene, sensors


@pytest.mark.parametrize("rho, t", [("rho_0_5", 0.1), ("rho_0_9", 0.02), ("rho_0_95", 0.01)])
def test_rule_follows_the_albedo(rho, t):
    """The furnace's walls all have albedo ρ, so ρ̄ = ρ and t = min(0.1,
    0.2·(1 − ρ)): 0.1 at ρ = 0.5, 0.02 at 0.9, 0.01 at 0.95; the engine's
    TraceParams carry it, and an explicit engine.rr_threshold overrides it."""
    _, scene, sensors = _furnace(rho)
    assert mean_albedo(scene) == pytest.approx({"rho_0_5": 0.5, "rho_0_9": 0.9, "rho_0_95": 0.95}[rho], abs=1e-6)
    assert rr_threshold_rule(scene)[0] == pytest.approx(t, rel=1e-6)
    eng = Engine(scene, sensors)
    assert eng.trace_params("path", 1).rr_threshold == pytest.approx(t, rel=1e-6)
    eng.rr_threshold = 0.5
    assert eng.trace_params("path", 1).rr_threshold == pytest.approx(0.5)


def test_rule_bounds():
    """No geometry (ρ̄ = 0) gives the cap 0.1; a closed box of albedo 0.999
    gives the floor 0.01, not 2e-4 (paths ~ln t/ln ρ̄ bounces long)."""
    _, scene, _ = _furnace("rho_0_5")
    g = scene.geometry
    empty = dataclasses.replace(scene, geometry=dataclasses.replace(g, points=g.points[:0], triangles=g.triangles[:0],
                                                                    albedo=g.albedo[:0]))  # fmt: skip
    assert rr_threshold_rule(empty)[0] == RR_THRESHOLD_MAX
    white = dataclasses.replace(scene, geometry=dataclasses.replace(g, albedo=np.full_like(g.albedo, 0.999)))
    assert rr_threshold_rule(white)[0] == RR_THRESHOLD_MIN


@pytest.mark.parametrize("t", [0.01, 1.0])
def test_furnace_reads_its_closed_form_at_any_threshold(t):
    """The furnace at ρ = 0.9 reads L_e/(1 − ρ) (irradiance π·L_e/(1 − ρ))
    within 4 standard errors both with t = 0.01 (paths rarely rouletted) and
    t = 1 (plain roulette with probability ρ at every bounce): the weight
    window is unbiased whatever its threshold."""
    c, scene, sensors = _furnace("rho_0_9")
    rows = expected_values(c)
    eng = Engine(scene, sensors)
    eng.rr_threshold = t
    res = eng.run("path", samples=1 << 12, seed=31)
    checked = 0
    for i, (s, ch, truth, _) in enumerate(rows):
        if s.kind != SensorKind.IRRADIANCE:
            continue  # verify reports a patch's flux, the engine its mean irradiance
        checked += 1
        assert abs(res.mean[i, ch] - truth) <= 4 * res.stderr[i, ch] + 2e-6 * abs(truth), (t, s.name, res.mean[i, ch], truth)
    assert checked >= 3


def test_pilot_lowers_the_threshold_where_the_roulette_is_the_noise():
    """The threshold pilot (engine.methods.rr_pilot_choice). In the
    integrating sphere (ρ = 0.8, a point source at the centre) every wall
    point gets the same direct light, I/R², so next-event estimation adds
    an almost fixed amount at each vertex and the roulette's own noise is
    nearly all there is: past the threshold the path goes on with weight t
    for a geometric number of vertices (mean ρ/(1 − ρ)), so the relative
    variance per sample is ∝ t² while a path is only ln t/ln ρ vertices
    longer. The pilot must go below the rule's t = 0.2·(1 − 0.8) = 0.04,
    each step of 4× cutting variance × rays by well over its margin of 2,
    down to its last step t/64 = 6.25e-4 in a fixed-budget run; with a 1%
    target and 32 samples drawn anyway it stops at 0.01, where its noisiest
    sensor needs 1.96²·relvar/0.01² ≤ 32 samples. In the furnace at ρ = 0.5
    (emitting walls) a vertex's light varies with the direction drawn, and
    a lower t only lengthens paths: the rule's 0.1 stays."""
    cfg_case = case("integrating_sphere")
    _, scene, sensors, _ = _load_case(cfg_case, default_configs_dir())
    sensors = [s for s in sensors if s.kind == SensorKind.IRRADIANCE]
    eng = Engine(scene, sensors)
    eng.run("path", samples=32, seed=5)
    p = eng.rr_pilot
    assert p["rule"] == pytest.approx(0.04, rel=1e-3)
    assert p["threshold"] == pytest.approx(0.04 / 64, rel=1e-6), p["tried"]
    costs = [rv * rays for _, rv, _, rays in p["tried"]]
    assert all(b * 2.0 <= a for a, b in zip(costs, costs[1:])), p["tried"]
    eng.run("path", samples=32, seed=5, rel_error=0.01, max_samples=32)
    assert eng.rr_pilot["threshold"] == pytest.approx(0.01, rel=1e-6), eng.rr_pilot["tried"]
    _, fscene, fsensors = _furnace("rho_0_5")
    feng = Engine(fscene, [s for s in fsensors if s.kind == SensorKind.IRRADIANCE])
    feng.run("path", samples=64, seed=5)
    assert feng.rr_pilot["threshold"] == pytest.approx(0.1, rel=1e-6), feng.rr_pilot["tried"]
    assert len(feng.rr_pilot["tried"]) == 2


def test_no_pilot_with_an_explicit_threshold():
    """engine.rr_threshold set: the run uses it as it is, no pilot runs."""
    _, scene, sensors = _furnace("rho_0_9")
    eng = Engine(scene, [s for s in sensors if s.kind == SensorKind.IRRADIANCE])
    eng.rr_threshold = 0.3
    eng.run("path", samples=32, seed=2)
    assert eng.rr_pilot is None
