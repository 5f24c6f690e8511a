"""Sensor responses: what a reading is reported as (W, lx, µmol m⁻² s⁻¹, melanopic EDI, a photodiode …).

A :class:`Response` is a linear functional of a spectral quantity: a
quadrature vector ``q`` on the grid such that the response of a spectral
irradiance ``E_λ`` (W m⁻² nm⁻¹, sampled on the grid) is ``q · E_λ``. The same
``q`` applies to spectral radiance or flux; only the unit changes, so each
response names a CSV column stem and unit per quantity (irradiance, radiance,
flux). Columns follow the CSV's pattern: ``<stem>_<unit>`` and
``<stem>_stderr_<unit>``.

Registry (:func:`response`, :data:`NAMES`): name, weighting q(λ) (trapezoid
rule on the 1 nm grid), irradiance column:

* ``radiometric``: 1 over 380–780 nm; ``irradiance_W_m2``
* ``photopic``: K_m V(λ), K_m = 683.002 lm/W (CIE 018:2019); ``illuminance_lx``
* ``scotopic``: K′_m V′(λ), K′_m = 1700.06 lm/W; ``scotopic_illuminance_lx``
* ``<α>``: s_α(λ), the CIE S 026 action spectrum; S 026's names,
  ``s_cone_opic_irradiance_W_m2`` … ``rhodopic_irradiance_W_m2``,
  ``melanopic_irradiance_W_m2``
* ``<α>_edi``: s_α(λ) / K_α,v^D65; ``<α>_edi_lx`` (``s_cone_edi_lx`` …
  ``melanopic_edi_lx``)
* ``par``: λ/(h c N_A)·1e6 over 400–700 nm (photons); ``ppfd_umol_m2_s``
* ``epar``: the same over 400–750 nm; ``eppfd_umol_m2_s``
* custom: a responsivity CSV (:func:`custom_response`); ``<name>_<unit>``

with α one of ``s_cone``, ``m_cone``, ``l_cone``, ``rhodopic``, ``melanopic``.

Notes
-----
*Scotopic.* K′_m = 1700.06 lm/W is the CIE value (CIE S 010/E:2004 =
ISO 23539:2005; CIE 018:2019): K_cd/V′(555.016 nm), K_cd = 683 lm/W the
SI's efficacy at 540 THz, the scotopic efficacy that makes photopic and
scotopic lumens agree there (as K_m = K_cd/V(555.016 nm) = 683.002 lm/W
does for photopic). The older figure 1699 lm/W is 683/V′(555 nm) with V′
read at 555 nm; they differ by 0.06 %.

*α-opic (CIE S 026:2018).* α-opic irradiance ``E_α = ∫ E_λ s_α(λ) dλ``
(W m⁻²). Its α-opic equivalent daylight (D65) illuminance ``E_α,v^D65 =
E_α / K_α,v^D65``, where the α-opic efficacy of luminous radiation (ELR) of
D65 is ``K_α,v^D65 = ∫ s_α D65 dλ / (K_m ∫ V D65 dλ)`` (W/lm). The ELRs are
computed from the tables (:func:`d65_elr_W_lm`), not typed in: 0.81729,
1.45583, 1.62891, 1.44971, 1.32621 mW/lm (S-, M-, L-cone, rhodopic,
melanopic), matching S 026 Table 2's 0.8173, 1.4558, 1.6289, 1.4497,
1.3262 mW/lm. By this definition D65 has EDI = illuminance for every α.

*PAR photon flux.* A photon of wavelength λ carries h c/λ, so E_λ dλ watts
are E_λ λ/(h c) photons per second and E_λ λ/(h c N_A)·1e6 µmol/s. PAR is
400–700 nm (McCree 1972; ASABE S640), ePAR 400–750 nm (Zhen & Bugbee 2020).

References
----------
CIE S 026/E:2018, "CIE System for Metrology of Optical Radiation for
ipRGC-Influenced Responses to Light", §3 and Table 2. CIE 018:2019, "The
Basis of Physical Photometry". ASABE S640 (2017), "Quantities and Units of
Electromagnetic Radiation for Plants". Zhen, S. and Bugbee, B. (2020), Plant,
Cell & Environment 43(5), 1259–1272.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from simulator.errors import UserError
from simulator.spectra.grid import WAVELENGTHS_NM, trapezoid_weights
from simulator.spectra.sources import C_M_S, H_J_S, K_M_LM_W, N_A_PER_MOL

__all__ = [
    "QUANTITIES",
    "K_PRIME_M_LM_W",
    "ALPHA_OPIC",
    "NAMES",
    "Response",
    "response",
    "d65_elr_W_lm",
    "photon_weights_umol_J",
    "custom_response",
]

#: the quantities a reading can be: what the sensor kinds of the CSV report
QUANTITIES = ("irradiance", "radiance", "flux")
#: maximum luminous efficacy for scotopic vision, lm/W (CIE; see module Notes)
K_PRIME_M_LM_W = 1700.06
#: CIE S 026 photoreceptor names, in the standard's order
ALPHA_OPIC = ("s_cone", "m_cone", "l_cone", "rhodopic", "melanopic")
_ALPHA_TITLE = {"s_cone": "S-cone-opic", "m_cone": "M-cone-opic", "l_cone": "L-cone-opic",
                "rhodopic": "rhodopic", "melanopic": "melanopic"}
_ALPHA_STEM = {"s_cone": "s_cone_opic", "m_cone": "m_cone_opic", "l_cone": "l_cone_opic",
               "rhodopic": "rhodopic", "melanopic": "melanopic"}
#: registry names :func:`response` accepts (custom responses come from CSV files)
NAMES = ("radiometric", "photopic", "scotopic", *ALPHA_OPIC, *(f"{a}_edi" for a in ALPHA_OPIC), "par", "epar")

_NAME_RE = re.compile(r"^[a-z][a-z0-9_]{0,39}$")


@dataclass(frozen=True)
class Response:
    """One sensor response.

    Attributes
    ----------
    name : str
        Registry or custom name (``photopic``, ``par``, ``diode``).
    title : str
        Human name, for map titles: ``"PPFD"``, ``"illuminance"``.
    q : ndarray, shape (401,)
        Quadrature vector: response of a spectral density f on the grid is ``q · f``.
    stems : dict of str to str
        Column stem per quantity (``irradiance`` → ``ppfd``).
    units : dict of str to str
        Column unit per quantity (``irradiance`` → ``umol_m2_s``), as the
        CSV's names spell units (``_`` for ``/`` and products).
    source : str
        Where the weighting comes from (standard, file).
    notes : tuple of str
    """

    name: str
    title: str
    q: np.ndarray
    stems: dict[str, str]
    units: dict[str, str]
    source: str = ""
    notes: tuple[str, ...] = field(default=())

    def columns(self, quantity: str) -> tuple[str, str]:
        """``(value column, stderr column)`` of a quantity, e.g. ``("ppfd_umol_m2_s", "ppfd_stderr_umol_m2_s")``.

        ``quantity`` is one of :data:`QUANTITIES` or ``"scalar_irradiance"``
        (a probe's fluence rate: ``scalar_`` + the irradiance stem, e.g.
        ``scalar_ppfd_umol_m2_s``, ``scalar_illuminance_lx``).
        """
        if quantity == "scalar_irradiance":
            stem, unit = "scalar_" + self.stems["irradiance"], self.units["irradiance"]
            return f"{stem}_{unit}", f"{stem}_stderr_{unit}"
        stem, unit = self.stems[quantity], self.units[quantity]
        return f"{stem}_{unit}", f"{stem}_stderr_{unit}"

    def of(self, spectral: np.ndarray) -> np.ndarray:
        """Response of spectral densities on the grid, shape (..., 401) → (...)."""
        return np.asarray(spectral, float) @ self.q


def _frozen(a) -> np.ndarray:
    a = np.array(a, dtype=np.float64)
    a.setflags(write=False)
    return a


def _quantities(irr: tuple[str, str], rad: tuple[str, str], flux: tuple[str, str]) -> tuple[dict, dict]:
    pairs = dict(zip(QUANTITIES, (irr, rad, flux)))
    return {k: v[0] for k, v in pairs.items()}, {k: v[1] for k, v in pairs.items()}


def _alpha_spectrum(alpha: str) -> np.ndarray:
    from simulator.spectra import tables

    if alpha == "rhodopic":
        return tables.scotopic()
    if alpha == "melanopic":
        return tables.melanopic()
    l, m, s = tables.cone_fundamentals()
    return {"l_cone": l, "m_cone": m, "s_cone": s}[alpha]


@lru_cache(maxsize=None)
def d65_elr_W_lm(alpha: str) -> float:
    """α-opic efficacy of luminous radiation of D65, K_α,v^D65, W/lm (CIE S 026 §3.4; see module Notes)."""
    from simulator.spectra import tables

    d65 = tables.illuminant("D65")
    full = trapezoid_weights()
    return float((full * _alpha_spectrum(alpha)) @ d65 / (K_M_LM_W * (full * tables.photopic()) @ d65))


def photon_weights_umol_J(lo_nm: float, hi_nm: float) -> np.ndarray:
    """Quadrature vector of photon flux over [lo, hi]: ``q · E_λ`` in µmol s⁻¹ per W … (see Notes).

    ``q_i = w_i · λ_i·1e-9 / (h c N_A) · 1e6`` with ``w`` the trapezoid
    weights over [lo, hi] (nm), λ in m: µmol per joule at each wavelength.
    """
    return trapezoid_weights(lo_nm, hi_nm) * (WAVELENGTHS_NM * 1e-9 / (H_J_S * C_M_S * N_A_PER_MOL) * 1e6)


@lru_cache(maxsize=None)
def response(name: str) -> Response:
    """A registry response by name (see module table).

    Raises
    ------
    KeyError
        Not a registry name (:data:`NAMES`).
    """
    from simulator.spectra import tables

    full = trapezoid_weights()
    if name == "radiometric":
        s, u = _quantities(("irradiance", "W_m2"), ("radiance", "W_m2_sr"), ("flux", "W"))
        return Response(name, "irradiance", _frozen(full), s, u, "∫ dλ over 380–780 nm")
    if name == "photopic":
        s, u = _quantities(("illuminance", "lx"), ("luminance", "cd_m2"), ("luminous_flux", "lm"))
        return Response(name, "illuminance", _frozen(K_M_LM_W * tables.photopic() * full), s, u,
                        "K_m V(λ), CIE 1924 photopic, K_m = 683.002 lm/W (CIE 018:2019)")
    if name == "scotopic":
        s, u = _quantities(("scotopic_illuminance", "lx"), ("scotopic_luminance", "cd_m2"), ("scotopic_luminous_flux", "lm"))
        return Response(name, "scotopic illuminance", _frozen(K_PRIME_M_LM_W * tables.scotopic() * full), s, u,
                        "K'_m V'(λ), CIE 1951 scotopic, K'_m = 1700.06 lm/W (CIE 018:2019)")
    if name in ALPHA_OPIC:
        stem, title = _ALPHA_STEM[name], _ALPHA_TITLE[name]
        s, u = _quantities((f"{stem}_irradiance", "W_m2"), (f"{stem}_radiance", "W_m2_sr"), (f"{stem}_flux", "W"))
        return Response(name, f"{title} irradiance", _frozen(_alpha_spectrum(name) * full), s, u,
                        f"CIE S 026:2018 {title} action spectrum")
    if name.endswith("_edi") and name[:-4] in ALPHA_OPIC:
        alpha = name[:-4]
        base = _ALPHA_STEM[alpha].replace("_opic", "")
        s, u = _quantities((f"{base}_edi", "lx"), (f"{base}_edl", "cd_m2"), (f"{base}_ed_flux", "lm"))
        k = d65_elr_W_lm(alpha)
        return Response(name, f"{_ALPHA_TITLE[alpha]} EDI", _frozen(_alpha_spectrum(alpha) * full / k), s, u,
                        f"CIE S 026:2018 {_ALPHA_TITLE[alpha]} equivalent daylight (D65) illuminance, "
                        f"K_α,v^D65 = {1e3 * k:.5f} mW/lm")
    if name == "par":
        s, u = _quantities(("ppfd", "umol_m2_s"), ("par_photon_radiance", "umol_m2_s_sr"), ("ppf", "umol_s"))
        return Response(name, "PPFD", _frozen(photon_weights_umol_J(400, 700)), s, u,
                        "photons 400–700 nm, E_λ λ/(h c N_A) (ASABE S640)")
    if name == "epar":
        s, u = _quantities(("eppfd", "umol_m2_s"), ("epar_photon_radiance", "umol_m2_s_sr"), ("eppf", "umol_s"))
        return Response(name, "ePPFD", _frozen(photon_weights_umol_J(400, 750)), s, u,
                        "photons 400–750 nm, E_λ λ/(h c N_A) (Zhen & Bugbee 2020)")
    raise KeyError(name)


_UNIT_RE = re.compile(r"^responsivity_([A-Za-z][A-Za-z0-9]*)_W$")


def _responsivity_column(name: str) -> str | None:
    if name == "responsivity" or _UNIT_RE.match(name):
        return None
    return "'responsivity' (relative: peak-normalised) or 'responsivity_<unit>_W' (absolute, e.g. responsivity_A_W)"


def custom_response(path, name: str) -> Response:
    """A response from a responsivity CSV (a photodiode datasheet).

    Parameters
    ----------
    path : str or Path
        Two columns (see :mod:`simulator.spectra.csvfile`): ``wavelength_nm``
        and either

        * ``responsivity``: *relative* (any scale). It is normalised to peak
          1, so the reading is a responsivity-weighted radiometric value in
          W m⁻² (W m⁻² sr⁻¹, W): what the datasheet's relative curve times a
          flat 1 A/W … would read. Columns ``<name>_W_m2`` etc.
        * ``responsivity_<U>_W`` (``A_W``, ``V_W``, ``lm_W``): *absolute*, U
          per watt, used as is. The reading is in U m⁻² for irradiance (a
          photocurrent density: times the detector's area gives its current),
          U m⁻² sr⁻¹ for radiance and U for flux. Columns ``<name>_<U>_m2`` etc.

        Values must be ≥ 0; the responsivity is 0 outside the file's range
        (noted) and is linearly interpolated within it.
    name : str
        Column stem: lower case letters, digits and ``_``, starting with a
        letter, at most 40 characters, not a registry name.

    Raises
    ------
    UserError
        A bad name, or any problem with the file (one line naming file and line).
    """
    from simulator.spectra.csvfile import read_spectral_csv

    if not _NAME_RE.match(name):
        raise UserError(f"custom response name {name!r} must be lower-case letters, digits and '_', "
                        "starting with a letter (at most 40 characters)")
    if name in NAMES:
        raise UserError(f"custom response name {name!r} is a built-in response; choose another")
    t = read_spectral_csv(path, "responsivity", _responsivity_column,
                          lambda y: None if y >= 0 else "is negative")
    r = t.on_grid("zero")
    from simulator.spectra.wide import wide_weights

    wide = t.on_wide_grid() @ wide_weights()
    outside = 1.0 - float(t.on_wide_grid() @ wide_weights(380, 780)) / wide if wide > 0 else 0.0
    cut = None
    if outside > 1e-3:  # said, not silent: the columns integrate over the transport's grid
        cut = (f"{t.path.name}: {100 * outside:.1f}% of its responsivity (integrated flat) lies outside 380–780 nm "
               "and is left out of its response columns, which integrate over 380–780 nm; a sensor model "
               "(docs/sensors.md) reads 300–1100 nm")
    peak = float(r.max())
    if peak <= 0:
        raise UserError(f"{path}: responsivity is zero everywhere in 380–780 nm")
    m = _UNIT_RE.match(t.column)
    full = trapezoid_weights()
    if m is None:
        r = r / peak
        s, u = _quantities((name, "W_m2"), (name, "W_m2_sr"), (name, "W"))
        how = f"relative responsivity from {t.path.name}, normalised to peak 1 (raw peak {peak:g})"
    else:
        unit = m.group(1)
        s, u = _quantities((name, f"{unit}_m2"), (name, f"{unit}_m2_sr"), (name, unit))
        how = f"absolute responsivity from {t.path.name}, {unit}/W"
    custom = Response(name, name, _frozen(r * full), s, u, how, tuple(n for n in (t.coverage_note(), cut) if n))
    taken = _registry_columns()
    for quantity in QUANTITIES + ("scalar_irradiance",):
        col = custom.columns(quantity)[0]
        if col in taken:
            raise UserError(f"custom response name {name!r} would write column {col!r}, which {taken[col]!r} writes; "
                            "choose another name")
    return custom


@lru_cache(maxsize=None)
def _registry_columns() -> dict[str, str]:
    """Every column a registry response writes → the response's name."""
    return {c: n for n in NAMES for q in QUANTITIES + ("scalar_irradiance",) for c in response(n).columns(q)}
