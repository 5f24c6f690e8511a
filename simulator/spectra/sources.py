"""Emission spectra: blackbody, CIE illuminants, an RGB light colour, measured SPD files.

An emission spectrum here is a *shape* on the grid: what a light's numbers
mean in absolute terms is set by the stage, through the UsdLux rule that
:func:`simulator.scene.usd.load_stage` documents. :func:`spectral_emission`
scales a shape so that its integrals are exactly the ``(radiometric,
photometric)`` pair :func:`simulator.units.emission_pair` gives the engine:

* ``light_units = "photometric"``: ``value`` is luminance (or intensity,
  illuminance), so ``S`` is scaled to ``K_m ∫ V S dλ = value``;
* ``light_units = "radiometric"``: ``value`` is W (per m² sr, …) within
  380–780 nm, so ``∫ S dλ = value``.

This is UsdLux's convention for ``colorTemperature``: the blackbody colour is
luminance-normalised, so the temperature changes the spectrum and never the
light's luminance. A light colour multiplies the (normalised) white spectrum
by its uplift (:func:`colour_emission`).

Notes
-----
Planck's law, spectral radiance per nanometre::

    B_λ(T) = 2 h c² / λ⁵ / (exp(h c / (λ k T)) − 1)  · 1e-9   [W m⁻² sr⁻¹ nm⁻¹, λ in m]

with the exact SI constants h = 6.62607015e-34 J s, c = 299792458 m/s,
k = 1.380649e-23 J/K (CODATA 2018 / SI 2019). A *colour temperature*
(:func:`blackbody`) uses CIE 15's second radiation constant c₂ = h c/k =
1.4388e-2 m K (the ITS-90 value, as colour-science and so the engine's
twin do) in place of the exact 1.438777e-2 m K: the shapes differ by at most
2e-4 over the grid and efficacies by 1.3e-5 (3000 K).

References
----------
Planck, M. (1901); CIE 15:2018 (illuminants); UsdLux "Quantities and units"
(OpenUSD documentation, LightAPI ``colorTemperature``).
"""

from __future__ import annotations

import difflib
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError
from simulator.spectra.grid import WAVELENGTHS_NM, integrate
from simulator.spectra.planck import C2_CIE_M_K, C_M_S, H_J_S, K_B_J_K, planck_W_m2_sr_nm
from simulator.units import K_M as _K_M

__all__ = [
    "H_J_S",
    "C_M_S",
    "K_B_J_K",
    "N_A_PER_MOL",
    "C2_CIE_M_K",
    "K_M_LM_W",
    "Spectrum",
    "planck_W_m2_sr_nm",
    "blackbody",
    "equal_energy",
    "cie_illuminant",
    "colour_emission",
    "spd_csv",
    "emitter_spectrum",
    "spectral_emission",
]

#: Avogadro constant, 1/mol (exact, SI 2019)
N_A_PER_MOL = 6.02214076e23
#: maximum luminous efficacy for photopic vision, lm/W: :data:`simulator.units.K_M` (683.002, CIE 018:2019)
K_M_LM_W = _K_M


@dataclass(frozen=True)
class Spectrum:
    """A spectral shape on the grid.

    Attributes
    ----------
    name : str
        What it is, for records: ``"D65"``, ``"blackbody 3000 K"``, a file name.
    values : ndarray, shape (401,)
        Non-negative relative spectral density on :data:`~simulator.spectra.grid.WAVELENGTHS_NM`.
    notes : tuple of str
        One-line notes (e.g. a file that does not cover 380–780 nm).
    wide : ndarray, shape (801,), or None
        The same shape on the wide grid, 300–1100 nm (:mod:`simulator.spectra.wide`), equal to
        ``values`` on 380–780 nm, 0 outside ``wide_range``; None: known on 380–780 nm only.
    wide_range : tuple of float
        Where ``wide`` is defined, nm (the rest of 300–1100 nm is 0 for want of data).
    """

    name: str
    values: np.ndarray
    notes: tuple[str, ...] = field(default=())
    wide: np.ndarray | None = None
    wide_range: tuple[float, float] = (380.0, 780.0)

    def on_wide_grid(self) -> np.ndarray:
        """The shape on the wide grid, shape (801,): :attr:`wide`, or the visible values with 0 outside."""
        if self.wide is not None:
            return self.wide
        from simulator.spectra.wide import widen

        return widen(self.values, None)

    @property
    def radiometric(self) -> float:
        """∫ S dλ over 380–780 nm."""
        return float(integrate(self.values))

    @property
    def photometric(self) -> float:
        """K_m ∫ V S dλ over 380–780 nm."""
        from simulator.spectra.tables import photopic

        return K_M_LM_W * float(integrate(self.values * photopic()))

    @property
    def efficacy_lm_W(self) -> float:
        """Luminous efficacy of radiation K(S), lm/W (as :func:`simulator.units.luminous_efficacy`)."""
        return self.photometric / self.radiometric


