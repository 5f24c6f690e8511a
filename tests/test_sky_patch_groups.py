"""A dome split into Tregenza's 145 sky patches (and the ground) as light groups: daylight coefficients.

``LightGroups.patch_base`` gives the dome 146 groups; each emitted-light
contribution of the dome goes to the group of the patch its direction points
into (``light_contribution_dir`` in the estimator kernel), and the
covariance between the 146 coefficients comes from batch means
(:class:`simulator.engine.stats.GroupBatchStats`). Checked against closed
forms (an unobstructed horizontal receiver), the plain dome run (a uniform
sky recombined), the exact per-sample co-moment (few groups, both ways),
and independent replicas (the recombined variance dᵀCd of CIE skies).
"""

import math
from dataclasses import replace

import numpy as np
from scipy import stats

from simulator.engine.driver import Engine, LightGroups
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor, SensorKind
from simulator.study.inputs import sky_patches as sp

L_LM = 400.0  # the dome's authored luminance, cd/m²


def _open_sky():
    dome = Light("/Sky", LightKind.DOME, np.zeros(3), np.eye(3), (2.0, L_LM))
    scene = Scene(geometry=Geometry(), lights=[dome], sensors=[], path="<test>")
    return scene, [Sensor("up", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))]


def _split(n_lights_before=0, n_after=0, base=0):
    lg = np.array([-1] * n_lights_before + [base + 145] + [-1] * n_after)
    pb = np.array([-1] * n_lights_before + [base] + [-1] * n_after)
    return lg, pb


def _office():
    from simulator.scene.usd import load_stage

    return load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")


def _office_sky_and_sensors():
    scene = _office()
    sky = [l for l in scene.lights if l.kind == LightKind.DOME]
    scene = replace(scene, lights=sky)
    pts = [(1.0, 1.0, 0.8), (2.5, 2.0, 0.8), (4.5, 3.0, 0.8)]
    sensors = [Sensor(f"wp{i}", SensorKind.IRRADIANCE, np.array(p), np.array([0.0, 0.0, 1.0])) for i, p in enumerate(pts)]
    return scene, sensors


def test_open_sky_patch_coefficients_are_the_closed_form():
    """An unobstructed horizontal receiver under a dome of luminance L: patch p's coefficient is
    E_p = L·∫_p cosθ dω = L·(π/n)(sin²a₁ − sin²a₀) (docs/REFERENCES.md §Tregenza sky patches); with
    cosine-weighted sampling (method light, 16384 samples) each sample's light lands in one patch;
    the 145 z-scores (estimate − E_p)/σ_p are checked as a χ²(145) sum below its 1e-4 upper quantile
    (a missing or misplaced patch would give a z of tens), the ground slot reads 0 (no direction
    below the horizon), and the coefficients sum to the total π·L, which this sampler reads exactly
    (its estimator is constant unoccluded), to float32 rounding (1e-6)."""
    scene, sensors = _open_sky()
    lg, pb = _split()
    r = Engine(scene, sensors, device="cpu", threads=1).run_groups("light", LightGroups(lg, 146, patch_base=pb), samples=16384, seed=3)
    proj = np.array([sp.patch_projected_solid_angle(p) for p in range(145)])
    gm = r.group_mean[:, 0, 1]
    se = np.sqrt(np.diagonal(r.group_cov[0, 1]))
    z = (gm[:145] - L_LM * proj) / se[:145]
    assert float(np.sum(z**2)) < stats.chi2.ppf(1 - 1e-4, 145)
    assert gm[145] == 0.0
    assert abs(gm.sum() / (math.pi * L_LM) - 1.0) < 1e-6
    assert abs(r.mean[0, 1] / (math.pi * L_LM) - 1.0) < 1e-6


def test_one_patch_lit_matches_its_closed_form_under_mis():
    """A sky with one patch lit (d = e_p) reads E = L·∫_p cosθ dω for an unobstructed horizontal
    receiver: the cap (p = 144, ∫cos = π(1 − sin²84°) = 0.0344 sr) and a horizon patch (p = 0,
    0.00453 sr), under MIS (two strategies, each sample's light in several patches), within 4σ."""
    scene, sensors = _open_sky()
    lg, pb = _split()
    r = Engine(scene, sensors, device="cpu", threads=1).run_groups("mis", LightGroups(lg, 146, patch_base=pb), samples=8192, seed=11)
    for p in (144, 0):
        d = np.zeros(146)
        d[p] = 1.0
        e = float(d @ r.group_mean[:, 0, 1])
        s = math.sqrt(float(d @ r.group_cov[0, 1] @ d))
        truth = L_LM * sp.patch_projected_solid_angle(p)
        assert abs(e - truth) <= 4 * s, (p, e, truth, s)


