"""One-pass light-group tallies: the groups sum to the total, and the reported covariance is right.

Each sample's light is tallied per group on the paths the total is traced on
(``Engine.run_groups``). Checked here on the office stage (interreflection,
path tracing): the sum of the group means against the same pass's total; two
groups that are one point light split in two (identical per sample:
correlation 1); and independent replicas with different seeds, whose scatter
must follow the reported covariance (a chi-square test on dᵀ(Ê − Ē)).
"""

from dataclasses import replace

import numpy as np
from scipy import stats

from simulator.engine.driver import Engine, LightGroups
from simulator.scene.model import Light, LightKind, Sensor, SensorKind


def _office():
    from simulator.scene.usd import load_stage

    return load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")


def _sensors():
    pts = [(1.0, 1.0, 0.8), (2.5, 2.0, 0.8), (4.5, 3.0, 0.8)]
    out = [Sensor(f"wp{i}", SensorKind.IRRADIANCE, np.array(p), np.array([0.0, 0.0, 1.0])) for i, p in enumerate(pts)]
    out.append(Sensor("cell", SensorKind.RADIANCE, np.array([3.0, 2.0, 2.98]), np.array([0.0, 0.0, -1.0]), half_angle=np.radians(30)))
    return out


def _group_of(scene):
    """window row 0, corridor row 1, sky 2, sun 3."""
    key = {"WindowRow": 0, "CorridorRow": 1, "Sky": 2, "Sun": 3}
    return np.array([next(v for k, v in key.items() if k in l.name) for l in scene.lights])


def test_group_tallies_sum_to_the_total_of_the_same_pass():
    """Σ_g Ê_g equals the pass's total Ê (the same samples, each light's share added to
    the total and to its group): equal up to float32 rounding of the per-sample sums,
    |Σ_g Ê_g − Ê| ≤ 1e-5·|Ê|; the total's variance equals Σ_gh C_gh to 1e-6; and the total
    matches an ordinary run with the same seed (tallies change no sample) to 1e-12."""
    scene = _office()
    sensors = _sensors()
    eng = Engine(scene, sensors)
    eng.split_indirect = 1  # one path a sample in the ordinary run too, as a group pass draws them
    r = eng.run_groups("path", LightGroups(_group_of(scene), 4), samples=512, seed=5)
    plain = eng.run("path", samples=512, seed=5)
    assert r.group_mean.shape == (4, len(sensors), 2) and r.group_cov.shape == (len(sensors), 2, 4, 4)
    assert np.all(np.abs(r.group_mean.sum(axis=0) - r.mean) <= 1e-5 * np.abs(r.mean))
    assert np.allclose(r.group_cov.sum(axis=(2, 3)), r.stderr**2, rtol=1e-6, atol=0)
    assert np.allclose(r.mean, plain.mean, rtol=1e-12, atol=0) and np.allclose(r.stderr, plain.stderr, rtol=1e-12, atol=0)
    assert np.all(r.group_mean[:, :3] > 0)  # every group lights the work plane (the sun through the window, by reflection)


def test_one_light_split_in_two_groups_is_perfectly_correlated():
    """A point light of intensity I as two coincident lights of I/2 in two groups: every
    sample gives both groups the same light (the same shadow rays, the same path), so the
    reported correlation is 1 (within 1e-9) and the difference d = (1, −1) has variance 0
    (≤ 1e-9 of the sum's), while the sum has the path's real variance."""
    scene = _office()
    sensors = _sensors()
    lamp = Light("/A", LightKind.POINT, np.array([3.0, 2.0, 2.5]), np.eye(3), (50.0, 50.0 * 683.0))
    sc = replace(scene, lights=[lamp, replace(lamp, name="/B")])
    r = Engine(sc, sensors).run_groups("path", LightGroups(np.array([0, 1]), 2), samples=512, seed=2)
    c = r.group_cov
    corr = c[..., 0, 1] / np.sqrt(c[..., 0, 0] * c[..., 1, 1])
    assert np.all(c[..., 0, 0] > 0)
    assert np.all(np.abs(corr - 1.0) <= 1e-9), corr
    d = np.array([1.0, -1.0])
    s = np.array([1.0, 1.0])
    assert np.all(np.einsum("g,scgh,h->sc", d, c, d) <= 1e-9 * np.einsum("g,scgh,h->sc", s, c, s))


