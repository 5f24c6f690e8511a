"""Glare indices and the position index, as closed formulas (numpy).

All angles are in the view's frame: a view direction ``v`` and an up vector
``u`` orthogonal to it. For a source in direction ``d``:

- σ (sigma): the angle between ``v`` and ``d`` (0 on the line of sight);
- τ (tau): the angle between ``u`` and the projection of ``d`` on the plane
  normal to ``v``: 0 straight above the line of sight, 90° beside it, 180°
  straight below (evalglare's ``pict_get_tau``);
- the source lies below the line of sight when u·d < 0 (τ > 90°).

Position index P (how much less a source glares away from the line of sight):

- above the line of sight, Guth's (IES Lighting Handbook)::

      P = exp[(35.2 − 0.31889·τ − 1.22·e^(−2τ/9))·10⁻³·σ + (21 + 0.26667·τ − 0.002963·τ²)·10⁻⁵·σ²]

- below it, the form of Iwata and Osterhaus as evalglare (3.02 and later)
  writes it, in Guth's coordinates (Kikuchi's conversion)::

      β = atan(tan σ · √(1 + 0.3225·cos²τ)),   P = exp(6.49·10⁻³·β + 21·10⁻⁵·β²)

  (σ, τ, β in degrees). At τ = 90° both give exp(6.5·10⁻³σ + 21·10⁻⁵σ²):
  the two branches meet at the horizontal plane of the view;
- P is at most 16 (evalglare's cap).

Indices (E_v vertical illuminance at the eye, lx; L_s, ω_s, P_s a source's
mean luminance, cd/m², solid angle, sr, and position index; L_b background
luminance, cd/m²):

- DGP (Wienold & Christoffersen 2006), with evalglare's constants::

      DGP = c1·E_v + c2·log10(1 + Σ L_s²·ω_s / (E_v^1.87·P_s²)) + c3,   at most 1,

  c1 = 5.87·10⁻⁵, c2 = 0.092, c3 = 0.159 (the paper prints 9.18·10⁻² and
  0.16; evalglare's rounding moves DGP by at most 0.001 while the log10
  term is at most 10, and is kept so that a run reproduces evalglare's);
- low-light correction (Wienold 2009; off by default, as in evalglare since
  2.14): below 1000 lx, DGP × e^(0.024·E_v − 4) / (1 + e^(0.024·E_v − 4));
- DGPs (Wienold 2009), the simplified form from E_v alone: 6.22·10⁻⁵·E_v + 0.184,
  at most 1 (meant for views without the sun in sight: it sees no source);
- UGR (CIE 117-1995): 8·log10(0.25/L_b · Σ L_s²·ω_s / P_s²); 0 without a source.

Sources: docs/REFERENCES.md §Glare indices.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "DGP_C1", "DGP_C2", "DGP_C3", "DGP_EV_EXPONENT", "POSITION_INDEX_MAX",
    "view_angles", "position_index_guth", "position_index_below", "position_index",
    "dgp", "dgp_glare_term", "low_light_factor", "dgps", "ugr",
]  # fmt: skip

#: DGP's constants as evalglare uses them (the paper: 5.87e-5, 9.18e-2, 0.16)
DGP_C1 = 5.87e-5
DGP_C2 = 0.092
DGP_C3 = 0.159
#: the exponent of E_v in DGP's glare term
DGP_EV_EXPONENT = 1.87
#: evalglare's upper bound of the position index
POSITION_INDEX_MAX = 16.0
#: DGPs = DGPS_SLOPE·E_v + DGPS_OFFSET (Wienold 2009)
DGPS_SLOPE = 6.22e-5
DGPS_OFFSET = 0.184


def view_angles(d: np.ndarray, view: np.ndarray, up: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """σ, τ (degrees) and whether each direction lies below the line of sight.

    Parameters
    ----------
    d : ndarray, shape (..., 3)
        Unit directions from the eye (in front of it: d·view > 0).
    view, up : ndarray, shape (3,)
        Unit view direction and unit up vector orthogonal to it.

    Returns
    -------
    sigma_deg, tau_deg : ndarray, shape (...)
        τ is 0 where σ is 0 (the line of sight itself; P = 1 there whatever τ).
    below : ndarray of bool, shape (...)
        u·d < 0.
    """
    d = np.asarray(d, np.float64)
    c = np.clip(d @ view, -1.0, 1.0)
    sigma = np.degrees(np.arccos(c))
    # the projection of d on the plane normal to the view: d − (d·v)v, its angle to up
    perp = d - c[..., None] * view
    norm = np.linalg.norm(perp, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_tau = np.where(norm > 0, (perp @ up) / np.where(norm > 0, norm, 1.0), 1.0)
    tau = np.degrees(np.arccos(np.clip(cos_tau, -1.0, 1.0)))
    return sigma, tau, (d @ up) < 0.0


def position_index_guth(sigma_deg, tau_deg) -> np.ndarray:
    """Guth's position index above the line of sight (module docstring), uncapped."""
    s = np.asarray(sigma_deg, np.float64)
    t = np.asarray(tau_deg, np.float64)
    a = (35.2 - 0.31889 * t - 1.22 * np.exp(-2.0 * t / 9.0)) * 1e-3 * s
    b = (21.0 + 0.26667 * t - 0.002963 * t * t) * 1e-5 * s * s
    return np.exp(a + b)