def test_uniform_sky_recombined_equals_the_plain_dome_run():
    """In the office (the sky through the window, interreflected: path tracing) the uniform sky,
    d = 1 on every patch and the ground, recombined from the 146 coefficients equals the pass's
    own total to float32 rounding (1e-5; the same samples) and an independent plain run of the dome
    (another seed) within 4σ of the difference, σ² = dᵀCd + σ²_run. (The ground slot is not 0 here:
    the stage's outdoor ground ends 30 m out, and grazing directions below the horizon pass it.)"""
    scene, sensors = _office_sky_and_sensors()
    lg, pb = _split()
    eng = Engine(scene, sensors)
    r = eng.run_groups("path", LightGroups(lg, 146, patch_base=pb), samples=1024, seed=21)
    plain = eng.run("path", samples=1024, seed=22)
    d = np.ones(146)
    e = np.einsum("g,gsc->sc", d, r.group_mean)
    var = np.einsum("g,scgh,h->sc", d, r.group_cov, d)
    assert np.all(np.abs(e - r.mean) <= 1e-5 * np.abs(r.mean))
    assert np.all(np.abs(e - plain.mean) <= 4 * np.sqrt(var + plain.stderr**2)), (e, plain.mean)


def test_batch_means_agree_with_the_exact_co_moment():
    """Few groups (the office's window row, corridor row, sky and sun), traced once with per-sample
    cross products and once with batch means (``batch=True``), the same samples: the means are
    equal (1e-9 relative; only summation order differs), and for each recombination d the ratio
    dᵀC_batch d / dᵀC_exact d, a batch-means variance with B − 1 = 127 degrees of freedom (4096
    samples in blocks of 32) over a near-exact one, lies inside the χ²(127)/127 1e-4 quantiles
    [0.63, 1.50]."""
    scene = _office()
    key = {"WindowRow": 0, "CorridorRow": 1, "Sky": 2, "Sun": 3}
    groups = np.array([next(v for k, v in key.items() if k in l.name) for l in scene.lights])
    _, sensors = _office_sky_and_sensors()
    eng = Engine(scene, sensors)
    exact = eng.run_groups("path", LightGroups(groups, 4), samples=4096, seed=5)
    batch = eng.run_groups("path", LightGroups(groups, 4, batch=True), samples=4096, seed=5)
    assert np.allclose(batch.group_mean, exact.group_mean, rtol=1e-9, atol=0)
    lo, hi = stats.chi2.ppf([1e-4, 1 - 1e-4], 127) / 127
    for d in (np.ones(4), np.array([1.0, 0.0, -1.0, 0.5]), np.array([0.0, 0.0, 1.0, 1.0])):
        q = np.einsum("g,scgh,h->sc", d, batch.group_cov, d) / np.einsum("g,scgh,h->sc", d, exact.group_cov, d)
        assert np.all((q > lo) & (q < hi)), (d, q)


def test_replicas_scatter_as_the_recombined_covariance():
    """R = 30 independent passes (seeds 300…329) of the office's split sky, 512 samples each: for the
    CIE overcast sky, the CIE clear sky (type 12, sun at azimuth 250°, elevation 30°: it shines in
    through the west window) and one bright patch minus the uniform sky (a contrast, negative weights),
    Σ_r (dᵀÊ_r − dᵀĒ)² / dᵀC̄d, C̄ the mean reported (batch-means) covariance, is χ²(R − 1) if the
    covariance is right: inside its two-sided 1e-4 quantiles for each sensor, channel and sky (18
    tests)."""
    scene, sensors = _office_sky_and_sensors()
    lg, pb = _split()
    eng = Engine(scene, sensors)
    reps = [eng.run_groups("path", LightGroups(lg, 146, patch_base=pb), samples=512, seed=300 + k) for k in range(30)]
    m = np.stack([r.group_mean for r in reps])
    c_bar = np.mean([r.group_cov for r in reps], axis=0)
    a, h = math.radians(250.0), math.radians(30.0)
    sun = np.array([math.sin(a) * math.cos(h), math.cos(a) * math.cos(h), math.sin(h)])
    contrast = -np.ones(146)
    contrast[int(sp.patch_index(sun))] += 20.0
    skies = [np.r_[sp.sky_weights("overcast", None), 0.0], np.r_[sp.sky_weights(12, sun), 0.0], contrast]
    lo, hi = stats.chi2.ppf([5e-5, 1 - 5e-5], len(reps) - 1)
    for d in skies:
        x = np.einsum("g,rgsc->rsc", d, m)
        ss = ((x - x.mean(axis=0)) ** 2).sum(axis=0)
        q = ss / np.einsum("g,scgh,h->sc", d, c_bar, d)
        assert np.all((q > lo) & (q < hi)), (q, lo, hi)


