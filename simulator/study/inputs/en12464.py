"""The EN 12464-1 calculation grid: spacing from the area's size, points at cell centres.

Notes
-----
The maximum grid spacing for an area whose relevant dimension is ``d``
metres is

.. math:: p = 0.2 \\cdot 5^{\\log_{10} d}, \\qquad p \\le 10\\ \\text{m},

where ``d`` is the longer side of the (rectangular) calculation area,
unless the longer side is two or more times the shorter one, in which case
``d`` is the shorter side. The number of points along the relevant
dimension is the whole number nearest to ``d / p``; the spacing that gives
is used to find the nearest whole number of points along the other side,
so that cells stay close to square; a cell's length-to-width ratio must
stay between 0.5 and 2. Points lie at the cell centres. Worked values of
the formula: p = 0.2 m for d = 1 m, 0.6 m (0.615) for 5 m, 1 m for 10 m,
3 m (3.08) for 50 m, 5 m for 100 m.

References
----------
EN 12464-1:2011, Light and lighting — Lighting of work places — Part 1:
Indoor work places, §4.4 (illuminance grid) and its table of typical grid
spacings; EN 12464-1:2021 keeps the formula.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["grid_spacing_m", "Grid", "en12464_grid", "explicit_grid"]

#: largest spacing the rule allows, metres
MAX_SPACING_M = 10.0
#: the cell aspect ratio the standard allows
MIN_ASPECT, MAX_ASPECT = 0.5, 2.0


def grid_spacing_m(d_m: float) -> float:
    """Maximum grid spacing ``p = 0.2 · 5^log10(d)`` (metres), at most 10 m.

    Parameters
    ----------
    d_m : float
        Relevant dimension of the calculation area, metres (> 0).
    """
    if not d_m > 0.0:
        raise ValueError(f"d must be > 0, got {d_m}")
    return min(0.2 * 5.0 ** math.log10(d_m), MAX_SPACING_M)


@dataclass(frozen=True)
class Grid:
    """Cell-centre grid over a ``length × width`` rectangle.

    Attributes
    ----------
    n_u, n_v : int
        Points along the length (u) and the width (v).
    pitch_u_m, pitch_v_m : float
        Cell size along u and v, metres (= side / points).
    relevant_d_m : float
        The ``d`` the spacing rule used (0 for an explicit spacing).
    max_spacing_m : float
        ``p`` from the rule, or the explicit spacing.
    """

    n_u: int
    n_v: int
    pitch_u_m: float
    pitch_v_m: float
    relevant_d_m: float
    max_spacing_m: float

    def centres(self) -> list[tuple[float, float]]:
        """Cell centres ``(u, v)`` in metres from the rectangle's corner, u fastest."""
        return [((i + 0.5) * self.pitch_u_m, (j + 0.5) * self.pitch_v_m) for j in range(self.n_v) for i in range(self.n_u)]


def en12464_grid(length_m: float, width_m: float) -> Grid:
    """The EN 12464-1 grid over a ``length_m × width_m`` area (see Notes of the module).

    The relevant dimension is the longer side, or the shorter one when the
    sides' ratio is 2 or more; its point count is the nearest whole number to
    ``d / p`` (at least 1), and the other side's count is the nearest whole
    number to its length over the resulting pitch.

    Raises
    ------
    ValueError
        A non-positive side, or a cell aspect ratio outside [0.5, 2] (which
        only a side far shorter than its pitch can give).
    """
    if not (length_m > 0.0 and width_m > 0.0):
        raise ValueError(f"sides must be > 0, got {length_m} x {width_m}")
    long_m, short_m = max(length_m, width_m), min(length_m, width_m)
    d = short_m if long_m / short_m >= 2.0 else long_m
    p = grid_spacing_m(d)
    n_d = max(1, round(d / p))
    pitch = d / n_d
    other = long_m if d == short_m and long_m != short_m else short_m
    n_o = max(1, round(other / pitch))
    if d == length_m:
        n_u, n_v = n_d, n_o
    else:
        n_u, n_v = n_o, n_d
    g = Grid(n_u, n_v, length_m / n_u, width_m / n_v, d, p)
    aspect = g.pitch_u_m / g.pitch_v_m
    if not MIN_ASPECT <= aspect <= MAX_ASPECT:
        raise ValueError(f"cell aspect ratio {aspect:.2f} is outside [0.5, 2] for a {length_m:g} m x {width_m:g} m area")
    return g


def explicit_grid(length_m: float, width_m: float, spacing_m: float) -> Grid:
    """Cell-centre grid with cells no larger than ``spacing_m`` on either side
    (``ceil(side / spacing)`` points, so the pitch is at most the spacing)."""
    n_u = max(1, math.ceil(length_m / spacing_m - 1e-9))
    n_v = max(1, math.ceil(width_m / spacing_m - 1e-9))
    return Grid(n_u, n_v, length_m / n_u, width_m / n_v, 0.0, spacing_m)
