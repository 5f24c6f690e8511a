"""The two-column spectral CSV every measured file uses (SPD, reflectance, responsivity).

Format::

    # comment lines start with '#'; blank lines are skipped
    wavelength_nm,<value column>
    400,0.012
    405,0.015
    ...

The first column is the wavelength in nanometres, strictly increasing; the
second column's header names the quantity and its unit (for example
``relative_spd``, ``reflectance``, ``responsivity_A_W``); what a header may
be is up to the caller. Quoted cells and trailing empty cells (as
spreadsheets export them) are accepted. Every problem is one :class:`UserError` line naming
the file and line: ``diode.csv:7: wavelength 455 nm is not above the previous (460 nm)``.
On the grid the values are linearly interpolated; outside the file's range
they are 0 (emission, responsivity) or held at the end value (reflectance),
as the caller asks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from simulator.errors import UserError, require_file
from simulator.spectra.grid import WAVELENGTHS_NM

__all__ = ["SpectralTable", "read_spectral_csv"]

#: wavelengths a file may state, nm (ultraviolet C to short-wave infrared)
_WAVELENGTH_RANGE_NM = (100.0, 3000.0)


@dataclass(frozen=True)
class SpectralTable:
    """A validated two-column file.

    Attributes
    ----------
    path : Path
    column : str
        The value column's header, e.g. ``responsivity_A_W``.
    wavelength_nm : ndarray, shape (m,)
    values : ndarray, shape (m,)
    """

    path: Path
    column: str
    wavelength_nm: np.ndarray
    values: np.ndarray

    def on_grid(self, outside: str = "zero") -> np.ndarray:
        """The values linearly interpolated onto :data:`~simulator.spectra.grid.WAVELENGTHS_NM`.

        Parameters
        ----------
        outside : {"zero", "hold"}
            What the grid gets beyond the file's range: 0, or the end values.

        Returns
        -------
        ndarray, shape (401,)
        """
        if outside not in ("zero", "hold"):
            raise ValueError(f"outside must be 'zero' or 'hold', not {outside!r}")
        fill = (0.0, 0.0) if outside == "zero" else (self.values[0], self.values[-1])
        return np.interp(WAVELENGTHS_NM, self.wavelength_nm, self.values, left=fill[0], right=fill[1])

    def on_wide_grid(self) -> np.ndarray:
        """The values linearly interpolated onto the wide grid, 300–1100 nm (:mod:`simulator.spectra.wide`),
        0 beyond the file's range; shape (801,)."""
        from simulator.spectra.wide import WIDE_NM

        return np.interp(WIDE_NM, self.wavelength_nm, self.values, left=0.0, right=0.0)

    def coverage_note(self) -> str | None:
        """A one-line note when the file does not cover 380–780 nm, else None."""
        lo, hi = float(self.wavelength_nm[0]), float(self.wavelength_nm[-1])
        if lo <= WAVELENGTHS_NM[0] and hi >= WAVELENGTHS_NM[-1]:
            return None
        return f"{self.path.name} covers {lo:g}–{hi:g} nm, not all of 380–780 nm"


def read_spectral_csv(path, what: str, columns: Callable[[str], str | None],
                      check: Callable[[float], str | None] | None = None,
                      within_nm: tuple[float, float] = (380.0, 780.0)) -> SpectralTable:
    """Read and validate a two-column spectral CSV.

    Parameters
    ----------
    path : str or Path
    what : str
        What the file is, for messages (``"SPD"``, ``"reflectance"``, …).
    columns : callable
        Given the value column's header, returns None if it is accepted,
        else what was expected (one phrase, for the message).
    check : callable, optional
        Given one value, returns None if it is acceptable, else the reason.
    within_nm : (float, float)
        The range the file must overlap, nm: the visible grid, or a sensor model's wide grid.

    Returns
    -------
    SpectralTable

    Raises
    ------
    UserError
        ``"<path>:<line>: <what is wrong>"`` (or ``"<path>: ..."`` for the
        file as a whole): missing file, bad header, a row that is not two
        finite numbers, wavelengths not increasing or outside 100–3000 nm, a
        value ``check`` rejects, fewer than two rows, no overlap with 380–780 nm.
    """
    p = require_file(path)
    try:
        text = p.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as e:
        raise UserError(f"{path}: cannot read {what} file: {e}") from None
    header: str | None = None
    wl: list[float] = []
    vals: list[float] = []
    for n, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        cells = [c.strip().strip('"').strip() for c in line.split(",")]
        while len(cells) > 2 and cells[-1] == "":  # spreadsheet exports pad rows with empty cells
            cells.pop()
        if header is None:
            if len(cells) != 2 or cells[0] != "wavelength_nm":
                raise UserError(f"{path}:{n}: {what} header must be 'wavelength_nm,<column>', not {line!r}")
            expected = columns(cells[1])
            if expected is not None:
                raise UserError(f"{path}:{n}: {what} column {cells[1]!r}: expected {expected}")
            header = cells[1]
            continue
        if len(cells) != 2:
            raise UserError(f"{path}:{n}: expected 2 values (wavelength_nm, {header}), got {len(cells)}")
        try:
            x, y = float(cells[0]), float(cells[1])
        except ValueError:
            raise UserError(f"{path}:{n}: not a number in {line!r}") from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise UserError(f"{path}:{n}: values must be finite, got {line!r}")
        if not (_WAVELENGTH_RANGE_NM[0] <= x <= _WAVELENGTH_RANGE_NM[1]):
            raise UserError(f"{path}:{n}: wavelength {x:g} nm is outside {_WAVELENGTH_RANGE_NM[0]:g}–"
                            f"{_WAVELENGTH_RANGE_NM[1]:g} nm (is the column in nm?)")
        if wl and x <= wl[-1]:
            raise UserError(f"{path}:{n}: wavelength {x:g} nm is not above the previous ({wl[-1]:g} nm)")
        if check is not None:
            why = check(y)
            if why is not None:
                raise UserError(f"{path}:{n}: {header} {y:g} {why}")
        wl.append(x)
        vals.append(y)
    if header is None:
        raise UserError(f"{path}: empty {what} file (expected a 'wavelength_nm,<column>' header and rows)")
    if len(wl) < 2:
        raise UserError(f"{path}: {what} file needs at least 2 rows, has {len(wl)}")
    if wl[-1] <= within_nm[0] or wl[0] >= within_nm[1]:
        raise UserError(f"{path}: {what} covers {wl[0]:g}–{wl[-1]:g} nm, outside {within_nm[0]:g}–{within_nm[1]:g} nm")
    return SpectralTable(p, header, np.array(wl), np.array(vals))
