"""A sensor model's spectral side: its channels' responsivities, their calibration, f1′ and the mismatch factor.

Every channel has a relative spectral responsivity s(λ) on the wide grid
(300–1100 nm, :mod:`simulator.spectra.wide`): a responsivity CSV (the
format of ``output.responses``' custom files, read here over 300–1100 nm,
not cut to the visible) or a named function (``photopic``: V(λ); ``par``:
the ideal quantum response over 400–700 nm). A model reports one quantity
(:data:`QUANTITIES`: illuminance in lx, irradiance in W/m² over 380–780 nm,
PPFD in µmol m⁻² s⁻¹) and is *calibrated* under one illuminant at normal
incidence (``calibration = "A"``, the photometric convention): its first
channel then reads the true quantity of that illuminant. So channel c's
signal, for spectral irradiance E_λ arriving through the head's optics, is

    X_c = k_c ∫ E_λ s_c(λ) dλ,   k_c = ∫ S_cal q dλ / ∫ S_cal s_c dλ,

q the quantity's weighting (K_m V(λ) for lux). For a grey scene whose
emitters share the spectrum S, E_λ = E_W S(λ)/∫_{380}^{780} S dλ wherever the
light arrives (surfaces are grey beyond the visible too, the default this
module states), so X_c = E_W,optics · k_c ∫ S s_c / ∫_vis S.

Quality indices (ISO/CIE 19476:2014, CIE S 023/E:2013), for the first channel:

- f1′ = ∫ |s*(λ) − V(λ)| dλ / ∫ V(λ) dλ over 380–780 nm, with
  s*(λ) = s(λ) ∫ S_A V dλ / ∫ S_A s dλ (normalised under illuminant A);
- the spectral mismatch correction factor for a light of spectrum S_t,
  F = ∫ S_t V dλ · ∫ S_A s dλ / (∫ S_A V dλ · ∫ S_t s dλ): the true
  illuminance is F times the meter's reading. The V integrals run over
  380–780 nm (the photometric twin's grid), those of s over the whole wide
  grid (a meter reads its infrared too). F = 1 under A by construction.

References
----------
ISO/CIE 19476:2014, §5.3 (f1′) and §5.4 (spectral mismatch correction);
CIE 15:2018 (illuminant A); docs/REFERENCES.md §Sensor models.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from simulator.errors import UserError
from simulator.spectra.wide import VISIBLE, WIDE_MAX_NM, WIDE_MIN_NM, WIDE_NM, wide_weights

__all__ = ["QUANTITIES", "Quantity", "Channel", "named_responsivity", "responsivity_csv", "quantity_weights",
           "calibration_spectrum", "calibration_factor", "f1_prime", "mismatch_factor", "channel_ratio"]


@dataclass(frozen=True)
class Quantity:
    """What a model reports: its CSV column stem and unit, and its weighting's name."""

    name: str
    stem: str
    unit: str
    title: str


#: the quantities a model may report
QUANTITIES = {
    "illuminance": Quantity("illuminance", "illuminance", "lx", "illuminance (K_m V(λ), 380–780 nm)"),
    "irradiance": Quantity("irradiance", "irradiance", "W_m2", "irradiance (380–780 nm)"),
    "ppfd": Quantity("ppfd", "ppfd", "umol_m2_s", "PPFD (photons 400–700 nm)"),
}


@lru_cache(maxsize=None)
def quantity_weights(quantity: str) -> np.ndarray:
    """Quadrature vector q on the wide grid of a quantity (801,): ``q · S`` is the quantity of the
    spectral density S, equal to the transport's own integral on 380–780 nm (0 elsewhere)."""
    from simulator.spectra.responses import response

    name = {"illuminance": "photopic", "irradiance": "radiometric", "ppfd": "par"}[quantity]
    q = np.zeros_like(WIDE_NM)
    q[VISIBLE] = response(name).q
    q.setflags(write=False)
    return q


@lru_cache(maxsize=None)
def _v_visible() -> np.ndarray:
    from simulator.spectra.tables import photopic

    v = np.zeros_like(WIDE_NM)
    v[VISIBLE] = photopic()
    return v


@dataclass(frozen=True)
class Channel:
    """One channel: its relative responsivity on the wide grid and where it comes from.

    Attributes
    ----------
    name : str
    responsivity : ndarray, shape (801,)
        Relative, peak 1, 0 outside the source's range.
    source : str
        A file name or a function's name, for records.
    counts_per_unit : float or None
        Counts per unit of the model's quantity under the calibration illuminant at normal incidence, at
        the electronics' reference gain and integration time (None: no electronics).
    dark_counts_per_s : float
        Mean dark counts per second of integration.
    notes : tuple of str
    """

    name: str
    responsivity: np.ndarray
    source: str
    counts_per_unit: float | None = None
    dark_counts_per_s: float = 0.0
    notes: tuple[str, ...] = field(default=())


