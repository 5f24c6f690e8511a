"""The wide grid, 300–1100 nm at 1 nm: where a sensor model's channels read light beyond the visible.

Transport and every response column live on the 380–780 nm grid
(:mod:`simulator.spectra.grid`), where a light's radiometric value is
defined. A real sensor sees more: a silicon channel reaches 1,100 nm, an
infrared channel is mostly beyond 780 nm, a UV meter below 380 nm. A
sensor model (:mod:`simulator.sensor_models`) therefore weighs the light
on this grid, which contains the visible grid node for node (index 80 is
380 nm, 480 is 780 nm).

How far a light spectrum is known on it (:attr:`Spectrum.wide_range`):

- blackbodies (colour temperatures) and CIE illuminant A: Planck's law,
  all of 300–1100 nm;
- CIE daylight (D50, D55, D65, D75): the CIE D-series (S0, S1, S2) over
  300–830 nm, where CIE defines it, and beyond 830 nm the blackbody at the
  illuminant's correlated colour temperature joined at 830 nm (an
  approximation, noted: real daylight has water-vapour bands near 940 nm);
- E (equal energy): flat over the whole grid;
- a measured SPD: its file's range, 0 outside it (noted where a channel
  responds there);
- the other CIE tables (fluorescent, LED, HP): 380–780 nm, 0 outside.

Inside 380–780 nm a wide spectrum equals its grid values exactly, so a
ratio taken on the wide grid agrees with the transport's radiometric and
photometric values; the parts outside are scaled to join it.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from simulator.spectra.grid import LAMBDA_MAX_NM, LAMBDA_MIN_NM, WAVELENGTHS_NM

__all__ = ["WIDE_MIN_NM", "WIDE_MAX_NM", "WIDE_NM", "VISIBLE", "wide_weights", "widen", "cie_a_relative",
           "daylight_wide"]

WIDE_MIN_NM = 300.0
WIDE_MAX_NM = 1100.0
#: the wide grid, nm, shape (801,)
WIDE_NM = np.arange(WIDE_MIN_NM, WIDE_MAX_NM + 0.5, 1.0)
WIDE_NM.setflags(write=False)
#: the visible grid's nodes on the wide grid: ``WIDE_NM[VISIBLE]`` is :data:`~simulator.spectra.grid.WAVELENGTHS_NM`
VISIBLE = slice(int(LAMBDA_MIN_NM - WIDE_MIN_NM), int(LAMBDA_MAX_NM - WIDE_MIN_NM) + 1)
assert np.array_equal(WIDE_NM[VISIBLE], WAVELENGTHS_NM)


@lru_cache(maxsize=16)
def _weights(lo: float, hi: float) -> np.ndarray:
    q = np.zeros_like(WIDE_NM)
    i0, i1 = int(lo - WIDE_MIN_NM), int(hi - WIDE_MIN_NM)
    q[i0:i1 + 1] = 1.0
    q[i0] = q[i1] = 0.5
    q.setflags(write=False)
    return q


def wide_weights(lo_nm: float = WIDE_MIN_NM, hi_nm: float = WIDE_MAX_NM) -> np.ndarray:
    """Trapezoid-rule quadrature vector over [lo, hi] (whole nm inside the wide grid), shape (801,)."""
    lo, hi = float(lo_nm), float(hi_nm)
    if not (WIDE_MIN_NM <= lo < hi <= WIDE_MAX_NM) or lo != int(lo) or hi != int(hi):
        raise ValueError(f"[{lo:g}, {hi:g}] nm is not whole nm inside {WIDE_MIN_NM:g}–{WIDE_MAX_NM:g} nm")
    return _weights(lo, hi)


def widen(visible: np.ndarray, outside: np.ndarray | None, lo_nm: float = WIDE_MIN_NM,
          hi_nm: float = WIDE_MAX_NM) -> np.ndarray:
    """A spectrum on the wide grid: ``visible`` (401 values) on 380–780 nm, ``outside`` (801 values, or
    None for 0) below and above, each side scaled so that it meets the visible part at 380 and 780 nm
    (where it is nonzero there), and 0 outside [lo, hi]."""
    out = np.zeros_like(WIDE_NM)
    out[VISIBLE] = np.asarray(visible, float)
    if outside is not None:
        o = np.asarray(outside, float)
        i0, i1 = VISIBLE.start, VISIBLE.stop - 1
        lo_scale = out[i0] / o[i0] if o[i0] > 0 else 1.0
        hi_scale = out[i1] / o[i1] if o[i1] > 0 else 1.0
        out[:i0] = o[:i0] * lo_scale
        out[i1 + 1:] = o[i1 + 1:] * hi_scale
    out[(WIDE_NM < lo_nm) | (WIDE_NM > hi_nm)] = 0.0
    out.setflags(write=False)
    return out


def cie_a_relative(wavelength_nm) -> np.ndarray:
    """CIE standard illuminant A, relative (100 at 560 nm), by its defining formula (CIE 15:2018 §3.1;
    ISO 10526/CIE S 005): S_A(λ) = 100 (560/λ)⁵ (exp(c₂/(2848·560)) − 1)/(exp(c₂/(2848·λ)) − 1),
    c₂ = 1.435e7 nm K."""
    lam = np.asarray(wavelength_nm, float)
    c2 = 1.435e7
    return 100.0 * (560.0 / lam) ** 5 * np.expm1(c2 / (2848.0 * 560.0)) / np.expm1(c2 / (2848.0 * lam))


#: CIE daylight illuminants and their correlated colour temperatures, K (CIE 15:2018 Table 1; nominal × 1.4388/1.4380)
DAYLIGHT_CCT_K = {"D50": 5003.0, "D55": 5503.0, "D65": 6504.0, "D75": 7504.0}


@lru_cache(maxsize=None)
def daylight_wide(name: str) -> np.ndarray:
    """A CIE daylight illuminant on the wide grid before joining (801 values): the D-series over
    300–830 nm from its chromaticity, the blackbody at its CCT beyond (scaled to meet it at 830 nm)."""
    import colour

    from simulator.spectra.planck import C2_CIE_M_K, planck_W_m2_sr_nm

    xy = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"][name]
    sd = colour.sd_CIE_illuminant_D_series(xy)
    inside = WIDE_NM <= 830.0
    out = np.zeros_like(WIDE_NM)
    out[inside] = np.asarray(sd[WIDE_NM[inside]], float)
    bb = planck_W_m2_sr_nm(DAYLIGHT_CCT_K[name], WIDE_NM, C2_CIE_M_K)
    i830 = int(830 - WIDE_MIN_NM)
    out[~inside] = bb[~inside] * out[i830] / bb[i830]
    return np.clip(out, 0.0, None)
