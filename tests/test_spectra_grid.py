"""The wavelength grid, transport bands, the hero-wavelength sampler, and the lazy colour-science import."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from simulator.spectra.grid import WAVELENGTHS_NM, Bands, hero_pdf_per_nm, integrate, sample_hero_nm, trapezoid_weights

ROOT = Path(__file__).resolve().parents[1]


def test_trapezoid_weights_integrate_polynomials_exactly_on_sub_intervals():
    """∫_400^700 (a + bλ) dλ is exact for the trapezoid rule; the weights are 0 outside."""
    q = trapezoid_weights(400, 700)
    assert q[(WAVELENGTHS_NM < 400) | (WAVELENGTHS_NM > 700)].max() == 0.0
    assert integrate(2.0 + 0.5 * WAVELENGTHS_NM, 400, 700) == pytest.approx(2 * 300 + 0.25 * (700**2 - 400**2), rel=1e-14)
    with pytest.raises(ValueError):
        trapezoid_weights(400.5, 700)
    with pytest.raises(ValueError):
        trapezoid_weights(300, 700)


@pytest.mark.parametrize("n", [1, 4, 16, 40, 80])
def test_bands_tile_the_grid(n):
    """Band rows add up to the full-range weights; each band of a flat spectrum is its width."""
    b = Bands(n)
    assert np.allclose(b.matrix().sum(axis=0), trapezoid_weights(), rtol=0, atol=1e-12)
    assert np.allclose(b.integrate(np.ones_like(WAVELENGTHS_NM)), b.width_nm, rtol=1e-12)
    assert b.edges_nm[0] == 380 and b.edges_nm[-1] == 780 and len(b.centres_nm) == n


def test_band_count_must_divide_the_range():
    with pytest.raises(ValueError):
        Bands(7)


def test_hero_wavelengths_are_uniform_and_stratified():
    """Each hero wavelength is uniform on [380, 780] nm (chi-square over 40
    bins of 20,000 draws, p > 0.001, fixed seed), the four are 100 nm apart
    modulo the range, and the pdf twin integrates to 1."""
    lam = sample_hero_nm(np.random.default_rng(4).random(20000), 4)
    for k in range(4):
        counts, _ = np.histogram(lam[k], bins=40, range=(380, 780))
        assert stats.chisquare(counts).pvalue > 1e-3
    gaps = np.mod(lam[1:] - lam[:-1], 400.0)
    assert np.allclose(gaps, 100.0, atol=1e-9)
    assert hero_pdf_per_nm() * 400.0 == pytest.approx(1.0)


def test_spectra_modules_do_not_import_colour_science():
    """Importing the spectra package (everything but the tables' first use)
    leaves colour-science unimported: a grey run never pays its ~1 s."""
    code = ("import sys; import simulator.spectra.grid, simulator.spectra.sources, simulator.spectra.responses, "
            "simulator.spectra.reflectance, simulator.spectra.reduce, simulator.spectra.posthoc, "
            "simulator.spectra.config, simulator.spectra.transport, simulator.io.results, simulator.io.maps; "
            "print('colour' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
