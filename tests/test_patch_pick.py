"""The light pick's factors per surface patch (paths, vertices past the first).

- ``patch_pick_factors``: a patch the pilot never reached keeps row 0's
  factor; one it reached V times gives (G + k·(E/V)·f0)/(E + k·(E/V)), k =
  PATCH_PICK_PRIOR_VISITS, which tends to G/E (shadowed value over
  estimate) as V grows.
- On the office the sun is a distant light of 0.53°: its estimate ê is its
  unoccluded irradiance (πL·sin²σ·cosθ of the cone's centre), so at a
  vertex its shadowed value over ê is its visible fraction, 1 in the sun
  and 0 in the shade (over the cone, cosθ departs from its centre's by
  at most sinσ·tanθ: 0.8% on the floor, θ = 60°; 2% allowed for steeper
  faces): on the patches the pilot visited 50 times or more, the sun's
  shadowed value over its estimate lies in [0, 1.02], some patches (the
  sunlit floor) are near 1 and many (the shaded floor, the walls in the
  sun's shadow) near 0.
- The factors are the same bytes at 1 and 2 CPU threads (the pilot's sums
  come from one worker).
- Readings stay unbiased: the office's 1,464 guided readings with the
  patch factors and without them, at independent seeds, agree:
  z = (a − b)/√(se_a² + se_b²) lies within ±1.96 for 95% of the sensors
  (binomial 4σ band [92.7%, 97.3%] as in tests/test_guide.py), and their
  grand totals within 4σ of each other.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from simulator.config.loader import load_config
from simulator.engine.driver import PATCH_PICK_PRIOR_VISITS, Engine, patch_pick_factors
from simulator.pipeline import collect_sensors, load_scene
from simulator.scene.model import SensorKind

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


def test_patch_factors_shrink_toward_row_0():
    row0 = np.array([0.5, 0.25])
    tally = np.zeros((3, 2, 3))
    tally[1, 0] = (2.0, 1.0, 4.0)  # E = 2 over 4 visits, G = 1
    tally[2, 1] = (1e6, 3e5, 1e6)  # many visits: G/E = 0.3
    f = patch_pick_factors(tally, row0)
    assert np.allclose(f[0], row0)  # never reached
    k = PATCH_PICK_PRIOR_VISITS
    assert np.isclose(f[1, 0], (1.0 + k * 0.5 * 0.5) / (2.0 + k * 0.5))
    assert np.isclose(f[1, 1], row0[1])  # this light's estimate never formed there
    assert abs(f[2, 1] - 0.3) < 1e-4


def _office():
    cfg = load_config(CONFIGS / "office_bench.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    return scene, sensors


def _patch_factors(eng: Engine) -> np.ndarray:
    rec = eng._dev.rec
    assert int(rec.n_patch_pick) == 1
    return rec.patch_pick_factor.numpy().reshape(eng._dev.layout.n_patches, int(rec.n_lights))


def test_the_suns_patch_factors_are_its_visible_fraction_and_thread_invariant():
    scene, sensors = _office()
    sun = [i for i, l in enumerate(scene.lights) if l.kind.name == "DISTANT"][0]
    factors = []
    for threads in (1, 2):
        eng = Engine(scene, sensors, threads=threads)
        eng.run("guided", samples=8, seed=3)
        factors.append(_patch_factors(eng))
    assert factors[0].tobytes() == factors[1].tobytes()
    tally_eng = Engine(scene, sensors, threads=1)
    f = factors[0][:, sun]
    # the pilot's own visits: its sums again (same seed, same bytes), read before they become factors
    dev = tally_eng._dev
    tally_eng._patch_pick_pilot("guided", 3, -1, "total", np.arange(len(sensors)))
    t = dev.read_patch_pick_tally()[:, sun]
    busy = (t[:, 2] >= 50) & (t[:, 0] > 0)
    assert busy.sum() >= 20
    ratio = t[busy, 1] / t[busy, 0]
    assert np.all(ratio <= 1.02) and np.all(ratio >= 0.0)
    assert ratio.max() > 0.9 and np.mean(ratio < 0.1) > 0.2
    assert np.all(np.isfinite(f)) and np.all(f >= 0.0)


def test_patch_factors_keep_the_office_unbiased(office_guided):
    """With the patch factors: tests/conftest.py's ``office_guided`` (512
    samples, seed 2024, the auto plan's light mask, which steers first
    vertices only; the patch factors steer the vertices past the first).
    Without them: 256 samples at seed 12, the same mask. The difference of
    two readings has a standard error of √(1/512 + 1/256) per-sample spreads,
    13% less than the √(2/256) of two runs of 256 (what this test read
    before), so a bias stands out at least as far as it did."""
    run = office_guided
    assert run.patch_pick == 1
    eng = Engine(run.scene, run.sensors)
    eng.patch_pick = False
    eng.set_light_mask(run.light_mask)
    b = eng.run("guided", samples=256, seed=12)
    assert int(eng._dev.rec.n_patch_pick) == 0
    a = run.result
    z = (a.mean[:, 1] - b.mean[:, 1]) / np.sqrt(a.stderr[:, 1] ** 2 + b.stderr[:, 1] ** 2)
    cover = float(np.mean(np.abs(z) < 1.96))
    assert 0.927 <= cover <= 0.973, cover
    tot = a.mean[:, 1].sum() - b.mean[:, 1].sum()
    assert abs(tot) <= 4.0 * np.sqrt((a.stderr[:, 1] ** 2).sum() + (b.stderr[:, 1] ** 2).sum())
