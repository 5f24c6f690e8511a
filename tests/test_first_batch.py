"""An adaptive run's first batch: sized by the engine from a short pilot
where the config leaves ``samples`` out, a floor where it sets it.

A sensor's need at the end of a run is n = z²·stderr²·n_drawn/target², the
samples that meet z·stderr ≤ rel·|value| at its measured variance per sample
(stderr² = σ²/n); the run should spend little more than that on its slowest
sensor (the rule's next batch is its need × 1.1, engine.adaptive).
"""

from __future__ import annotations

import dataclasses
import numpy as np
import pytest

from simulator.commands.verify import _load_case, default_configs_dir, expected_values
from simulator.config import load_config
from simulator.config.overrides import apply_overrides
from simulator.engine.adaptive import (
    PILOT_LOW_BATCH,
    PILOT_MIN_BATCH,
    StoppingRule,
    first_batch_from_pilot,
    pilot_floor,
    run_batches,
)
from simulator.engine.driver import BLOCK, Engine
from simulator.engine.methods import rr_pilot_choice
from simulator.reference.cases import case
from simulator.scene.model import SensorKind


def _case(name: str, variant: tuple | None = None):
    c = case(name)
    if variant is not None:
        c = dataclasses.replace(c, variants=(variant,))
    _, scene, sensors, _ = _load_case(c, default_configs_dir())
    return c, scene, sensors


def test_first_batch_is_half_the_pilots_median_need_within_its_bounds():
    """need = z²·relvar/rel²: relvar 0.01 at 1% and z = 1.96 needs 384.16,
    so the batch is ⌈0.5·384.16⌉ = 193; a tiny need gives the floor, a huge
    one the upper bound, a pilot that read nothing the upper bound (nothing
    to size by). The median, not the mean, of the pilot's sensors."""
    z = 1.96
    assert first_batch_from_pilot(np.array([0.01, 0.01, np.nan]), z, 0.01, 1024) == 193
    assert first_batch_from_pilot(np.array([0.001, 0.01, 100.0]), z, 0.01, 1 << 20) == 193
    assert first_batch_from_pilot(np.array([1e-7]), z, 0.01, 1024) == PILOT_MIN_BATCH
    assert first_batch_from_pilot(np.array([1.0]), z, 0.01, 1024) == 1024
    assert first_batch_from_pilot(np.array([np.nan, np.nan]), z, 0.01, 1024) == 1024
    assert first_batch_from_pilot(np.array([1e-7]), z, 0.01, 4) == 4  # never above the upper bound


def test_roulette_pilot_is_tuned_to_the_target_not_the_first_batch():
    """Adaptive cost of a threshold: rays × max(floor, z²·relvar_max/rel²),
    the rays the noisiest sensor spends. With measurements like the
    integrating sphere's (t = 0.04: relvar_max 3.4e-3 at 40 rays, needing
    131 samples at 1%; t = 0.01: 2.0e-4 at 52 rays, needing 7.9) a first
    batch of 1,024 (the old rule: the target is met within it, so stop at
    the rule's t) must not keep t = 0.04 when the floor is 8: 52·8 = 416 rays
    against 40·131 = 5,240."""
    table = {0.04: (8.2e-4, 3.4e-3, 40.0), 0.01: (4.3e-5, 2.0e-4, 52.0), 0.0025: (2.4e-6, 1.2e-5, 65.0),
             0.000625: (1.7e-7, 8e-7, 77.0)}
    seen = []

    def measure(t):
        seen.append(round(t, 6))
        return table[round(t, 6)]

    t, tried = rr_pilot_choice(0.04, measure, PILOT_MIN_BATCH, 1.96, 0.01)
    assert t == pytest.approx(0.01) and seen == [0.04, 0.01]  # 7.9 ≤ 8: no lower t can save a sample
    seen.clear()
    t, _ = rr_pilot_choice(0.04, measure, 1024, 1.96, 0.01)
    assert t == pytest.approx(0.04) and seen == [0.04]  # 131 ≤ 1024: 1,024 samples at 40 rays are the cheapest
    seen.clear()
    t, _ = rr_pilot_choice(0.04, measure)  # fixed budget: relvar × rays, lowered while it halves
    assert t == pytest.approx(0.000625) and seen == [0.04, 0.01, 0.0025, 0.000625]


