"""The wavelength grid every spectrum is sampled on, and the transport bands.

Two layouts, for two jobs:

* The *reduction grid* :data:`WAVELENGTHS_NM`, 380–780 nm at 1 nm (401
  samples), is where spectra live on the host and where every response is
  integrated (trapezoid rule). It is the grid :mod:`simulator.units`
  integrates efficacies on, so the photopic response of a spectrum equals the
  photometric twin the engine carries for it. PAR (400–700 nm) and ePAR
  (400–750 nm) lie inside it; so do the CIE S 026 action spectra (defined on
  380–780 nm). Nothing probesim reports needs 300–380 nm or 780–800 nm.
* :class:`Bands`: equal-width bands over the same range for spectral
  *transport* (the kernels carry one value per band). See docs/DESIGN.md,
  "Spectral transport", for why bands rather than hero wavelengths.

Notes
-----
A quadrature vector ``q`` (shape (401,)) turns a spectral density sampled
on the grid into its integral, ``∫ f(λ) dλ ≈ q · f``. :func:`trapezoid_weights`
builds one over any sub-interval [lo, hi] of the grid whose ends are grid
points, so a boxcar response (PAR) integrates exactly from lo to hi.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

__all__ = [
    "LAMBDA_MIN_NM",
    "LAMBDA_MAX_NM",
    "STEP_NM",
    "WAVELENGTHS_NM",
    "trapezoid_weights",
    "integrate",
    "Bands",
    "sample_hero_nm",
    "hero_pdf_per_nm",
]

LAMBDA_MIN_NM = 380.0
LAMBDA_MAX_NM = 780.0
STEP_NM = 1.0
#: the reduction grid, nm, shape (401,)
WAVELENGTHS_NM = np.arange(LAMBDA_MIN_NM, LAMBDA_MAX_NM + STEP_NM / 2, STEP_NM)
WAVELENGTHS_NM.setflags(write=False)


@lru_cache(maxsize=32)
def _weights(lo_nm: float, hi_nm: float) -> np.ndarray:
    wl = WAVELENGTHS_NM
    if not (LAMBDA_MIN_NM <= lo_nm < hi_nm <= LAMBDA_MAX_NM):
        raise ValueError(f"[{lo_nm:g}, {hi_nm:g}] nm is not inside the grid {LAMBDA_MIN_NM:g}–{LAMBDA_MAX_NM:g} nm")
    i0, i1 = np.searchsorted(wl, [lo_nm, hi_nm])
    if wl[i0] != lo_nm or wl[i1] != hi_nm:
        raise ValueError(f"[{lo_nm:g}, {hi_nm:g}] nm: the ends must be grid points ({STEP_NM:g} nm steps)")
    q = np.zeros_like(wl)
    q[i0:i1 + 1] = STEP_NM
    q[i0] = q[i1] = STEP_NM / 2
    q.setflags(write=False)
    return q


def trapezoid_weights(lo_nm: float = LAMBDA_MIN_NM, hi_nm: float = LAMBDA_MAX_NM) -> np.ndarray:
    """Trapezoid-rule quadrature vector over [lo, hi] on the grid, nm.

    Parameters
    ----------
    lo_nm, hi_nm : float
        Interval ends, nm; grid points with ``380 <= lo < hi <= 780``.

    Returns
    -------
    ndarray, shape (401,)
        ``q`` with ``q · f ≈ ∫_lo^hi f(λ) dλ`` (zero outside [lo, hi]); read-only.
    """
    return _weights(float(lo_nm), float(hi_nm))


def integrate(values: np.ndarray, lo_nm: float = LAMBDA_MIN_NM, hi_nm: float = LAMBDA_MAX_NM) -> np.ndarray:
    """∫ values(λ) dλ over [lo, hi] along the last axis (trapezoid rule).

    Parameters
    ----------
    values : array_like, shape (..., 401)
        A spectral density on :data:`WAVELENGTHS_NM` (e.g. W m⁻² nm⁻¹).

    Returns
    -------
    ndarray, shape (...)
        The integral (e.g. W m⁻²).
    """
    return np.asarray(values, float) @ trapezoid_weights(lo_nm, hi_nm)


@dataclass(frozen=True)
class Bands:
    """``n`` equal-width wavelength bands over 380–780 nm for spectral transport.

    Band ``b`` covers ``[380 + b·w, 380 + (b+1)·w]`` nm, ``w = 400/n``. A
    band carries the integral of a spectral quantity over it (W in the band),
    so the bands of a spectrum add up to its grid integral exactly.

    Attributes
    ----------
    n : int
        Number of bands; must divide 400 (the grid has 1 nm steps).
    """

    n: int = 16

    def __post_init__(self):
        if self.n < 1 or 400 % self.n:
            raise ValueError(f"band count {self.n} must divide 400 (1 nm grid over 380–780 nm)")

    @property
    def width_nm(self) -> float:
        return 400.0 / self.n

    @property
    def edges_nm(self) -> np.ndarray:
        """Band edges, nm, shape (n + 1,)."""
        return LAMBDA_MIN_NM + self.width_nm * np.arange(self.n + 1)

    @property
    def centres_nm(self) -> np.ndarray:
        """Band centres, nm, shape (n,)."""
        e = self.edges_nm
        return 0.5 * (e[:-1] + e[1:])

    def matrix(self) -> np.ndarray:
        """Band-integration matrix ``B``, shape (n, 401): ``B @ f`` = ∫ f over each band.

        Rows are :func:`trapezoid_weights` over each band, so ``B.sum(0)``
        equals the full-grid weights (shared edge points get half from each side).
        """
        e = self.edges_nm
        return np.stack([trapezoid_weights(e[b], e[b + 1]) for b in range(self.n)])

    def integrate(self, values: np.ndarray) -> np.ndarray:
        """Band integrals of a spectral density, shape (..., n)."""
        return np.asarray(values, float) @ self.matrix().T

    def average(self, values: np.ndarray, weight: np.ndarray) -> np.ndarray:
        """Weighted band averages ``∫_b v·w dλ / ∫_b w dλ`` (e.g. a reflectance
        averaged under the emitter's spectrum), shape (..., n); 0 where ∫_b w = 0."""
        num = self.integrate(np.asarray(values, float) * weight)
        den = self.integrate(weight)
        return np.divide(num, den, out=np.zeros_like(num), where=den > 0)


def sample_hero_nm(u, n: int = 4) -> np.ndarray:
    """Hero wavelengths: one uniform wavelength and its ``n − 1`` equally spaced rotations.

    ``λ_k = 380 + 400 · frac(u + k/n)`` nm, k = 0 … n−1 (Wilkie et al. 2014):
    each λ_k is uniform on [380, 780] nm, and together they stratify the
    range. The twin :func:`hero_pdf_per_nm` gives each one's density, so the
    estimate of ``∫ q(λ) f(λ) dλ`` from one path is ``(1/n) Σ_k q(λ_k) f(λ_k) / p``.

    Parameters
    ----------
    u : float or ndarray, shape (m,)
        Uniform random numbers in [0, 1).
    n : int

    Returns
    -------
    ndarray, shape (n,) or (n, m)
    """
    u = np.asarray(u, float)
    k = np.arange(n).reshape((n,) + (1,) * u.ndim)
    return LAMBDA_MIN_NM + (LAMBDA_MAX_NM - LAMBDA_MIN_NM) * np.mod(u + k / n, 1.0)


def hero_pdf_per_nm() -> float:
    """Density of each hero wavelength, nm⁻¹: uniform, 1/400."""
    return 1.0 / (LAMBDA_MAX_NM - LAMBDA_MIN_NM)
