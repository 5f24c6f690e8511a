"""Reductions: a response's standard error from the covariance between wavelengths or bands."""

from __future__ import annotations

import numpy as np
import pytest

from simulator.spectra import responses as R, sources
from simulator.spectra.grid import Bands
from simulator.spectra.reduce import band_weights, reduce_bands, reduce_grid


def _correlated_band_samples(n_samples: int, bands: Bands, seed: int):
    """Per-sample band values that share a path factor (as one path carrying every band does)."""
    rng = np.random.default_rng(seed)
    common = rng.exponential(1.0, (n_samples, 1))
    own = rng.normal(0.0, 0.2, (n_samples, bands.n))
    return bands.integrate(sources.cie_illuminant("D65").values) * (common + own)


def test_band_covariance_gives_the_stderr_of_the_projected_samples():
    """Var(w·X̄) = wᵀ Cov(X̄) w: reduce_bands' stderr equals the standard
    error of the per-sample projections w·X_i (what a kernel would
    accumulate) to rounding; treating the bands as independent would
    understate it (here by more than 2×)."""
    b = Bands(16)
    x = _correlated_band_samples(4000, b, seed=9)
    w = {n: band_weights(R.response(n), b, sources.cie_illuminant("D65").values) for n in ("photopic", "par")}
    mean, cov = x.mean(axis=0), np.cov(x, rowvar=False) / len(x)
    out = reduce_bands(w, mean, cov)
    for name, wv in w.items():
        proj = x @ wv
        assert out[name][0] == pytest.approx(proj.mean(), rel=1e-12)
        assert out[name][1] == pytest.approx(proj.std(ddof=1) / np.sqrt(len(x)), rel=1e-9)
        independent = np.sqrt(np.sum(wv**2 * np.diag(cov)))
        assert out[name][1] > 2 * independent


def test_grid_reduction_with_covariance_stderr_or_none():
    """On the grid: a full covariance, per-wavelength stderrs of independent
    values (Σ q² σ²), or an exact spectrum (stderr 0)."""
    e = sources.cie_illuminant("D65").values
    q = R.response("par")
    sigma = 0.01 * e
    cov = np.diag(sigma**2)
    a = reduce_grid([q], e, cov=cov)["par"]
    b = reduce_grid([q], e, stderr=sigma)["par"]
    c = reduce_grid([q], e)["par"]
    assert a[0] == pytest.approx(q.of(e)) and a[1] == pytest.approx(b[1], rel=1e-12)
    assert b[1] == pytest.approx(np.sqrt(np.sum(q.q**2 * sigma**2)), rel=1e-12)
    assert c[1] == 0.0
    full = np.outer(sigma, sigma)  # perfectly correlated: stderr is the linear sum
    assert reduce_grid([q], e, cov=full)["par"][1] == pytest.approx(float(q.q @ sigma), rel=1e-9)
