"""Glare sources and a view's figures from pixel statistics (simulator.glare.sources, .evaluate), no tracing.

Maps here are built by hand on the view's half lat-long layout (simulator.glare.view): a disc of known
luminance over a uniform background, noise of known variance. Expected values are the formulas
(docs/REFERENCES.md §Glare indices), evaluated on the same pixels.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.glare import indices as ix
from simulator.glare import view as V
from simulator.glare.evaluate import PixelStats, SunReading, evaluate
from simulator.glare.sources import GlareSettings, find_sources, parse_evalglare_options

VIEW = np.array([0.0, 1.0, 0.0])
UP = np.array([0.0, 0.0, 1.0])
FRAME = V.view_frame(VIEW, UP)


def _map(w=96, h=96):
    omega = V.pixel_solid_angles(w, h).reshape(-1)
    dirs = V.pixel_centre_directions(w, h, FRAME).reshape(-1, 3)
    return omega, dirs


def _stats(lum: np.ndarray, dirs: np.ndarray, lum_var=None) -> PixelStats:
    """Pixel statistics of a map whose luminance is ``lum`` (cd/m², both channels alike); E_v's integrand
    at each pixel's centre cosine."""
    l2 = np.repeat(lum[:, None], 2, axis=1)
    var = np.zeros_like(l2) if lum_var is None else np.repeat(lum_var[:, None], 2, axis=1)
    cos = np.clip(dirs @ VIEW, 0, 1)[:, None]
    return PixelStats(lum=l2, lum_var=var, ev=l2 * cos, ev_var=var * cos**2, count=np.full(len(lum), 16))


def test_pixel_layout_tiles_the_front_hemisphere():
    """The half map's pixels sum to 2π sr, every centre lies in front of the eye, and a direction falls in
    the pixel whose centre it is."""
    for w, h in [(96, 96), (7, 5)]:
        omega, dirs = _map(w, h)
        assert omega.sum() == pytest.approx(2 * math.pi, rel=1e-12)
        assert np.all(dirs @ VIEW > 0)
        row, col, front = V.pixel_of_directions(dirs, w, h, FRAME)
        assert np.all(front) and np.array_equal(row * w + col, np.arange(w * h))


def test_fisheye_solid_angles_sum_to_the_hemisphere():
    """An angular fisheye's pixels inside the circle cover 2π sr (the Jacobian sin ρ/ρ·(π/2)², midpoint rule)."""
    assert V.fisheye_solid_angles(200).sum() == pytest.approx(2 * math.pi, rel=2e-4)


def test_a_uniform_disc_over_a_dim_background_gives_the_formulas():
    """A disc of 30° radius, 5000 cd/m², 40° above the line of sight, over a 100 cd/m² background: one source
    of the disc's pixels; E_v = Σ ω·L·cos; DGP = c1·E_v + c2·log10(1 + L²ω/(E_v^1.87·P²)) + c3 and
    UGR = 8·log10(0.25/L_b·L²ω/P²) with L_b = (E_v − E_dir)/π = the background's, P Guth's at the
    disc's centre (its luminance-weighted mean direction)."""
    omega, dirs = _map()
    centre = math.cos(math.radians(40)) * VIEW + math.sin(math.radians(40)) * UP
    disc = dirs @ centre >= math.cos(math.radians(30))
    lum = np.where(disc, 5000.0, 100.0)
    est = evaluate(_stats(lum, dirs), omega, dirs, FRAME, [], np.zeros(2), GlareSettings(), (96, 96))
    assert len(est.sources) == 1
    s = est.sources[0]
    w = omega[disc].sum()
    assert s.omega_sr == pytest.approx(w, rel=1e-12) and s.luminance_cd_m2 == pytest.approx(5000.0, rel=1e-12)
    c = (omega[disc][:, None] * dirs[disc]).sum(axis=0)
    p = float(ix.position_index(c / np.linalg.norm(c), VIEW, UP))
    ev = float((omega * lum * np.clip(dirs @ VIEW, 0, 1)).sum())
    e_dir = float((omega * lum * np.clip(dirs @ VIEW, 0, 1))[disc].sum())
    g = 5000.0**2 * w / p**2
    assert est.ev_lx == pytest.approx(ev, rel=1e-12)
    assert est.dgp == pytest.approx(5.87e-5 * ev + 0.092 * math.log10(1 + g / ev**1.87) + 0.159, rel=1e-12)
    assert est.ugr == pytest.approx(8 * math.log10(0.25 / ((ev - e_dir) / math.pi) * g), rel=1e-12)
    assert est.background_cd_m2 == pytest.approx((ev - e_dir) / math.pi, rel=1e-12)
    assert est.dgp_stderr == 0.0 and est.ugr_stderr == 0.0