def named_responsivity(name: str) -> np.ndarray:
    """A responsivity by name on the wide grid: ``photopic`` (V(λ), an ideal photometer head) or
    ``par`` (the ideal quantum response: ∝ λ over 400–700 nm, peak 1). Each is its quantity's own
    quadrature vector over the wide grid's weights (halved at the ends of its range, as the trapezoid
    rule weighs them), so that it integrates to exactly the quantity: F = 1 under every light."""
    quantity = {"photopic": "illuminance", "par": "ppfd"}.get(name)
    if quantity is None:
        raise KeyError(name)
    q = quantity_weights(quantity)
    w = wide_weights()
    s = np.divide(q, w, out=np.zeros_like(q), where=w > 0)
    return s / s.max()


def _responsivity_column(name: str) -> str | None:
    if name == "responsivity" or (name.startswith("responsivity_") and name.endswith("_W")):
        return None
    return "'responsivity' (relative) or 'responsivity_<unit>_W'"


def responsivity_csv(path) -> tuple[np.ndarray, tuple[str, ...]]:
    """A channel's responsivity CSV (``wavelength_nm,responsivity``) on the wide grid, normalised to peak
    1, 0 outside the file's range; notes where the file stops short of 300–1100 nm or runs past it.

    Raises
    ------
    UserError
        One line naming the file and row (:func:`simulator.spectra.csvfile.read_spectral_csv`), or a
        responsivity 0 everywhere on 300–1100 nm.
    """
    from simulator.spectra.csvfile import read_spectral_csv

    t = read_spectral_csv(path, "responsivity", _responsivity_column, lambda y: None if y >= 0 else "is negative",
                          within_nm=(WIDE_MIN_NM, WIDE_MAX_NM))
    s = t.on_wide_grid()
    peak = float(s.max())
    if peak <= 0:
        raise UserError(f"{path}: responsivity is zero everywhere in 300–1100 nm")
    notes = []
    lo, hi = float(t.wavelength_nm[0]), float(t.wavelength_nm[-1])
    if lo > WIDE_MIN_NM or hi < WIDE_MAX_NM:
        notes.append(f"{t.path.name} covers {lo:g}–{hi:g} nm: 0 outside it")
    if lo < WIDE_MIN_NM or hi > WIDE_MAX_NM:
        notes.append(f"{t.path.name}: the part outside 300–1100 nm is not read")
    return s / peak, tuple(notes)


def calibration_spectrum(name: str):
    """The calibration illuminant (a :class:`simulator.spectra.sources.Spectrum`) by name: a CIE
    illuminant (``"A"``, ``"D65"``), a temperature, or ``"E"``."""
    from simulator.spectra.sources import emitter_spectrum

    return emitter_spectrum(name)


def calibration_factor(responsivity: np.ndarray, quantity: str, cal_wide: np.ndarray) -> float:
    """k = ∫ S_cal q / ∫ S_cal s: the factor that makes ``k ∫ E_λ s`` the true quantity under the
    calibration illuminant."""
    w = wide_weights()
    num = float(quantity_weights(quantity) @ cal_wide)
    den = float((responsivity * w) @ cal_wide)
    if den <= 0:
        raise UserError("the channel does not respond to its calibration illuminant (∫ S_cal s dλ = 0)")
    return num / den


def channel_ratio(responsivity: np.ndarray, light_wide: np.ndarray, light_visible: np.ndarray) -> float:
    """∫ S s dλ (wide) / ∫ S dλ (380–780 nm): the channel's raw response per radiometric watt of the light."""
    from simulator.spectra.grid import trapezoid_weights

    den = float(light_visible @ trapezoid_weights())
    return float((responsivity * wide_weights()) @ light_wide) / den if den > 0 else 0.0


def f1_prime(responsivity: np.ndarray) -> float:
    """f1′ (ISO/CIE 19476 §5.3.3) of a relative responsivity on the wide grid: see module docstring."""
    from simulator.spectra.sources import cie_illuminant

    a = cie_illuminant("A").on_wide_grid()
    wv = wide_weights(380, 780)
    v = _v_visible()
    s_star = responsivity * float((a * v) @ wv) / float((a * responsivity) @ wv)
    return float(np.abs(s_star - v) @ wv) / float(v @ wv)


def mismatch_factor(responsivity: np.ndarray, light_wide: np.ndarray, quantity: str = "illuminance",
                    cal_wide: np.ndarray | None = None) -> float:
    """The spectral mismatch correction factor F of a light (its spectrum on the wide grid) for a channel
    calibrated under ``cal_wide`` (default: illuminant A) to report ``quantity``: the true quantity is F
    × the channel's reading. For illuminance under A this is ISO/CIE 19476's F (see module docstring):
    F = ∫ S_t q · ∫ S_cal s / (∫ S_cal q · ∫ S_t s), the q integrals over 380–780 nm, those of s over
    the wide grid."""
    if cal_wide is None:
        from simulator.spectra.sources import cie_illuminant

        cal_wide = cie_illuminant("A").on_wide_grid()
    q, ww = quantity_weights(quantity), wide_weights()
    num = float(q @ light_wide) * float((cal_wide * responsivity) @ ww)
    den = float(q @ cal_wide) * float((light_wide * responsivity) @ ww)
    return num / den if den > 0 else float("nan")