def _shape(name: str, values, notes=(), wide=None, wide_range=(380.0, 780.0)) -> Spectrum:
    v = np.asarray(values, dtype=np.float64).copy()
    v.setflags(write=False)
    return Spectrum(name, v, tuple(n for n in notes if n), wide, tuple(map(float, wide_range)))


def blackbody(temperature_K: float) -> Spectrum:
    """Planckian radiator of a colour temperature on the grid, W m⁻² sr⁻¹ nm⁻¹
    with CIE 15's c₂ (see module Notes; only its shape is used)."""
    t = float(temperature_K)
    if not (math.isfinite(t) and t > 0):
        raise ValueError(f"blackbody temperature must be a positive number of kelvin, not {temperature_K!r}")
    from simulator.spectra.wide import WIDE_MAX_NM, WIDE_MIN_NM, WIDE_NM, widen

    v = planck_W_m2_sr_nm(t, WAVELENGTHS_NM, C2_CIE_M_K)
    return _shape(f"blackbody {t:g} K", v, wide=widen(v, planck_W_m2_sr_nm(t, WIDE_NM, C2_CIE_M_K)),
                  wide_range=(WIDE_MIN_NM, WIDE_MAX_NM))


def equal_energy() -> Spectrum:
    """CIE illuminant E: a flat spectrum (probesim's default radiometric spectrum)."""
    from simulator.spectra.wide import WIDE_MAX_NM, WIDE_MIN_NM, WIDE_NM, widen

    return _shape("E", np.ones_like(WAVELENGTHS_NM), wide=widen(np.ones_like(WAVELENGTHS_NM), np.ones_like(WIDE_NM)),
                  wide_range=(WIDE_MIN_NM, WIDE_MAX_NM))


def cie_illuminant(name: str) -> Spectrum:
    """A CIE illuminant from colour-science's tables: ``D65``, ``A``, ``D50``, ``FL1``–``FL12``,
    ``FL3.1``–``FL3.15``, ``LED-B1``–``LED-B5``, ``LED-BH1``, ``LED-RGB1``, ``LED-V1``, ``LED-V2``, …

    Raises
    ------
    UserError
        An unknown name (with the closest known ones).
    """
    from simulator.spectra import tables

    if name == "E":
        return equal_energy()
    names = tables.illuminant_names()
    if name not in names:
        hint = difflib.get_close_matches(name, names, n=3)
        raise UserError(f"unknown illuminant {name!r}" + (f" (did you mean {', '.join(map(repr, hint))}?)" if hint else
                        " (expected a CIE illuminant such as 'D65', 'A', 'FL2', 'LED-B3')"))
    from simulator.spectra import wide as W

    v = tables.illuminant(name)
    if name == "A":  # defined by Planck's law at 2848 K (c₂ = 1.435e-2 m K): all of the wide grid
        return _shape(name, v, wide=W.widen(v, W.cie_a_relative(W.WIDE_NM)), wide_range=(W.WIDE_MIN_NM, W.WIDE_MAX_NM))
    if name in W.DAYLIGHT_CCT_K:  # the D-series to 830 nm, the blackbody at its CCT beyond
        return _shape(name, v, wide=W.widen(v, W.daylight_wide(name)), wide_range=(W.WIDE_MIN_NM, W.WIDE_MAX_NM))
    return _shape(name, v)


def colour_emission(rgb, base: Spectrum) -> Spectrum:
    """A coloured light: its white spectrum times the uplift of its linear sRGB ``color``.

    ``S_c(λ) = base(λ) · Σ_k c_k B_k(λ)`` with ``B`` the Mallett–Yuksel basis
    (:func:`simulator.spectra.reflectance.uplift` without the ≤ 1 bound: a
    light colour may exceed 1). Grey ``(c, c, c)`` gives ``c · base``
    exactly; ``(1, 1, 1)`` on a D65 base is D65.
    """
    from simulator.spectra.tables import mallett_basis

    c = np.asarray(rgb, float).reshape(3)
    if not np.all(np.isfinite(c)) or np.any(c < 0):
        raise UserError(f"light color {tuple(c)} must be three non-negative numbers")
    tint = c @ mallett_basis()
    wide = None
    if base.wide is not None:  # the uplift is defined on 380–780 nm: held at its end values beyond
        from simulator.spectra.wide import WIDE_NM, widen

        wide = widen(base.values * tint, base.wide * np.interp(WIDE_NM, WAVELENGTHS_NM, tint))
    return _shape(f"{base.name} × color ({c[0]:g}, {c[1]:g}, {c[2]:g})", base.values * tint, base.notes, wide,
                  base.wide_range)


