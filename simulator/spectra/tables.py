"""CIE tables sampled on the reduction grid (380–780 nm, 1 nm), cached.

Every table but one comes from ``colour-science`` (imported here, lazily, on
first use): the CIE 1924 photopic V(λ), the CIE 1951 scotopic V′(λ), the
CIE 2006 10° cone fundamentals (Stockman & Sharpe, energy, peak 1: the S-,
M- and L-cone action spectra of CIE S 026), the CIE illuminants and the
Mallett & Yuksel (2019) sRGB basis. The CIE S 026 melanopic action spectrum
is not in colour-science; it is read from ``data/cie_s026_melanopic.csv``
(CIE S 026/E:2018 Table 2, 1 nm). A tabulated spectrum is sampled the way
:mod:`simulator.units` samples it (``sd[wavelengths]``, colour-science's own
interpolator), so the photopic response here and the photometric twin there
agree to rounding.

References
----------
CIE 018:2019 (V, V′); CIE 170-1:2006 (cone fundamentals); CIE S 026/E:2018
(α-opic action spectra); CIE 15:2018 (illuminants, LED series); Mallett, I.
and Yuksel, C. (2019), "Spectral Primary Decomposition for Rendering with
sRGB Reflectance", EGSR 2019.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from simulator.spectra.grid import WAVELENGTHS_NM

__all__ = [
    "photopic",
    "scotopic",
    "cone_fundamentals",
    "melanopic",
    "illuminant",
    "illuminant_names",
    "mallett_basis",
    "cmfs_1931",
]

_DATA = Path(__file__).with_name("data")
#: S 026 defines the cone action spectra from 390 nm; below it they are 0
_CONES_FROM_NM = 390.0


def _colour():
    import colour  # lazy: ~1 s

    return colour


def _frozen(a) -> np.ndarray:
    a = np.asarray(a, dtype=np.float64).copy()
    a.setflags(write=False)
    return a


@lru_cache(maxsize=None)
def photopic() -> np.ndarray:
    """CIE 1924 photopic luminous efficiency V(λ), shape (401,)."""
    c = _colour()
    return _frozen(c.colorimetry.SDS_LEFS_PHOTOPIC["CIE 1924 Photopic Standard Observer"][WAVELENGTHS_NM])


@lru_cache(maxsize=None)
def scotopic() -> np.ndarray:
    """CIE 1951 scotopic luminous efficiency V′(λ) (S 026's rhodopic action spectrum), shape (401,)."""
    c = _colour()
    return _frozen(c.colorimetry.SDS_LEFS_SCOTOPIC["CIE 1951 Scotopic Standard Observer"][WAVELENGTHS_NM])


@lru_cache(maxsize=None)
def cone_fundamentals() -> np.ndarray:
    """CIE 2006 10° cone fundamentals (l, m, s), energy, peak 1, shape (3, 401); 0 below 390 nm."""
    c = _colour()
    lms = np.asarray(c.MSDS_CMFS["Stockman & Sharpe 10 Degree Cone Fundamentals"][WAVELENGTHS_NM], float).T
    lms = np.nan_to_num(lms, nan=0.0)
    lms[:, WAVELENGTHS_NM < _CONES_FROM_NM] = 0.0  # colour-science extrapolates; S 026 leaves them undefined
    return _frozen(np.clip(lms, 0.0, None))


@lru_cache(maxsize=None)
def melanopic() -> np.ndarray:
    """CIE S 026 melanopic action spectrum s_mel(λ), peak 1, shape (401,)."""
    from simulator.spectra.csvfile import read_spectral_csv

    t = read_spectral_csv(_DATA / "cie_s026_melanopic.csv", "action spectrum",
                          lambda c: None if c == "s_mel" else "'s_mel'")
    return _frozen(t.on_grid("zero"))


@lru_cache(maxsize=None)
def illuminant_names() -> tuple[str, ...]:
    """Names of the CIE illuminants colour-science tabulates (``D65``, ``A``, ``FL2``, ``LED-B3``, …)."""
    return tuple(_colour().SDS_ILLUMINANTS)


@lru_cache(maxsize=None)
def illuminant(name: str) -> np.ndarray:
    """Relative SPD of a CIE illuminant on the grid, shape (401,) (KeyError if unknown).

    Tables that stop short of 780 nm are 0 beyond their end.
    """
    sd = _colour().SDS_ILLUMINANTS[name]
    lo, hi = sd.shape.start, sd.shape.end
    v = np.zeros_like(WAVELENGTHS_NM)
    inside = (WAVELENGTHS_NM >= lo) & (WAVELENGTHS_NM <= hi)
    v[inside] = np.asarray(sd[WAVELENGTHS_NM[inside]], float)
    return _frozen(np.clip(v, 0.0, None))


@lru_cache(maxsize=None)
def mallett_basis() -> np.ndarray:
    """Mallett & Yuksel (2019) sRGB basis spectra (red, green, blue), shape (3, 401).

    colour-science tabulates them at 5 nm; linear interpolation onto the
    grid keeps each non-negative, and each column is then divided by its sum
    (the table sums to 1 within 1e-5) so that the three add up to exactly 1
    at every wavelength: a grey colour uplifts to an exactly flat spectrum.
    """
    from colour.recovery import MSDS_BASIS_FUNCTIONS_sRGB_MALLETT2019 as basis

    wl = np.asarray(basis.wavelengths, float)
    b = np.stack([np.interp(WAVELENGTHS_NM, wl, basis.values[:, k]) for k in range(3)])
    b = np.clip(b, 0.0, None)
    return _frozen(b / b.sum(axis=0))


@lru_cache(maxsize=None)
def cmfs_1931() -> np.ndarray:
    """CIE 1931 2° colour matching functions (x̄, ȳ, z̄), shape (3, 401)."""
    c = _colour()
    return _frozen(np.asarray(c.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"][WAVELENGTHS_NM], float).T)
