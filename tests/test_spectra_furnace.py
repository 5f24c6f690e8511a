"""A furnace with a coloured albedo: the spectral closed form, the grey reduction's error, and the
hero-wavelength estimator the kernels will run (here in numpy).

In a closed diffuse enclosure whose walls all emit L_e(λ) and reflect with
albedo ρ(λ), the radiance is L(λ) = L_e(λ)/(1 − ρ(λ)) everywhere, so an
irradiance sensor reads, for a response with weighting q (photopic, PAR …)::

    R = π ∫ q(λ) L_e(λ) / (1 − ρ(λ)) dλ.

probesim's grey reduction replaces ρ(λ) by the BT.709 luminance grey of the
sRGB albedo, ρ_g = 0.2126 r + 0.7152 g + 0.0722 b, and reads
``π R[L_e] / (1 − ρ_g)``. For ρ = uplift(0.8, 0.2, 0.2) (a saturated red,
Mallett–Yuksel) under D65 the grey reduction reads the illuminance 20.6 %
low (ρ_g = 0.328; the red band's 1/(1 − ρ) ≈ 4.4 is what it misses), the
PPFD 30.0 % low, and the melanopic EDI 17.6 % *high* (the room returns
little blue). Those are the errors of today's one-channel run on that room;
the tests compute them and check that spectral Monte Carlo resolves them.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.spectra import grid, reflectance, responses as R, sources
from simulator.spectra.grid import Bands, sample_hero_nm, hero_pdf_per_nm, trapezoid_weights
from simulator.spectra.reduce import band_weights
from simulator.units import luminance_grey

RED = (0.8, 0.2, 0.2)
NAMES = ("photopic", "melanopic_edi", "par")


def _closed_form(name: str, emission: np.ndarray, rho: np.ndarray) -> float:
    """π ∫ q L_e/(1 − ρ) dλ on the grid (trapezoid rule)."""
    return math.pi * float(R.response(name).of(emission / (1.0 - rho)))


def _grey_reduction(name: str, emission: np.ndarray, rgb) -> float:
    """What the one-channel run reads: π R[L_e] / (1 − grey(rgb))."""
    return math.pi * float(R.response(name).of(emission)) / (1.0 - luminance_grey(rgb))


def hero_furnace(emission: np.ndarray, rho: np.ndarray, names, n_paths: int, seed: int, n_hero: int = 4):
    """Hero-wavelength random walks in a furnace: mean and stderr of each response's irradiance.

    Each path draws one uniform u and carries the ``n_hero`` wavelengths of
    :func:`sample_hero_nm`; at every vertex it adds ``β_k L_e(λ_k)`` and
    multiplies ``β_k`` by ``ρ(λ_k)``; Russian roulette survives with
    ``p = max_k β_k`` (then β /= p), so paths end where every wavelength is
    dark. Irradiance = π × radiance (cosine-weighted directions: the furnace
    is uniform). A wavelength reads the nearest grid node, so the estimate's
    expectation is the grid's trapezoid integral exactly (node i's cell is
    its trapezoid weight). Per path the response estimate is
    ``(1/n) Σ_k q(λ_k) L_k / p(λ)`` with q as a density.
    """
    rng = np.random.default_rng(seed)
    lam = sample_hero_nm(rng.random(n_paths), n_hero)  # (n_hero, n_paths)
    idx = np.rint(lam - grid.LAMBDA_MIN_NM).astype(int)
    le, r = emission[idx], rho[idx]
    beta = np.ones_like(le)
    radiance = np.zeros_like(le)
    alive = np.ones(n_paths, bool)
    while alive.any():
        radiance[:, alive] += beta[:, alive] * le[:, alive]
        beta[:, alive] *= r[:, alive]
        p = np.minimum(1.0, beta.max(axis=0))
        survive = alive & (rng.random(n_paths) < p)
        beta[:, survive] /= p[survive]
        alive = survive
    out = {}
    t = trapezoid_weights()
    for name in names:
        density = R.response(name).q / t
        per_path = math.pi * (density[idx] * radiance).mean(axis=0) / hero_pdf_per_nm()
        out[name] = (float(per_path.mean()), float(per_path.std(ddof=1) / math.sqrt(n_paths)))
    return out


@pytest.fixture(scope="module")
def red_room():
    return sources.cie_illuminant("D65").values / 100.0, reflectance.uplift(RED)


def test_grey_reduction_error_on_a_saturated_red_furnace(red_room):
    """The grey reduction's relative error for ρ = uplift(0.8, 0.2, 0.2) under
    D65: −20.6 % for illuminance, +17.6 % melanopic EDI, −30.0 % PPFD (computed
    here from the closed form, to 0.05 %). A grey albedo of the same
    luminance is read exactly by the reduction."""
    le, rho = red_room
    err = {n: _grey_reduction(n, le, RED) / _closed_form(n, le, rho) - 1.0 for n in NAMES}
    assert err["photopic"] == pytest.approx(-0.206, abs=5e-4)
    assert err["melanopic_edi"] == pytest.approx(0.176, abs=5e-4)
    assert err["par"] == pytest.approx(-0.300, abs=5e-4)
    g = luminance_grey(RED)
    for n in NAMES:
        assert _grey_reduction(n, le, (g, g, g)) == pytest.approx(_closed_form(n, le, reflectance.uplift((g, g, g))), rel=1e-12)


def test_hero_wavelengths_read_the_coloured_furnace_within_4_sigma(red_room):
    """20,000 hero-wavelength paths (4 wavelengths each, seed 11) read
    π ∫ q L_e/(1 − ρ) within 4 standard errors for illuminance, melanopic EDI
    and PPFD, and resolve the grey reduction's error by more than 20 of them."""
    le, rho = red_room
    est = hero_furnace(le, rho, NAMES, 20000, seed=11)
    for n in NAMES:
        mean, se = est[n]
        truth = _closed_form(n, le, rho)
        assert abs(mean - truth) <= 4 * se + 1e-12 * truth, (n, mean, truth, se)
        assert abs(_grey_reduction(n, le, RED) - truth) > 20 * se, n