def test_replicas_scatter_as_the_reported_covariance():
    """R = 40 independent passes (seeds 100…139), 256 samples each: for fixed dimming
    vectors d (one with a negative weight, so the covariance terms matter) the statistic
    Σ_r (dᵀÊ_r − dᵀĒ)² / dᵀC̄d, C̄ the mean reported covariance, is χ²(R − 1) if the
    covariance is right; each sensor, channel and d must lie inside the two-sided
    1e-4 quantiles (60 tests: a 0.6% chance of a false alarm). Groups: two point lamps
    0.4 m apart (their interreflected light is strongly correlated), the window row and
    the sky; ignoring the covariance between groups (diagonal C) puts the lamps'
    contrast d = (1, −1, 0, 0) outside, so the test can tell."""
    scene = _office()
    sensors = _sensors()
    lamp = Light("/A", LightKind.POINT, np.array([2.0, 2.0, 2.5]), np.eye(3), (50.0, 50.0 * 683.0))
    rows = [l for l in scene.lights if "WindowRow" in l.name]
    sky = [l for l in scene.lights if "Sky" in l.name]
    scene = replace(scene, lights=[lamp, replace(lamp, name="/B", position=np.array([2.4, 2.0, 2.5]))] + rows + sky)
    groups = np.array([0, 1] + [2] * len(rows) + [3])
    eng = Engine(scene, sensors)
    reps = [eng.run_groups("path", LightGroups(groups, 4), samples=256, seed=100 + k) for k in range(40)]
    m = np.stack([r.group_mean for r in reps])  # (R, G, S, 2)
    c_bar = np.mean([r.group_cov for r in reps], axis=0)  # (S, 2, G, G)
    ds = [np.array([1.0, 1.0, 1.0, 1.0]), np.array([1.0, 0.0, -1.0, 0.0]), np.array([0.5, 1.0, 0.0, 0.3]),
          np.array([0.0, 0.0, 1.0, -1.0]), np.array([1.0, -1.0, 0.0, 0.0])]  # fmt: skip
    n_r = len(reps)
    lo, hi = stats.chi2.ppf([5e-5, 1 - 5e-5], n_r - 1)
    worst_diag = 0.0
    for d in ds:
        x = np.einsum("g,rgsc->rsc", d, m)
        ss = ((x - x.mean(axis=0)) ** 2).sum(axis=0)
        var = np.einsum("g,scgh,h->sc", d, c_bar, d)
        q = ss / var
        assert np.all((q > lo) & (q < hi)), (d, q, lo, hi)
        var_diag = np.einsum("g,scgg,g->sc", d, c_bar, d)
        worst_diag = max(worst_diag, float(np.max(np.maximum(ss / var_diag / hi, lo / (ss / var_diag)))))
    assert worst_diag > 1.0  # the diagonal-only covariance fails somewhere: the test can tell


def test_a_batch_too_big_for_one_launch_is_split_without_changing_it(monkeypatch):
    """With the group state capped (``GROUP_STATE_BYTES``: room for 2 kernel threads) each
    batch is drawn in several launches; the samples are the same (one random stream per
    sample), so the group means agree with one launch's to 1e-9 relative and the
    covariance to 1e-6 (only the blocks' float64 shifts differ)."""
    import simulator.engine.driver as D

    scene = _office()
    sensors = _sensors()[:2]
    lg = LightGroups(_group_of(scene), 4)
    eng = Engine(scene, sensors)
    one = eng.run_groups("path", lg, samples=200, seed=8)
    monkeypatch.setattr(D, "GROUP_STATE_BYTES", 2 * 16 * 4 * 7)
    assert len(D._split_batch(np.arange(2), np.zeros(2), np.full(2, 200), 2 * D.BLOCK)) > 2
    split = eng.run_groups("path", lg, samples=200, seed=8)
    assert np.array_equal(split.samples, one.samples)
    assert np.allclose(split.group_mean, one.group_mean, rtol=1e-9, atol=0)
    assert np.allclose(split.group_cov, one.group_cov, rtol=1e-6, atol=1e-12 * np.abs(one.group_cov).max())
