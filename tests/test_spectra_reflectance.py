"""RGB → reflectance uplift (Mallett & Yuksel 2019): bounds, grey stays grey, round trip; reflectance CSV."""

from __future__ import annotations

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.spectra import grid, reflectance


def test_uplift_is_bounded_by_its_largest_channel():
    """For 10,000 random albedos in [0, 1]³: 0 ≤ ρ(λ) ≤ max(r, g, b) ≤ 1 at
    every wavelength (the basis is non-negative and sums to 1)."""
    rgb = np.random.default_rng(3).random((10000, 3))
    rho = reflectance.uplift(rgb)
    assert rho.min() >= 0.0
    assert np.all(rho.max(axis=1) <= rgb.max(axis=1) + 1e-12)
    assert reflectance.uplift([1.0, 1.0, 1.0]).max() <= 1.0 + 1e-15


@pytest.mark.parametrize("c", [0.0, 0.18, 0.5, 0.95])
def test_grey_stays_grey(c):
    """A grey colour uplifts to an exactly flat spectrum of its value (1e-15)."""
    rho = reflectance.uplift([c, c, c])
    assert np.max(np.abs(rho - c)) <= 1e-15


def test_round_trip_error_is_small():
    """Uplift, then back to linear sRGB under D65 (CIE 1931 2°): the largest
    channel error over 2,000 random colours in [0, 1]³ is 1.2e-3 (measured);
    bounded here by 2e-3. Saturated primaries come back within 2e-3 too."""
    rgb = np.random.default_rng(5).random((2000, 3))
    back = reflectance.rgb_of_reflectance(reflectance.uplift(rgb))
    assert np.abs(back - rgb).max() < 2e-3
    eye = np.eye(3)
    assert np.abs(reflectance.rgb_of_reflectance(reflectance.uplift(eye)) - eye).max() < 2e-3


def test_out_of_range_colours_are_refused():
    for bad in ([1.1, 0, 0], [-0.1, 0.5, 0.5], [np.nan, 0, 0]):
        with pytest.raises(ValueError):
            reflectance.uplift(bad)


def test_measured_reflectance_csv(tmp_path):
    """A percent column is read as a fraction, held flat beyond the file's
    range, linearly interpolated inside; a value of 1 or more is refused."""
    p = tmp_path / "paint.csv"
    p.write_text("wavelength_nm,reflectance_percent\n400,10\n700,70\n")
    rho = reflectance.reflectance_csv(p)
    wl = grid.WAVELENGTHS_NM
    assert rho[wl == 380][0] == pytest.approx(0.1) and rho[wl == 780][0] == pytest.approx(0.7)
    assert rho[wl == 550][0] == pytest.approx(0.4, rel=1e-12)
    p.write_text("wavelength_nm,reflectance\n400,0.5\n700,1.0\n")
    with pytest.raises(UserError, match=r"paint\.csv:3: reflectance 1 is outside \[0, 1\)"):
        reflectance.reflectance_csv(p)