def position_index_below(sigma_deg, tau_deg) -> np.ndarray:
    """The position index below the line of sight (Iwata and Osterhaus as evalglare writes it), uncapped."""
    s = np.radians(np.asarray(sigma_deg, np.float64))
    t = np.radians(np.asarray(tau_deg, np.float64))
    beta = np.degrees(np.arctan(np.tan(s) * np.sqrt(1.0 + 0.3225 * np.cos(t) ** 2)))
    return np.exp(6.49e-3 * beta + 21e-5 * beta * beta)


def position_index(d: np.ndarray, view: np.ndarray, up: np.ndarray) -> np.ndarray:
    """P of unit directions ``d`` (..., 3): Guth above the line of sight, Iwata below, at most 16."""
    sigma, tau, below = view_angles(d, view, up)
    p = np.where(below, position_index_below(sigma, tau), position_index_guth(sigma, tau))
    return np.minimum(p, POSITION_INDEX_MAX)


def dgp_glare_term(ev_lx: float, l2w_over_p2: float) -> float:
    """c2·log10(1 + G/E_v^1.87), G = Σ L²ω/P² (cd²·m⁻⁴·sr)."""
    if not ev_lx > 0.0:
        return 0.0
    return DGP_C2 * math.log10(1.0 + max(0.0, l2w_over_p2) / ev_lx**DGP_EV_EXPONENT)


def low_light_factor(ev_lx: float) -> float:
    """The low-light correction's factor: e^(0.024·E_v − 4)/(1 + e^(0.024·E_v − 4)) below 1000 lx, else 1."""
    if ev_lx >= 1000.0:
        return 1.0
    x = 0.024 * ev_lx - 4.0
    return 1.0 / (1.0 + math.exp(-x))


def dgp(ev_lx: float, l2w_over_p2: float, low_light: bool = False, capped: bool = True) -> float:
    """DGP of a view whose sources give G = Σ L²ω/P² (module docstring); ``capped``: at most 1."""
    value = DGP_C1 * ev_lx + dgp_glare_term(ev_lx, l2w_over_p2) + DGP_C3
    if low_light:
        value *= low_light_factor(ev_lx)
    return min(1.0, value) if capped else value


def dgps(ev_lx: float) -> float:
    """The simplified DGP from E_v alone (Wienold 2009): 6.22·10⁻⁵·E_v + 0.184, at most 1 (as DGP)."""
    return min(1.0, DGPS_SLOPE * ev_lx + DGPS_OFFSET)


def ugr(background_cd_m2: float, l2w_over_p2: float) -> float:
    """CIE 117 UGR: 8·log10(0.25/L_b·Σ L²ω/P²); 0 without a source, NaN for L_b ≤ 0."""
    if not l2w_over_p2 > 0.0:
        return 0.0
    if not background_cd_m2 > 0.0:
        return math.nan
    return 8.0 * math.log10(0.25 / background_cd_m2 * l2w_over_p2)