def test_a_sensor_reading_zero_is_not_stopped_before_the_dark_floor():
    """A unit whose samples are all 0 has stderr 0 and would meet any
    relative target at once; with ``dark_floor`` it doubles up to that floor
    first (the samples a default first batch would have given it), while a
    lit unit stops by its variance."""
    value = np.array([[0.0, 0.0], [100.0, 100.0]])
    sigma = np.array([[0.0, 0.0], [10.0, 10.0]])  # the lit one needs (1.96·10/1)² = 385 samples
    count = np.zeros(2, np.int64)

    def step(ids, first, n):
        count[ids] += n

    def measure():
        with np.errstate(divide="ignore", invalid="ignore"):
            return value, sigma / np.sqrt(np.maximum(count, 1))[:, None]

    rule = StoppingRule(0.01, 0.0, 0.95)
    drawn, met = run_batches(step, np.ones(2, bool), np.full(2, 8, np.int64), 1 << 14, block=32, rule=rule,
                             measure=measure, dark_floor=1024)  # fmt: skip
    assert met.all()
    assert drawn[0] == 1024
    assert 385 <= drawn[1] <= 1.3 * 385
    count[:] = 0
    drawn, _ = run_batches(step, np.ones(2, bool), np.full(2, 8, np.int64), 1 << 14, block=32, rule=rule,
                           measure=measure)  # fmt: skip
    assert drawn[0] == 8  # without the floor: stopped on its first batch


@pytest.mark.parametrize("name, variant, method, rel", [("furnace ρ=0.5", ("reflectance", "rho_0_5"), "path", 0.01),
                                                        ("rect", None, "light", 0.005)])
def test_chosen_first_batch_spends_at_most_1_3x_what_the_slowest_sensor_needs(name, variant, method, rel):
    """With ``choose_first_batch`` the engine sizes the first batch from a
    pilot (at most ``samples``, here far above the need), and the run draws
    on its slowest sensor at most 1.3× that sensor's need, over all sensors
    at most 1.3× their needs; the readings stay within 4 standard errors of
    the closed form (the pilot is discarded, so nothing it sees biases them)."""
    c, scene, sensors = _case(name, variant)
    rows = expected_values(c)
    eng = Engine(scene, sensors)
    res = eng.run(method, samples=1 << 16, seed=11, rel_error=rel, choose_first_batch=True)
    plan = eng.batch_plans[method]
    assert plan["chosen_by"] == "pilot" and PILOT_MIN_BATCH <= plan["first_batch"] < plan["needed_max"], plan
    assert plan["spent_at_needed_max"] <= 1.3 * plan["needed_max"], plan
    assert plan["spent_over_needed"] <= 1.3, plan
    assert res.target_met.all()
    checked = 0
    for i, (s, ch, truth, _) in enumerate(rows):
        if s.kind != SensorKind.IRRADIANCE:
            continue
        checked += 1
        assert abs(res.mean[i, ch] - truth) <= 4 * res.stderr[i, ch] + 2e-6 * abs(truth), (s.name, res.mean[i, ch], truth)
    assert checked >= 3


def test_pilot_floor_follows_the_pilots_90th_percentile_need_raised_by_its_error():
    """A need from m pilot samples has the relative standard error of a
    variance from m samples, √(2/(m − 1)) (0.5345 at m = 8, 0.0886 at
    m = 256); the floor is ⌈q₀.₉·(1 + that)⌉ within [PILOT_LOW_BATCH, 8]:
    needs all 2 at m = 8 give ⌈3.07⌉ = 4; all 3 give ⌈4.60⌉ = 5; needs 1 … 10
    (q₀.₉ = 9.1) give 13.96, held at 8; all 3 at m = 256 give ⌈3.27⌉ = 4; a
    pilot of one sample per sensor says nothing (8)."""
    assert PILOT_LOW_BATCH == 4
    assert pilot_floor(np.full(32, 2.0), 8) == 4
    assert pilot_floor(np.full(32, 3.0), 8) == 5
    assert pilot_floor(np.arange(1.0, 11.0), 8) == PILOT_MIN_BATCH
    assert pilot_floor(np.full(4, 3.0), 256) == 4
    assert pilot_floor(np.full(4, 3.0), 1) == PILOT_MIN_BATCH
    assert pilot_floor(np.full(4, 1e-6), 8) == PILOT_LOW_BATCH  # never below 3 degrees of freedom
    z = 1.96  # through first_batch_from_pilot: relvar 2e-5 at 1% needs 0.77 each, so the floor is 4
    assert first_batch_from_pilot(np.full(32, 2e-5), z, 0.01, 1024, pilot_samples=8) == 4
    assert first_batch_from_pilot(np.full(32, 2e-5), z, 0.01, 1024) == PILOT_MIN_BATCH  # no pilot size: the floor
    assert first_batch_from_pilot(np.full(32, 2e-5), z, 0.01, 2, pilot_samples=8) == 2  # never above the upper bound
    assert first_batch_from_pilot(np.array([0.01, 0.01]), z, 0.01, 1024, pilot_samples=8) == 193  # the median rule


