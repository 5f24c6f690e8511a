"""IES LM-63 and EULUMDAT readers and the goniometric distribution.

The files in tests/data/photometry are written by make_files.py there, from
analytic distributions, by the LM-63 grammar (IES LM-63-2019 §5; the 1986,
1995 and 2002 editions' version lines) and the EULUMDAT layout, so the exact
candelas are known at every measured angle.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.scene.photometry import GoniometricDistribution, parse_ies, read_photometry
from simulator.scene.photometry.distribution import angles_from_local

DATA = Path(__file__).parent / "data" / "photometry"
PRINT_REL = 5e-6


def cos_d(x):
    return np.cos(np.radians(x))


def sin_d(x):
    return np.sin(np.radians(x))


#: file → (analytic I(θ, φ) in cd, measured θ, measured φ over the full circle)
ANALYTIC = {
    "lambert_2002.ies": (lambda t, p: np.where(t <= 90, 1000 * cos_d(t), 0.0), np.arange(0, 91, 5.0), np.arange(0, 360, 45.0)),
    "isotropic_1995.ies": (lambda t, p: np.full(np.broadcast(t, p).shape, 100.0), np.arange(0, 181, 5.0), np.arange(0, 360, 45.0)),
    "quadrant_2019.ies": (lambda t, p: 500 * cos_d(t) * (1 + 0.5 * cos_d(2 * p)), np.arange(0, 91, 5.0), np.arange(0, 360, 15.0)),
    "bilateral_2002.ies": (lambda t, p: 400 * cos_d(t) * (1 + 0.5 * cos_d(p)), np.arange(0, 91, 5.0), np.arange(0, 360, 22.5)),
    "asymmetric_2002_crlf.ies": (
        lambda t, p: np.where(t <= 90, 300 * (1 + 0.5 * sin_d(p)) * cos_d(t), 100 * np.abs(cos_d(t))),
        np.arange(0, 181, 5.0),
        np.arange(0, 360, 30.0),
    ),
    "bilateral90_1986.ies": (lambda t, p: 200 * cos_d(t) * (1 + 0.5 * sin_d(p)), np.arange(0, 91, 5.0), np.arange(0, 360, 30.0)),
    "tilt_trivial.ies": (lambda t, p: np.where(t <= 90, 1000 * cos_d(t), 0.0), np.arange(0, 91, 5.0), np.arange(0, 360, 90.0)),
    "full_isym0.ldt": (lambda t, p: np.where(t <= 90, 300 * (1 + 0.5 * sin_d(p)) * cos_d(t), 0.0), np.arange(0, 181, 5.0), np.arange(0, 360, 15.0)),
    "rot_isym1.ldt": (lambda t, p: 500 * np.clip(cos_d(t), 0, None), np.arange(0, 181, 5.0), np.arange(0, 360, 30.0)),
    "c0c180_isym2.ldt": (
        lambda t, p: np.where(t <= 90, 300 * (1 + 0.25 * cos_d(2 * p) + 0.25 * cos_d(p)) * cos_d(t), 0.0),
        np.arange(0, 181, 5.0),
        np.arange(0, 360, 15.0),
    ),
    "c90c270_isym3.ldt": (lambda t, p: np.where(t <= 90, 300 * (1 + 0.5 * sin_d(p)) * cos_d(t), 0.0), np.arange(0, 181, 5.0), np.arange(0, 360, 15.0)),
    "quadrant_isym4.ldt": (lambda t, p: np.where(t <= 90, 300 * (1 + 0.5 * cos_d(2 * p)) * cos_d(t), 0.0), np.arange(0, 181, 5.0), np.arange(0, 360, 15.0)),
    "absolute_isym1.ldt": (lambda t, p: 400 * np.clip(cos_d(t), 0, None), np.arange(0, 181, 5.0), np.arange(0, 360, 30.0)),
}


@pytest.mark.parametrize("name", sorted(ANALYTIC))
def test_exact_at_measured_angles_after_unfolding(name):
    """At every measured θ and at every φ that the symmetry implies (the
    measured planes and their mirror images over the full circle), the
    distribution returns the file's candela: the analytic value × the
    file's multipliers, to the 6 printed digits."""
    f, theta, phi = ANALYTIC[name]
    d = read_photometry(DATA / name)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    truth = f(t, p)
    got = d.candela_at(t, p)
    assert np.allclose(got, truth, rtol=PRINT_REL, atol=1e-9 * truth.max()), name
    # periodic in φ: the same at φ + 360° and φ − 360°
    assert np.allclose(d.candela_at(t, p + 360), got, rtol=1e-12) and np.allclose(d.candela_at(t, p - 720), got, rtol=1e-12)