def test_a_small_budget_is_cut_into_batches_whose_covariance_is_right():
    """16 samples per sensor (fewer than two blocks of 32): the run draws them in 8 batches of 2 (the
    same samples), so every recombined reading has a finite standard error where one block left the
    whole covariance infinite (a study's every error NaN). R = 30 replicas (seeds 400…429): for the CIE
    overcast and clear skies Σ_r (dᵀÊ_r − dᵀĒ)² / dᵀC̄d is χ²(R − 1) if the 7-degree-of-freedom
    batch-means covariance is unbiased: inside its two-sided 1e-4 quantiles for each sensor and
    channel (12 tests)."""
    scene, sensors = _office_sky_and_sensors()
    lg, pb = _split()
    eng = Engine(scene, sensors)
    reps = [eng.run_groups("path", LightGroups(lg, 146, patch_base=pb), samples=16, seed=400 + k) for k in range(30)]
    assert all(np.isfinite(r.group_cov).all() for r in reps)
    m = np.stack([r.group_mean for r in reps])
    c_bar = np.mean([r.group_cov for r in reps], axis=0)
    a, h = math.radians(250.0), math.radians(30.0)
    sun = np.array([math.sin(a) * math.cos(h), math.cos(a) * math.cos(h), math.sin(h)])
    lo, hi = stats.chi2.ppf([5e-5, 1 - 5e-5], len(reps) - 1)
    for d in (np.r_[sp.sky_weights("overcast", None), 0.0], np.r_[sp.sky_weights(12, sun), 0.0]):
        x = np.einsum("g,rgsc->rsc", d, m)
        ss = ((x - x.mean(axis=0)) ** 2).sum(axis=0)
        q = ss / np.einsum("g,scgh,h->sc", d, c_bar, d)
        assert np.all((q > lo) & (q < hi)), (q, lo, hi)


def test_an_unlit_group_of_unknown_error_adds_nothing_and_unknown_stays_infinite():
    """A group whose covariance is unknown (inf: one batch) adds nothing to a recombination that
    leaves it unlit (its weight 0 times inf is 0, not NaN): d = (2, 1, 0) reads 2·2 + 3 = 7 with the lit
    groups' own variance dᵀCd = 2²·1 + 2·2·1·(−0.25) + 1²·0.5 = 3.5. Lit, the error is inf, never NaN;
    both in the engine's stopping rule (``_recombined``) and in a study's recombination
    (``GroupReadings.combine``)."""
    from simulator.engine.driver import _recombined
    from simulator.study.trace.groups import GroupReadings

    cov = np.array([[1.0, -0.25, np.inf], [-0.25, 0.5, np.inf], [np.inf, np.inf, np.inf]])[None, None]  # (S, C, G, G)
    mean = np.array([[[2.0, 3.0, 5.0]]])  # (S, C, G)
    levels = np.array([[2.0, 1.0, 0.0], [1.0, 0.0, 1.0]])
    val, se = _recombined(mean, cov, levels)
    want = 2.0**2 * 1.0 + 2 * 2.0 * 1.0 * (-0.25) + 1.0**2 * 0.5  # dᵀCd over the lit groups 0 and 1
    assert abs(val[0, 0] - 7.0) <= 1e-12 and abs(se[0, 0] - math.sqrt(want)) <= 1e-12 * math.sqrt(want)
    assert np.isinf(se[0, 1])
    gr = GroupReadings(["a", "b", "c"], np.transpose(mean, (2, 0, 1)), np.sqrt(np.abs(np.diagonal(cov, axis1=2, axis2=3))).transpose(2, 0, 1),
                       cov, np.full((3, 1), 16), np.zeros(3))  # fmt: skip
    m, e = gr.combine({"a": 2.0, "b": 1.0})
    assert abs(m[0, 0] - 7.0) <= 1e-12 and abs(e[0, 0] - math.sqrt(want)) <= 1e-12 * math.sqrt(want)
    m, e = gr.combine({"a": 1.0, "c": 1.0})
    assert np.isinf(e[0, 0])


def test_kernel_patch_index_is_the_python_twin():
    """``tregenza_patch`` (the kernels') and :func:`sky_patches.patch_index` give the same patch for
    20000 random directions over the whole sphere (below the horizon: 145 in both), except within
    1e-4 rad of a patch boundary, where float32 and float64 rounding may disagree (none expected
    to be that close among these; the test counts them and requires at most 0.1%)."""
    import warp as wp

    from simulator.engine.driver import load_kernels
    from simulator.kernels.group_tally import tregenza_patch

    load_kernels("cpu")

    @wp.kernel
    def k_patch(d: wp.array(dtype=wp.vec3), out: wp.array(dtype=wp.int32)):
        i = wp.tid()
        out[i] = tregenza_patch(d[i])

    rng = np.random.default_rng(9)
    v = rng.normal(size=(20000, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    out = wp.empty(len(v), dtype=wp.int32, device="cpu")
    wp.launch(k_patch, dim=len(v), inputs=[wp.array(v.astype(np.float32), dtype=wp.vec3, device="cpu")], outputs=[out], device="cpu")
    got = out.numpy()
    want = sp.patch_index(v.astype(np.float32).astype(np.float64))
    assert np.mean(got != want) <= 1e-3, np.flatnonzero(got != want)[:10]
    assert set(np.unique(got[v[:, 2] <= 0])) == {145} and len(np.unique(got[v[:, 2] > 0])) == 145