def test_a_sun_disk_is_a_source_of_its_own():
    """A sun disk of luminance L (read at its centre) in front of a 3000 cd/m² window is a source of
    L²ω = Ω·L², split from the window by peak extraction; its E_v is π·sin²α·L·cos σ."""
    omega, dirs = _map()
    lum = np.where(dirs @ VIEW > math.cos(math.radians(50)), 3000.0, 50.0)
    s_dir = math.cos(math.radians(20)) * VIEW + math.sin(math.radians(20)) * UP
    big_omega, l_sun = 6.8e-5, 1.2e9
    sun = SunReading("/Sun", s_dir, big_omega, np.array([l_sun, l_sun]), np.zeros(2), np.array([l_sun**2] * 2), l_sun)
    est = evaluate(_stats(lum, dirs), omega, dirs, FRAME, [sun], np.zeros(2), GlareSettings(), (96, 96))
    suns = [s for s in est.sources if s.sun]
    assert len(suns) == 1 and len(est.sources) == 2
    own = l_sun
    cos_a = 1.0 - big_omega / (2 * math.pi)
    assert suns[0].l2w == pytest.approx(big_omega * own**2, rel=1e-9)
    assert suns[0].ev_lx == pytest.approx(math.pi * (1 - cos_a**2) * own * math.cos(math.radians(20)), rel=1e-9)
    off = GlareSettings(peak_extraction=False)  # evalglare -x: the sun joins the window and raises its mean
    est2 = evaluate(_stats(lum, dirs), omega, dirs, FRAME, [sun], np.zeros(2), off, (96, 96))
    assert len(est2.sources) == 1 and est2.sources[0].sun == "/Sun"


def test_unbiased_l2w_from_noisy_pixels():
    """A source of two adjacent pixels of 6000 cd/m² read with noise uniform in ±3000 cd/m² (variance
    3000²/3, known), on a dark 16 × 16 map (the noise never takes it under the source rules): over 5000
    independent maps the mean of the reported L²ω, (Ŝ² − V̂)/ω, is within 4 standard errors of the true
    L²ω, while Ŝ²/ω is biased up by V/ω (Var(Ŝ) = Σω²σ²), here about 7 standard errors."""
    rng = np.random.default_rng(7)
    omega, dirs = _map(16, 16)
    src = np.zeros(len(omega), bool)
    src[[16 * 5 + 7, 16 * 5 + 8]] = True
    w = omega[src].sum()
    half = 3000.0
    sd = half / math.sqrt(3.0)
    truth = 6000.0**2 * w
    est, naive = [], []
    settings = GlareSettings(threshold=150.0, search_radius=1.0)  # the noise keeps both above it; they merge
    var = np.where(src, sd**2, 0.0)
    for _ in range(5000):
        lum = np.where(src, 6000.0 + rng.uniform(-half, half, src.shape), 0.0)
        e = evaluate(_stats(lum, dirs, var), omega, dirs, FRAME, [], np.zeros(2), settings, (16, 16))
        (s,) = e.sources
        assert s.pixels == 2
        est.append(s.l2w)
        naive.append((s.luminance_cd_m2 * s.omega_sr) ** 2 / s.omega_sr)
    est, naive = np.array(est), np.array(naive)
    se = est.std(ddof=1) / math.sqrt(len(est))
    assert abs(est.mean() - truth) < 4 * se
    bias = float((omega[src] ** 2 * sd**2).sum()) / w
    assert naive.mean() - truth > 4 * se and naive.mean() - truth == pytest.approx(bias, rel=0.3)