def _spd_column(name: str) -> str | None:
    ok = name in ("relative_spd", "spd") or name.startswith("spd_") or name.startswith("spectral_")
    return None if ok else "'relative_spd', 'spd', 'spd_<unit>' or 'spectral_<quantity>_<unit>' (only the shape is used)"


def spd_csv(path) -> Spectrum:
    """A measured spectral power distribution from a CSV (see :mod:`simulator.spectra.csvfile`).

    The value column is ``relative_spd`` (or ``spd``, ``spd_<unit>``,
    ``spectral_<quantity>_<unit>``): only the shape is used, the stage sets
    the light's absolute value. Values must be non-negative; the spectrum is
    0 outside the file's range (noted), and must not be 0 everywhere.
    """
    from simulator.spectra.csvfile import read_spectral_csv

    t = read_spectral_csv(path, "SPD", _spd_column, lambda y: None if y >= 0 else "is negative")
    values = t.on_grid("zero")
    if not np.any(values > 0):
        raise UserError(f"{path}: SPD is zero everywhere in 380–780 nm")
    from simulator.spectra.wide import WIDE_MAX_NM, WIDE_MIN_NM, WIDE_NM, widen

    lo, hi = max(WIDE_MIN_NM, float(t.wavelength_nm[0])), min(WIDE_MAX_NM, float(t.wavelength_nm[-1]))
    wide = widen(values, np.interp(WIDE_NM, t.wavelength_nm, t.values, left=0.0, right=0.0), lo, hi)
    return _shape(Path(path).name, values, (t.coverage_note(),), wide, (lo, hi))


def emitter_spectrum(spec, base_dir: str | os.PathLike | None = None) -> Spectrum:
    """An emission spectrum from how a config or stage names it.

    Parameters
    ----------
    spec : str or float
        ``"E"``; a CIE illuminant name (``"D65"``, ``"A"``, ``"FL2"``,
        ``"LED-B3"``, …); a blackbody temperature as a number of kelvin or a
        string ``"3000K"`` / ``"blackbody:3000"``; or the path of an SPD CSV
        (ending ``.csv``, relative to ``base_dir``).
    base_dir : path, optional
        Folder relative paths are resolved against (a config's folder).

    Returns
    -------
    Spectrum
    """
    if isinstance(spec, bool):
        raise UserError(f"spectrum {spec!r}: expected a name, a temperature or a .csv file")
    if isinstance(spec, (int, float)):
        if not (math.isfinite(spec) and spec > 0):
            raise UserError(f"spectrum temperature must be a positive number of kelvin, not {spec!r}")
        return blackbody(float(spec))
    s = str(spec).strip()
    if s.lower().endswith(".csv"):
        p = Path(s)
        if base_dir is not None and not p.is_absolute():
            p = Path(base_dir) / p
        return spd_csv(p)
    low = s.lower()
    for prefix, suffix in (("blackbody:", ""), ("", "k")):
        if low.startswith(prefix) and low.endswith(suffix) and (prefix or suffix):
            body = low[len(prefix): len(low) - len(suffix)].strip()
            try:
                t = float(body)
            except ValueError:
                continue
            return emitter_spectrum(t)
    return cie_illuminant(s)


def spectral_emission(value: float, light_units: str, spectrum: Spectrum) -> np.ndarray:
    """The emitter's spectral density on the grid: ``spectrum`` scaled to the stated value.

    Parameters
    ----------
    value : float
        The stage's emission value (see :func:`simulator.units.emission_pair`).
    light_units : {"photometric", "radiometric"}
    spectrum : Spectrum

    Returns
    -------
    ndarray, shape (401,)
        Spectral radiance (W m⁻² sr⁻¹ nm⁻¹; or W sr⁻¹ nm⁻¹, W m⁻² nm⁻¹ as
        the light kind's value is) whose ``∫ dλ`` and ``K_m ∫ V dλ`` are the
        emission pair (see module docstring).
    """
    if light_units == "photometric":
        return spectrum.values * (value / spectrum.photometric)
    if light_units == "radiometric":
        return spectrum.values * (value / spectrum.radiometric)
    raise ValueError(f"light_units must be 'photometric' or 'radiometric', not {light_units!r}")
