"""``probesim compare A.exr B.exr``: error figures of one map against another.

Expected values are computed by hand from the constructed maps (formulas in
simulator.commands.compare's docstring).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.commands.compare import compare_arrays, compare_files
from simulator.errors import UserError
from simulator.io.exr import write_channels
from simulator.io.latlong import latlong_uv_to_direction


def _grey(path, values, **extra):
    v = np.asarray(values, np.float32)
    write_channels(path, {"R": v, "G": v, "B": v, **extra})
    return path


def test_identical_maps():
    """A map against itself: no error, PSNR infinite, SSIM 1."""
    a = np.random.default_rng(1).uniform(0.5, 2.0, (16, 32))
    f = compare_arrays(a, a)
    assert f["rel_rms"] == 0.0 and f["max_abs_error"] == 0.0
    assert f["psnr_db"] == math.inf and f["ssim"] == pytest.approx(1.0)


def test_one_pixel_off_in_a_latlong_map(tmp_path):
    """B = 1 everywhere on a 32 × 16 lat-long map, A = B except 3 at (row 5,
    column 20): relative RMS = √(4/512)/1, the largest error is 2 at that
    pixel, in the direction of its centre (u, v) = (20.5/32, 5.5/16); PSNR of
    log10 values is 10·log10(range²/MSE) with range 1 (log10 B is constant, so
    the data range falls back to 1) and MSE = log10(3)²/512."""
    b = np.ones((16, 32))
    a = b.copy()
    a[5, 20] = 3.0
    c = compare_files(_grey(tmp_path / "a.exr", a), _grey(tmp_path / "b.exr", b))
    assert c.quantity.startswith("Y")
    assert c.rel_rms == pytest.approx(math.sqrt(4 / 512), rel=1e-6)
    assert c.max_pixel == (5, 20) and c.max_abs_error == pytest.approx(2.0, rel=1e-6)
    assert c.value_a == pytest.approx(3.0) and c.value_b == pytest.approx(1.0)
    want = latlong_uv_to_direction(np.array([20.5 / 32, 5.5 / 16]))
    assert np.allclose(c.direction, want, atol=1e-12)
    assert c.lon_lat_deg == pytest.approx((math.degrees(math.pi * (1 - 2 * 20.5 / 32)), math.degrees(math.pi * (0.5 - 5.5 / 16))))
    assert c.psnr_db == pytest.approx(10 * math.log10(1.0 / (math.log10(3.0) ** 2 / 512)), rel=1e-6)
    assert c.ssim is not None and c.ssim < 1.0


def test_standardised_residuals_from_stderr_channels(tmp_path):
    """Both files carry L_W_m2_sr and L_stderr_W_m2_sr: with σ_A = 3, σ_B = 4
    and A − B = 5 on a quarter of the pixels (0 elsewhere), z = 5/5 = 1 there:
    none beyond 4σ and χ²/dof = 1/4."""
    b = np.full((8, 16), 10.0, np.float32)
    a = b.copy()
    a[:, :4] += 5.0
    write_channels(tmp_path / "a.exr", {"L_W_m2_sr": a, "L_stderr_W_m2_sr": np.full_like(a, 3.0)})
    write_channels(tmp_path / "b.exr", {"L_W_m2_sr": b, "L_stderr_W_m2_sr": np.full_like(b, 4.0)})
    c = compare_files(tmp_path / "a.exr", tmp_path / "b.exr")
    assert c.quantity == "L_W_m2_sr"
    assert c.beyond_4sigma == 0.0 and c.chi2_per_dof == pytest.approx(0.25) and c.dof == 128


def test_named_channel_and_small_maps(tmp_path):
    """--channel picks a channel; a 2 × 3 grid map has no SSIM (under 3
    pixels a side) but every other figure."""
    a = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]], np.float32)
    write_channels(tmp_path / "a.exr", {"Ev_lx": a, "E_W_m2": a})
    write_channels(tmp_path / "b.exr", {"Ev_lx": a * 2, "E_W_m2": a})
    c = compare_files(tmp_path / "a.exr", tmp_path / "b.exr", channel="Ev_lx")
    assert c.rel_rms == pytest.approx(0.5) and c.ssim is None and c.direction is None
    with pytest.raises(UserError, match="no channel 'X'"):
        compare_files(tmp_path / "a.exr", tmp_path / "b.exr", channel="X")


def test_cli_reports_and_refuses(tmp_path, capsys):
    """The CLI prints the figures (exit 0); mismatched sizes or a missing file
    is one line on stderr and exit status 2."""
    a = _grey(tmp_path / "a.exr", np.ones((8, 16)))
    b = _grey(tmp_path / "b.exr", np.ones((8, 16)) * 2)
    small = _grey(tmp_path / "s.exr", np.ones((4, 8)))
    assert main(["compare", str(a), str(b)]) == 0
    out = capsys.readouterr().out
    assert "relative RMS error: 0.5" in out and "largest error" in out and "PSNR" in out and "SSIM" in out
    for args in ([str(a), str(small)], [str(a), str(tmp_path / "missing.exr")]):
        assert main(["compare", *args]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and err.startswith("probesim: error: "), err