def test_merging_angle_and_peak_extraction():
    """Pixels merge within search_radius/2 (evalglare compares twice the angle with -r): two 2°-wide patches
    8° apart are two sources at -r 0.2 (5.7°) and one at -r 0.4 (11.5°); a patch's pixels at or above
    50,000 cd/m² become a source of their own."""
    omega, dirs = _map(180, 180)

    def patch(deg):
        c = math.cos(math.radians(deg)) * VIEW + math.sin(math.radians(deg)) * np.cross(VIEW, UP)
        return dirs @ c >= math.cos(math.radians(1.0))

    lum = np.where(patch(-4) | patch(4), 5000.0, 10.0)
    assert len(find_sources(dirs, omega, lum, VIEW, UP, GlareSettings())) == 2
    assert len(find_sources(dirs, omega, lum, VIEW, UP, GlareSettings(search_radius=0.4))) == 1
    lum2 = np.where(patch(4), 80000.0, lum)
    src = find_sources(dirs, omega, lum2, VIEW, UP, GlareSettings(search_radius=0.4))
    assert len(src) == 2 and sorted(src.peaks.tolist()) == [False, True]
    assert len(find_sources(dirs, omega, lum2, VIEW, UP, GlareSettings(search_radius=0.4, peak_extraction=False))) == 1


def test_relative_threshold_multiplies_the_mean_or_the_task():
    """A threshold ≤ 100 is a multiple of the view's mean luminance Σω·L/Σω, or of the task zone's."""
    omega, dirs = _map(48, 48)
    lum = np.where(dirs @ UP > 0.5, 1000.0, 100.0)
    mean = float((omega * lum).sum() / omega.sum())
    src = find_sources(dirs, omega, lum, VIEW, UP, GlareSettings(threshold=5.0))
    assert src.threshold_cd_m2 == pytest.approx(5.0 * mean, rel=1e-12)
    task = GlareSettings(threshold=2.0, task_direction=VIEW, task_angle_deg=20.0)
    src = find_sources(dirs, omega, lum, VIEW, UP, task)
    assert src.task_cd_m2 == pytest.approx(100.0) and src.threshold_cd_m2 == pytest.approx(200.0)
    assert len(src) == 1


def test_evalglare_options():
    """The source options of an evalglare command line; any other option is refused by name."""
    assert parse_evalglare_options("-b 5 -r 0.3 -x -C l+") == {"threshold": 5.0, "search_radius": 0.3,
                                                              "peak_extraction": False, "low_light": True}  # fmt: skip
    assert parse_evalglare_options("-Y 30000") == {"peak_extraction": True, "peak_cd_m2": 30000.0}
    t = parse_evalglare_options("-b 5 -t 0 2 0 30")
    assert t["threshold"] == 5.0 and np.allclose(t["task_direction"], [0, 1, 0]) and t["task_angle_deg"] == 30.0
    assert GlareSettings(**t).evalglare_options() == "-b 5 -r 0.2 -Y 50000 -t 0 1 0 30"
    for bad, word in [("-d", "'-d'"), ("-b", "-b needs"), ("-b x", "number"), ("-C q", "-C"), ("-t 0 0 0 10", "zero length"),
                      ("-t 1 0 0", "-t needs")]:
        with pytest.raises(ValueError, match=word):
            parse_evalglare_options(bad)
    assert GlareSettings().evalglare_options() == "-b 2000 -r 0.2 -Y 50000"