@pytest.mark.parametrize("name, symmetry", [
    ("lambert_2002.ies", "rotational"), ("quadrant_2019.ies", "quadrant"), ("bilateral_2002.ies", "bilateral"),
    ("asymmetric_2002_crlf.ies", "none"), ("bilateral90_1986.ies", "bilateral-90"), ("full_isym0.ldt", "none"),
    ("rot_isym1.ldt", "rotational"), ("c0c180_isym2.ldt", "bilateral"), ("c90c270_isym3.ldt", "bilateral-90"),
    ("quadrant_isym4.ldt", "quadrant"),
])  # fmt: skip
def test_symmetry_recognised(name, symmetry):
    assert read_photometry(DATA / name).symmetry == symmetry


def test_isym3_equals_the_full_file_everywhere():
    """EULUMDAT Isym 3 (planes C270 … C90, mirrored about C90–C270) unfolds
    to the same distribution as the Isym 0 file of the same function."""
    a = read_photometry(DATA / "c90c270_isym3.ldt")
    b = read_photometry(DATA / "full_isym0.ldt")
    t, p = np.meshgrid(np.linspace(0, 180, 37), np.linspace(0, 360, 97), indexing="ij")
    assert np.allclose(a.candela_at(t, p), b.candela_at(t, p), rtol=PRINT_REL, atol=1e-9)


def test_linear_between_measured_angles():
    """Bilinear: along θ at a measured φ, and along φ at a measured θ, the
    value between two measured angles is the linear blend of theirs; in the
    middle of a cell, the mean of its four corners."""
    d = read_photometry(DATA / "asymmetric_2002_crlf.ies")
    for frac in (0.25, 0.5, 0.9):
        t = 30 + 5 * frac
        assert d.candela_at(t, 60) == pytest.approx((1 - frac) * d.candela_at(30, 60) + frac * d.candela_at(35, 60), rel=1e-12)
        p = 60 + 30 * frac
        assert d.candela_at(40, p) == pytest.approx((1 - frac) * d.candela_at(40, 60) + frac * d.candela_at(40, 90), rel=1e-12)
    corners = [d.candela_at(a, b) for a in (30, 35) for b in (60, 90)]
    assert d.candela_at(32.5, 75) == pytest.approx(np.mean(corners), rel=1e-12)


def test_periodic_cell_from_last_plane_to_360():
    """A file whose planes stop short of 360° (0 … 300°) closes the circle:
    between 300° and 360° the value blends linearly toward the 0° plane."""
    text = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 6 1 2 0 0 0\n1 1 0\n0 90\n0 60 120 180 240 300\n"
    text += "\n".join(f"{v} {v / 2}" for v in (100, 200, 300, 400, 500, 600)) + "\n"
    d = parse_ies(text, "periodic.ies")
    assert d.candela_at(0, 330) == pytest.approx(0.5 * (600 + 100), rel=1e-12)
    assert d.candela_at(0, -30) == pytest.approx(350.0, rel=1e-12)
    assert d.candela_at(45, 0) == pytest.approx(75.0, rel=1e-12)


def test_zero_outside_measured_vertical_range():
    d = read_photometry(DATA / "lambert_2002.ies")  # 0–90°
    assert d.candela_at(90.0, 10) == pytest.approx(0.0, abs=1e-9)
    assert d.candela_at(120.0, 10) == 0.0 and d.candela_at(179.0, 200) == 0.0


def test_isotropic_total_lumens_is_exact():
    """I = I0 everywhere: Φ = 4π·I0 (the interpolant is the constant, integrated exactly)."""
    d = GoniometricDistribution(np.arange(0, 181, 10.0), [0, 360], np.full((2, 19), 80.0))
    assert d.total_lumens() == pytest.approx(4 * math.pi * 80.0, rel=1e-12)
    assert read_photometry(DATA / "isotropic_1995.ies").total_lumens() == pytest.approx(4 * math.pi * 100.0, rel=PRINT_REL)


@pytest.mark.parametrize("step_deg", [10.0, 5.0, 2.5, 1.0])
def test_lambertian_total_lumens_within_interpolation_bound(step_deg):
    """I = I0·cosθ over the lower hemisphere: Φ = π·I0. The linear
    interpolant's error per point is ≤ (h²/8)·max|I''| = h²·I0/8, so over
    the hemisphere (2π sr) |ΔΦ| ≤ 2π·h²·I0/8; the error is also positive-
    definite second order: halving h quarters it (within 1%)."""
    i0 = 1000.0

    def phi_err(h):
        t = np.arange(0, 90 + 1e-9, h)
        d = GoniometricDistribution(t, [0, 360], np.vstack([i0 * cos_d(t)] * 2))
        return d.total_lumens() - math.pi * i0

    h = math.radians(step_deg)
    err = phi_err(step_deg)
    assert abs(err) <= 2 * math.pi * h * h * i0 / 8
    assert phi_err(step_deg / 2) / err == pytest.approx(0.25, rel=0.01)


