"""Per-zone illuminance figures with standard errors, compliance, and how well a sensor predicts a target.

Notes
-----
For a zone of N sensors with readings ``E_i`` and independent standard
errors ``σ_i`` (each sensor has its own random stream), first-order error
propagation (the delta method) gives

.. math::

    \\bar E = \\tfrac1N \\textstyle\\sum_i E_i, \\quad
    \\sigma_{\\bar E} = \\tfrac1N \\sqrt{\\textstyle\\sum_i \\sigma_i^2}, \\qquad
    U_0 = E_{\\min} / \\bar E, \\quad
    \\sigma_{U_0}^2 = \\textstyle\\sum_i \\bigl(\\partial U_0 / \\partial E_i\\bigr)^2 \\sigma_i^2,

with :math:`\\partial U_0/\\partial E_i = [i = m]/\\bar E - E_{\\min}/(N \\bar E^2)`
for the minimum's sensor ``m``; likewise for ``E_min/E_max``. ``E_min`` and
``E_max`` carry the standard error of the sensor that attains them (the
extreme of noisy readings is biased outward by about that much).

A sensor ``s`` predicts a target ``T`` (a zone's mean) after a per-sensor
linear calibration ``T ≈ a·r_s + b`` fitted by least squares over the
scenarios; its relative errors are ``|a·r_s,j + b − T_j| / T_j``.

References
----------
EN 12464-1:2011, §4.3–4.4 (maintained illuminance Ē and uniformity
U0 = Emin/Ē over a calculation grid).
JCGM 100:2008 (GUM), §5.1.2 (law of propagation of uncertainty).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ZoneFigures", "zone_figures", "compliance", "calibrated_errors", "TARGET_FIGURES"]

#: target keys and the figure each bounds from below ("min") or above ("max")
TARGET_FIGURES = {"mean": ("mean", "min"), "min": ("min", "min"), "max": ("max", "max"), "u0": ("u0", "min"), "min_max": ("min_max", "min")}


@dataclass(frozen=True)
class ZoneFigures:
    """Figures of one zone in one scenario, each with its standard error (same units as the readings)."""

    min: float
    min_se: float
    mean: float
    mean_se: float
    max: float
    max_se: float
    u0: float
    u0_se: float
    min_max: float
    min_max_se: float


def zone_figures(e: np.ndarray, se: np.ndarray) -> ZoneFigures:
    """Figures of readings ``e`` (N,) with standard errors ``se`` (N,); see Notes of the module."""
    n = len(e)
    m, big = int(np.argmin(e)), int(np.argmax(e))
    mean = float(e.mean())
    mean_se = float(np.sqrt(np.sum(se**2)) / n)
    emin, emax = float(e[m]), float(e[big])
    if mean > 0:
        d = np.full(n, -emin / (n * mean * mean))
        d[m] += 1.0 / mean
        u0, u0_se = emin / mean, float(np.sqrt(np.sum((d * se) ** 2)))
    else:
        u0, u0_se = float("nan"), float("nan")
    if emax > 0:
        d = np.zeros(n)
        d[m] += 1.0 / emax
        d[big] += -emin / (emax * emax)
        mm, mm_se = emin / emax, float(np.sqrt(np.sum((d * se) ** 2)))
    else:
        mm, mm_se = float("nan"), float("nan")
    return ZoneFigures(emin, float(se[m]), mean, mean_se, emax, float(se[big]), u0, u0_se, mm, mm_se)


def compliance(fig: ZoneFigures, targets: dict[str, float]) -> dict[str, str]:
    """Per target: ``pass`` when the figure meets it by more than 2 standard errors,
    ``fail`` when it misses by more than 2, else ``unsure``."""
    out = {}
    for key, bound in targets.items():
        attr, side = TARGET_FIGURES[key]
        v, s = getattr(fig, attr), getattr(fig, attr + "_se")
        margin = (v - bound) if side == "min" else (bound - v)
        out[key] = "pass" if margin > 2 * s else ("fail" if margin < -2 * s else "unsure")
    return out


def calibrated_errors(r: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares calibration of readings onto a target, and its relative errors.

    Parameters
    ----------
    r : ndarray, shape (..., C, J)
        Readings of C sensors in J scenarios (leading axes: replicates).
    t : ndarray, shape (..., J)
        Target in each scenario (> 0 where it counts).

    Returns
    -------
    corr : ndarray, shape (..., C)
        Pearson correlation of each sensor with the target (0 for a constant sensor).
    rel : ndarray, shape (..., C, J)
        ``|a·r + b − t| / t`` after each sensor's own fit (NaN where t ≤ 0).
    """
    t = t[..., None, :]
    rm = r.mean(axis=-1, keepdims=True)
    tm = t.mean(axis=-1, keepdims=True)
    dr, dt = r - rm, t - tm
    sxx = np.sum(dr * dr, axis=-1, keepdims=True)
    sxy = np.sum(dr * dt, axis=-1, keepdims=True)
    syy = np.sum(dt * dt, axis=-1, keepdims=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(sxx > 0, sxy / np.where(sxx > 0, sxx, 1.0), 0.0)
        corr = np.where((sxx > 0) & (syy > 0), sxy / np.sqrt(sxx * syy), 0.0)[..., 0]
        pred = tm + a * dr
        rel = np.where(t > 0, np.abs(pred - t) / np.where(t > 0, t, 1.0), np.nan)
    return corr, rel
