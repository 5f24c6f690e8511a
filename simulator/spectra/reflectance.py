"""Reflectance spectra: RGB → spectrum uplift, and measured reflectance CSV files.

The uplift is Mallett & Yuksel's spectral primary decomposition (2019): three
basis spectra B_r, B_g, B_b, each non-negative and adding up to 1 at every
wavelength, fitted so that their linear sRGB round-trips under D65::

    ρ(λ) = r·B_r(λ) + g·B_g(λ) + b·B_b(λ).

Why this one: it is bounded by construction (``0 ≤ ρ(λ) ≤ max(r, g, b)`` for
``0 ≤ r, g, b``, so an albedo ≤ 1 stays ≤ 1 at every wavelength, which a
furnace needs), grey stays exactly grey (``(c, c, c) → c`` flat), and it is
linear: no per-colour optimisation, and the kernels could store three
numbers per material and expand them per band. The cost is breadth: its
spectra are smooth and broad, so very saturated sRGB colours come out less
saturated in a spectral sense than a measured paint. Jakob & Hanika (2019)
fits sharper spectra but needs a precomputed table per colour space and is
not linear. Measured reflectances (``reflectance.csv``) override either.

References
----------
Mallett, I. and Yuksel, C. (2019), "Spectral Primary Decomposition for
Rendering with sRGB Reflectance", Eurographics Symposium on Rendering, §3–4.
Jakob, W. and Hanika, J. (2019), "A Low-Dimensional Function Space for
Efficient Spectral Upsampling", Computer Graphics Forum 38(2).
"""

from __future__ import annotations

import numpy as np

__all__ = ["uplift", "rgb_of_reflectance", "reflectance_csv", "measured_reflectance", "reflectance_grey", "is_flat"]


def uplift(rgb) -> np.ndarray:
    """Reflectance spectrum of a linear sRGB albedo (Mallett & Yuksel 2019).

    Parameters
    ----------
    rgb : array_like, shape (3,) or (..., 3)
        Linear Rec. 709 / sRGB albedo, each in [0, 1].

    Returns
    -------
    ndarray, shape (401,) or (..., 401)
        ρ(λ) on the grid, ``0 ≤ ρ ≤ max(rgb)``.

    Raises
    ------
    ValueError
        A channel outside [0, 1] or not finite.
    """
    from simulator.spectra.tables import mallett_basis

    c = np.asarray(rgb, float)
    if c.shape[-1] != 3:
        raise ValueError(f"expected RGB triples, got shape {c.shape}")
    if not np.all(np.isfinite(c)) or np.any(c < 0) or np.any(c > 1):
        raise ValueError(f"albedo colour {c.tolist()} must have every channel in [0, 1]")
    return c @ mallett_basis()


def rgb_of_reflectance(rho: np.ndarray) -> np.ndarray:
    """Linear sRGB of a reflectance seen under D65 by the CIE 1931 2° observer (white → (1, 1, 1)).

    ``XYZ = ∫ ρ D65 (x̄, ȳ, z̄) dλ / ∫ D65 ȳ dλ``, then the IEC 61966-2-1
    XYZ → linear sRGB matrix (colour-science's). Used to measure the uplift's
    round trip.
    """
    import colour

    from simulator.spectra import tables
    from simulator.spectra.grid import integrate

    d65 = tables.illuminant("D65")
    cmfs = tables.cmfs_1931()
    xyz = integrate(np.asarray(rho, float)[..., None, :] * d65 * cmfs) / integrate(d65 * cmfs[1])
    m = np.asarray(colour.models.RGB_COLOURSPACE_sRGB.matrix_XYZ_to_RGB, float)
    return xyz @ m.T


def _reflectance_column(name: str) -> str | None:
    return None if name in ("reflectance", "reflectance_percent") else "'reflectance' (0–1) or 'reflectance_percent' (0–100)"


def reflectance_csv(path, notes: list | None = None) -> np.ndarray:
    """A measured reflectance on the grid, from a CSV (see :mod:`simulator.spectra.csvfile`).

    Column ``reflectance`` (a fraction) or ``reflectance_percent``; every
    value must be in [0, 1) (energy conservation, as for a grey albedo).
    Beyond the file's range the end values are held (a file need not cover
    380–780 nm; ``notes`` gets a one-line note when it does not).

    Parameters
    ----------
    path : path
    notes : list, optional
        Appended: the coverage note (:meth:`SpectralTable.coverage_note`), if any.

    Returns
    -------
    ndarray, shape (401,)
    """
    from simulator.spectra.csvfile import read_spectral_csv

    scale = {"reflectance": 1.0, "reflectance_percent": 0.01}
    chosen: dict[str, float] = {}  # the column's scale, known once the header is read

    def columns(name):
        why = _reflectance_column(name)
        if why is None:
            chosen["scale"] = scale[name]
        return why

    def check(y):
        s = chosen["scale"]
        return None if 0.0 <= y * s < 1.0 else f"is outside [0, {1.0 / s:g}) (energy conservation)"

    table = read_spectral_csv(path, "reflectance", columns, check)
    note = table.coverage_note()
    if notes is not None and note is not None:
        notes.append(note + " (end values held beyond it)")
    return table.on_grid("hold") * chosen["scale"]


def reflectance_grey(rho) -> float:
    """The luminance-weighted grey of a reflectance: ``∫ ρ D65 ȳ dλ / ∫ D65 ȳ dλ``.

    The albedo one-channel transport (and Russian roulette) uses for a
    measured reflectance: the Y of its colour under D65, the sRGB white,
    as a ``diffuseColor``'s BT.709 grey is the Y of its colour. It does
    not depend on the run's emitter spectrum, so a stage's greys are the
    same in every run; a flat ρ = c gives exactly c.

    Parameters
    ----------
    rho : array_like, shape (401,)

    Returns
    -------
    float
    """
    from simulator.spectra import tables
    from simulator.spectra.grid import integrate

    w = tables.illuminant("D65") * tables.cmfs_1931()[1]
    return float(integrate(np.asarray(rho, float) * w) / integrate(w))


def is_flat(rho, rel: float = 1e-9) -> bool:
    """True when a reflectance is the same at every grid wavelength (to ``rel`` of its largest value)."""
    r = np.asarray(rho, float)
    return bool(np.ptp(r) <= rel * max(float(np.max(np.abs(r))), 1e-300))


def measured_reflectance(path) -> tuple[np.ndarray, float, list[str]]:
    """A material's measured reflectance: ``(ρ on the grid (401,), its grey, notes)``.

    ``ρ`` from :func:`reflectance_csv` (values in [0, 1), end values held
    beyond the file's range, with a note); the grey is
    :func:`reflectance_grey`, exactly the value for a flat file.
    """
    notes: list[str] = []
    rho = reflectance_csv(path, notes)
    grey = float(rho[0]) if is_flat(rho) else reflectance_grey(rho)
    return rho, grey, notes
