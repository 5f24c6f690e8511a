"""Measured spectral transmittance of glazing: a CSV for spectral runs, as reflectances are read.

A material's ``probesim:transmittance`` is either a number (the datasheet's
normal-incidence visible transmittance T0) or the path of a two-column CSV
(:mod:`simulator.spectra.csvfile`) of the pane's normal-incidence
transmittance T0(λ): column ``transmittance`` (0–1) or
``transmittance_percent`` (0–100), end values held beyond the file's range.
Grey transport uses its luminance-weighted grey (the Y under D65, as a
measured reflectance's grey, :func:`simulator.spectra.reflectance.reflectance_grey`),
exactly the value of a flat file; spectral runs read T0(λ_k) per hero lane.
"""

from __future__ import annotations

import numpy as np

__all__ = ["transmittance_csv", "measured_transmittance"]

_SCALES = {"transmittance": 1.0, "transmittance_percent": 0.01}


def transmittance_csv(path, notes: list | None = None) -> np.ndarray:
    """A measured normal-incidence transmittance on the grid, shape (401,), every value in [0, 1].

    Raises
    ------
    UserError
        The file's own problems, one line naming file and line (a value outside [0, 1] among them).
    """
    from simulator.spectra.csvfile import read_spectral_csv

    chosen: dict[str, float] = {}

    def columns(name):
        if name in _SCALES:
            chosen["scale"] = _SCALES[name]
            return None
        return "'transmittance' (0–1) or 'transmittance_percent' (0–100)"

    def check(y):
        s = chosen["scale"]
        return None if 0.0 <= y * s <= 1.0 else f"is outside [0, {1.0 / s:g}]"

    table = read_spectral_csv(path, "transmittance", columns, check)
    note = table.coverage_note()
    if notes is not None and note is not None:
        notes.append(note + " (end values held beyond it)")
    return table.on_grid("hold") * chosen["scale"]


def measured_transmittance(path) -> tuple[np.ndarray, float, list[str]]:
    """``(T0(λ) on the grid (401,), its grey, notes)`` of a transmittance CSV (module docstring)."""
    from simulator.spectra.reflectance import is_flat, reflectance_grey

    notes: list[str] = []
    t = transmittance_csv(path, notes)
    grey = float(t[0]) if is_flat(t) else reflectance_grey(t)
    return t, grey, notes