def test_integrating_sphere_first_batch_and_threshold_from_one_pilot():
    """In the integrating sphere at 1% the pilot's sensors need a few
    samples at t = 0.01 (and ~130 at the rule's 0.04), so the roulette pilot
    stops at 0.01 and the first batch is the floor the pilot's needs set
    (below 8: :func:`pilot_floor`); a sensor that misses the target in it
    takes one more batch. The old rule, the config's 1,024 as the first
    batch, kept t = 0.04 and drew 1,024."""
    c, scene, sensors = _case("integrating_sphere")
    sensors = [s for s in sensors if s.kind == SensorKind.IRRADIANCE]
    eng = Engine(scene, sensors)
    res = eng.run("path", samples=1024, seed=3, rel_error=0.01, choose_first_batch=True)
    assert eng.rr_pilot["threshold"] == pytest.approx(0.01, rel=1e-6), eng.rr_pilot["tried"]
    plan = eng.batch_plans["path"]
    need = 1.96**2 * eng.rr_pilot["relvar"] / 0.01**2
    assert plan["first_batch"] == pilot_floor(need[np.isfinite(need)], plan["pilot_samples"]) < PILOT_MIN_BATCH, plan
    assert res.target_met.all() and res.samples.max() <= plan["first_batch"] + BLOCK


def test_integrating_sphere_grid_draws_at_most_1_3x_its_slowest_sensors_need():
    """The bundled grid of 256 sensors in the integrating sphere, adaptive
    to 1% at the config's seed: the pilot's sensors need 0.9 samples
    (median) to 7.9, the floor is 6, and the run draws at most 1.3× per
    sensor what its slowest sensor needs (8.1 per sensor against 6.0 with
    the fixed floor of 8). Given samples are a floor: 128 (more than any
    sensor's 1% needs, at most 38 in the adaptive run) makes the run draw
    at least 128 each, where the pilot's choice draws under 40; a budget of
    1,024 showed the same at 8× the CPU."""
    cfg = apply_overrides(load_config(default_configs_dir() / "integrating_sphere_grid.toml"), rel_error=0.01)
    from simulator.pipeline import collect_sensors, load_scene

    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    eng = Engine(scene, sensors)
    res = eng.run("path", samples=cfg.simulation.samples, seed=cfg.simulation.seed, rel_error=0.01,
                  choose_first_batch=cfg.simulation.choose_first_batch)  # fmt: skip
    plan = eng.batch_plans["path"]
    assert plan["chosen_by"] == "pilot" and plan["first_batch"] < PILOT_MIN_BATCH, plan
    assert res.target_met.all()
    assert res.samples.sum() / len(sensors) <= 1.3 * plan["needed_max"], (res.samples.sum(), plan)
    res = eng.run("path", samples=128, seed=3, rel_error=0.01)  # samples given: the floor
    assert eng.batch_plans["path"] == {**eng.batch_plans["path"], "first_batch": 128, "chosen_by": "samples"}
    assert res.samples.min() == 128


def test_samples_left_out_of_a_config_is_the_engines_to_choose(tmp_path):
    """``samples`` absent from the file: ``samples_set`` False and an adaptive
    run chooses its first batch; given in the file or by ``--samples``: a
    floor. A fixed-budget run draws ``samples`` either way."""
    stage = default_configs_dir().parent / "stages" / "rect.usda"
    body = f'stage = "{stage.as_posix()}"\n[simulation]\nrel_error = 0.01\n{{extra}}[[sensor]]\nname = "a"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'
    path = tmp_path / "a.toml"
    path.write_text(body.replace("{extra}", ""))
    cfg = load_config(path)
    assert not cfg.simulation.samples_set and cfg.simulation.choose_first_batch
    assert cfg.simulation.samples == 1024
    assert apply_overrides(cfg, samples=64).simulation.samples_set
    assert not apply_overrides(cfg, seed=4).simulation.samples_set
    assert not apply_overrides(cfg, rel_error=0.02).simulation.samples_set
    path.write_text(body.replace("{extra}", "samples = 64\n"))
    cfg = load_config(path)
    assert cfg.simulation.samples_set and not cfg.simulation.choose_first_batch
    path.write_text(body.replace("{extra}", "").replace("rel_error = 0.01\n", ""))
    assert not load_config(path).simulation.choose_first_batch  # fixed budget: nothing to choose