def test_hero_wavelengths_read_a_grey_furnace_within_4_sigma():
    """Grey walls (ρ = 0.5 flat): hero wavelengths read π R[L_e]/(1 − ρ) too,
    with wavelength noise the one-channel run does not have (hence grey
    scenes keep one channel)."""
    le, rho = sources.cie_illuminant("A").values / 100.0, reflectance.uplift((0.5, 0.5, 0.5))
    est = hero_furnace(le, rho, NAMES, 20000, seed=12)
    for n in NAMES:
        mean, se = est[n]
        truth = math.pi * float(R.response(n).of(le)) / 0.5
        assert abs(mean - truth) <= 4 * se + 1e-12 * truth, (n, mean, truth, se)


def test_equal_width_bands_are_biased_on_the_saturated_furnace(red_room):
    """Why hero wavelengths rather than bands: n equal bands, each with the
    emitter-weighted mean reflectance, read the red furnace's illuminance
    with a bias that only more bands remove: −4.1 % (16 bands of 25 nm),
    −0.5 % (40 of 10 nm), −0.2 % (80 of 5 nm). A bias does not shrink with
    samples; hero wavelengths have none (test above)."""
    le, rho = red_room
    truth = _closed_form("photopic", le, rho)
    errs = {}
    for n in (16, 40, 80):
        b = Bands(n)
        per_band = math.pi * b.integrate(le) / (1.0 - b.average(rho, le))
        errs[n] = float(band_weights(R.response("photopic"), b, le) @ per_band) / truth - 1.0
    assert errs[16] == pytest.approx(-0.041, abs=1e-3)
    assert abs(errs[80]) < abs(errs[40]) < abs(errs[16])
    assert abs(errs[80]) < 0.005


def test_band_weights_are_exact_for_a_grey_scene():
    """With grey transport every band scales alike: band weights reproduce
    each response of the emitter to rounding, whatever the band count."""
    le = sources.spd_csv(Path(__file__).resolve().parents[1] / "stages" / "spectra" / "grow_led_spd.csv").values
    for n in (4, 16, 50):
        b = Bands(n)
        for name in ("photopic", "par", "epar", "melanopic_edi"):
            assert float(band_weights(R.response(name), b, le) @ b.integrate(0.7 * le)) == pytest.approx(
                0.7 * float(R.response(name).of(le)), rel=1e-12)
