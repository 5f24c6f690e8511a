"""The estimator family: analytic closed forms, the Monte Carlo methods that
must agree with them, what each is blind to, and adaptive stopping with
honest error bars."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.stats import binom

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.plan.planner import analytic_refusal, make_plan
from simulator.pipeline import collect_sensors, load_scene
from simulator.scene.model import SensorKind

from test_direct_light import FLOAT32_SLACK, expected

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


def _load(stage):
    cfg = load_config(CONFIGS / f"{stage}.toml")
    scene = load_scene(cfg)
    return cfg, scene, collect_sensors(cfg, scene)


@pytest.mark.parametrize("stage", ["point", "sphere", "rect", "disk", "dome"])
def test_analytic_matches_numpy_closed_forms(stage):
    """The Warp closed forms (Lambert's contour formula, the straddling-sphere
    formula, the disk contour integral, I·Ω/A for patches) agree with the
    independent numpy ones to float32 precision (2e-6 relative; the disk's
    256-node trapezoid rule is far more accurate than that here)."""
    _, scene, sensors = _load(stage)
    sensors = [s for s in sensors if analytic_refusal(scene, s) is None]
    assert sensors, "each closed-form stage has at least one analytic sensor"
    res = Engine(scene, sensors).run("analytic", samples=1, seed=1)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            truth = expected(stage, scene, s, ch)
            assert res.mean[i, ch] == pytest.approx(truth, rel=FLOAT32_SLACK, abs=1e-12), s.name
        assert res.stderr[i, 0] == 0.0 and res.samples[i] == 0


@pytest.mark.parametrize("method", ["light", "bsdf", "mis", "path"])
@pytest.mark.parametrize("stage", ["sphere", "rect", "disk", "dome"])
def test_every_method_agrees_with_analytic(stage, method):
    """Where both apply, every Monte Carlo method's reading is within 4
    standard errors of the closed form (fixed seed)."""
    _, scene, sensors = _load(stage)
    sensors = [s for s in sensors if analytic_refusal(scene, s) is None]
    eng = Engine(scene, sensors)
    exact = eng.run("analytic", samples=1, seed=1).mean
    res = eng.run(method, samples=1 << 14, seed=11)
    bound = 4 * res.stderr + FLOAT32_SLACK * np.abs(exact) + 1e-12
    assert np.all(np.abs(res.mean - exact) <= bound), (res.mean, exact, res.stderr)


@pytest.mark.parametrize("stage", ["point", "distant_occluder"])
def test_bsdf_is_blind_to_delta_lights(stage):
    """A point light and an angle-0 distant light occupy zero solid angle:
    no cosine-sampled direction ever hits them, so `bsdf` reads exactly 0
    (where `light` reads the closed form) and the run says so in a warning."""
    _, scene, sensors = _load(stage)
    sensors = [s for s in sensors if s.kind == SensorKind.IRRADIANCE]
    eng = Engine(scene, sensors)
    blind = eng.run("bsdf", samples=256, seed=1)
    seeing = eng.run("light", samples=256, seed=1)
    assert np.all(blind.mean == 0.0)
    assert np.any(seeing.mean > 0.0)
    assert any("cannot see point" in w for w in blind.warnings)


def test_analytic_refuses_where_an_occluder_could_block():
    """Under the occluder of distant_occluder.usda the closed form would read
    the unshadowed 1000 lx; the planner refuses it instead of a wrong number."""
    _, scene, sensors = _load("distant_occluder")
    assert all("may block" in analytic_refusal(scene, s) for s in sensors)
    with pytest.raises(UserError, match="method analytic cannot read sensor 'shadow'.*Occluder may block"):
        make_plan(scene, sensors, "analytic")


def test_analytic_refuses_radiance_meters():
    _, scene, sensors = _load("rect")
    meter = next(s for s in sensors if s.kind == SensorKind.RADIANCE)
    assert "radiance" in analytic_refusal(scene, meter)


def test_adaptive_stops_each_sensor_at_its_target():
    """With rel_error = 1%, every sensor stops once its 95% half-width is under
    1% of its reading, and an easy sensor stops with fewer samples than a hard
    one (near field of the rect light vs. far below it)."""
    _, scene, sensors = _load("rect")
    sensors = [s for s in sensors if s.name in ("centre", "near_field")]
    res = Engine(scene, sensors).run("light", samples=256, seed=5, rel_error=0.01, max_samples=1 << 22)
    assert res.target_met.all()
    assert np.all(1.959964 * res.stderr <= 0.01 * np.abs(res.mean))
    centre, near = res.samples
    assert centre < near


def test_adaptive_stops_at_the_sample_cap_and_says_so():
    _, scene, sensors = _load("rect")
    res = Engine(scene, sensors[:1]).run("bsdf", samples=64, seed=5, rel_error=1e-4, max_samples=2048)
    assert res.samples[0] == 2048 and not res.target_met[0]


def test_coverage_of_the_95_percent_interval():
    """200 seeds of one case with a known answer (bsdf sampling of the rect
    light's centre receiver, closed form 415.84 lx), each run adaptively to
    rel_error = 0.02. If the reported standard errors are honest, the 95%
    interval mean ± 1.96·stderr contains the truth in each run with
    probability ≈ 0.95, so the count of hits is Binomial(200, 0.95):
    P(count < 180) = 1.2e-3 and P(count > 198) = 4.0e-4, a false-alarm
    chance of 1.6e-3 for honest errors. The test asks for 90–99% (180–198
    hits), the band the issue states; optional stopping on the estimated
    error may lower the true coverage slightly, which this band would expose
    if it were large."""
    _, scene, sensors = _load("rect")
    sensor = [s for s in sensors if s.name == "centre"]
    eng = Engine(scene, sensor)
    truth = eng.run("analytic", samples=1, seed=0).mean[0, 1]
    hits = 0
    for seed in range(200):
        r = eng.run("bsdf", samples=1024, seed=1000 + seed, rel_error=0.02)
        assert r.target_met[0]
        hits += abs(r.mean[0, 1] - truth) <= 1.959964 * r.stderr[0, 1]
    assert binom.cdf(179, 200, 0.95) + binom.sf(198, 200, 0.95) < 2e-3  # the bound quoted above
    print(f"coverage: {hits}/200 intervals contain the truth")
    assert 180 <= hits <= 198, hits


def test_confidence_sets_the_stopping_interval():
    """confidence = 0.999 stops each sensor at 3.29 standard errors ≤ 1% of its
    reading (the two-sided 99.9% normal quantile), which takes about
    (3.29/1.96)² = 2.8× the samples of the default 95%."""
    from simulator.engine.stats import z_for_confidence

    assert z_for_confidence(0.95) == pytest.approx(1.959964, abs=1e-6)
    assert z_for_confidence(0.999) == pytest.approx(3.290527, abs=1e-6)
    _, scene, sensors = _load("rect")
    sensors = [s for s in sensors if s.name == "centre"]
    eng = Engine(scene, sensors)
    loose = eng.run("bsdf", samples=256, seed=8, rel_error=0.01)
    tight = eng.run("bsdf", samples=256, seed=8, rel_error=0.01, confidence=0.999)
    assert tight.target_met.all()
    assert np.all(3.290527 * tight.stderr <= 0.01 * np.abs(tight.mean))
    assert 2.0 < tight.samples[0] / loose.samples[0] < 4.0