def test_total_lumens_of_phi_dependent_file():
    """I = 300(1 + 0.5 sinφ)cosθ (θ ≤ 90°) + 100|cosθ| (θ > 90°): the sinφ
    term integrates to 0, so Φ = π·300 + π·100; 5° steps keep the
    interpolation error under the bound 4π·(h²/8)·300."""
    d = read_photometry(DATA / "asymmetric_2002_crlf.ies")
    h = math.radians(5.0)
    k = math.radians(30.0)
    bound = 2 * math.pi * (h * h / 8) * 300 * 1.5 + 2 * math.pi * (h * h / 8) * 100 + 2 * math.pi * (k * k / 8) * 150
    assert abs(d.total_lumens() - 400 * math.pi) <= bound


def test_absolute_and_relative_photometry():
    """LM-63 lumens per lamp −1 is absolute (rated_lumens None); otherwise
    the rated lamp lumens are lamps × lumens per lamp. EULUMDAT: the lamp
    set's flux, unless the number of lamps is negative (absolute). IES
    candela multiplier × ballast factor apply (0.5 × 200 = 100 cd; the
    asymmetric file stores I/0.9 with ballast factor 0.9)."""
    assert read_photometry(DATA / "lambert_2002.ies").rated_lumens is None
    rel = read_photometry(DATA / "isotropic_1995.ies")
    assert rel.rated_lumens == pytest.approx(1256.64, rel=1e-12)  # written as %g
    assert rel.candela_at(17, 33) == pytest.approx(100.0, rel=1e-12)
    assert read_photometry(DATA / "asymmetric_2002_crlf.ies").candela_at(0, 0) == pytest.approx(300.0, rel=PRINT_REL)
    assert read_photometry(DATA / "c0c180_isym2.ldt").rated_lumens == 2000.0
    assert read_photometry(DATA / "absolute_isym1.ldt").rated_lumens is None


def test_regular_table_reproduces_interpolation():
    """The kernel table contains every measured angle, so bilinear
    interpolation on it equals candela_at everywhere."""
    d = read_photometry(DATA / "bilateral_2002.ies")
    th, ph, table = d.regular_table()
    assert th[0] == 0 and th[-1] == 180 and ph[0] == 0 and ph[-1] == 360
    rng = np.random.default_rng(1)
    t = rng.uniform(0, 90, 500)
    p = rng.uniform(0, 360, 500)
    reg = GoniometricDistribution(th, ph, table)
    assert np.allclose(reg.candela_at(t, p), d.candela_at(t, p), rtol=1e-9, atol=1e-9)


def test_angles_from_local_frame():
    """θ from −Z, φ from +X toward +Y (the UsdLux ShapingAPI IES frame)."""
    th, ph = angles_from_local(np.array([[0, 0, -1.0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0]]))
    assert np.allclose(th, [0, 90, 90, 180, 90]) and np.allclose(ph[1:3], [0, 90]) and ph[4] == pytest.approx(180)


@pytest.mark.parametrize("text, words", [
    ("IESNA:LM-63-2002\nTILT=lamp.tlt\n", "separate tilt file"),
    ("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 2 2 0 0 0\n1 1 0\n0 90\n0\n10 5\n", "type B"),
    ("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n10\n", "file ends inside the candela values"),
    ("IESNA:LM-63-2002\n[TEST] x\n1 -1 1\n", "no TILT= line"),
    ("IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 2 1 2 0 0 0\n1 1 0\n0 90\n0 45\n10 5 10 5\n", "match no type C symmetry"),
])  # fmt: skip
def test_bad_files_are_one_line_user_errors(text, words):
    with pytest.raises(UserError) as e:
        parse_ies(text, "bad.ies")
    assert words in str(e.value) and "\n" not in str(e.value) and "bad.ies" in str(e.value)


def test_tilt_include_with_real_factors_is_refused():
    with pytest.raises(UserError, match="TILT=INCLUDE"):
        read_photometry(DATA / "tilt_real.ies")


def test_missing_and_unknown_files(tmp_path):
    with pytest.raises(UserError, match="no such file"):
        read_photometry(tmp_path / "none.ies")
    (tmp_path / "x.txt").write_text("")
    with pytest.raises(UserError, match="unknown photometric file type"):
        read_photometry(tmp_path / "x.txt")


def test_measured_360_plane_that_differs_is_averaged_with_0():
    """Real files repeat the 0° plane at 360° with measurement noise; both
    become their mean, so I is periodic in φ."""
    text = "IESNA:LM-63-1995\nTILT=NONE\n1 -1 1 2 3 1 2 0 0 0\n1 1 0\n0 90\n0 180 360\n100 50\n300 10\n110 60\n"
    d = parse_ies(text, "noisy.ies")
    assert d.candela_at(0, 0) == pytest.approx(105.0) and d.candela_at(0, 360) == pytest.approx(105.0)
    assert d.candela_at(90, 180) == pytest.approx(10.0)
