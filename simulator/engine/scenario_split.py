"""The indirect split of a pass that serves several dimming scenarios (host side, numpy only).

A plain path run reads an irradiance sample as its direct light once plus the
mean of K indirect paths (``kernels.estimators.split_irradiance``), K from a
pilot by the Neyman allocation (``Engine._split_rule``). A light-group pass
(``probesim study``) once drew one path a sample (K = 1), so at equal samples
a lamp-only scenario whose plain run splits came out much noisier: on the
office (window row, corridor row, sky and sun in one pass; both rows at 1.7,
the rest at 0; 8 work-plane sensors, 1024 samples) its variance per sample was
6.6× a plain run's (standard error 2.6×; 7.3× over three seed pairs), where the
plain run chose K = 5.

Notes
-----
The pilot tallies its samples per *pilot group* (lights with the same level
in every scenario share one; a split dome counts whole, at its largest slot's
level), direct part and indirect part apart, so each scenario j with levels
d_j has its own relative variances per sample summed over the sensors,

.. math:: V_{d,j} = \\sum_s \\frac{d_j^\\top C^{d}_s d_j}{(d_j^\\top (m^d_s + m^i_s))^2}, \\qquad
          V_{i,j} = \\sum_s \\frac{d_j^\\top C^{i}_s d_j}{(d_j^\\top (m^d_s + m^i_s))^2},

(C_s the pilot's per-sample covariance of the group vector, m_s its mean) and
its own Neyman K_j = √(V_i,j·c_d / (V_d,j·c_i)) with the rays per sample c_d,
c_i the pilot counted (shared: the paths are the same). Where any
scenario's Neyman K_j rounds to 2 or more (no gain threshold: the pass's
costs understate what its own run would gain), the pass draws K = SPLIT_MAX
indirect paths a sample, else 1. Why the largest and not max_j K_j: the pass's rays a path are dearer than a plain run's of
one scenario (it samples every group's lights at each vertex: on the office
c_i/c_d was 2.4 in the pass, 1.1 in the lamps' own run), so its K_j come out
below the plain run's (3–4 against 5) and the lamp-only scenario stayed
1.5× a plain run's variance per sample at equal samples. A sample's
variance v_d + v_i/K falls as K grows, so with K = SPLIT_MAX no scenario is
noisier per sample for want of indirect paths than its plain run (whose K
≤ SPLIT_MAX) nor than before (K = 1); the price is K indirect paths in every
sample (an adaptive pass draws fewer samples for it). The sum stays
unbiased for any K.
"""

from __future__ import annotations

import numpy as np

__all__ = ["pilot_groups", "neyman_split", "pass_split", "scenario_relative_variances", "MAX_PILOT_GROUPS"]

#: the most pilot groups the split pilot tallies per sample (a thread keeps G(G + 3) float64 pairs);
#: with more, the pass's K comes from its total (every light at its authored level)
MAX_PILOT_GROUPS = 16


def pilot_groups(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lights with the same level in every scenario merged: (group of each light (L,), levels (J, G')).

    Parameters
    ----------
    d : ndarray, shape (J, L)
        Each scenario's level of each light record
        (:func:`simulator.engine.scenario_pick.light_levels`).
    """
    d = np.asarray(d, np.float64)
    cols, group = np.unique(d.T, axis=0, return_inverse=True)
    return np.asarray(group, np.int64).reshape(-1), cols.T.copy()


def scenario_relative_variances(mean: np.ndarray, m2: np.ndarray, count: np.ndarray, levels: np.ndarray,
                                total: np.ndarray) -> np.ndarray:  # fmt: skip
    """Σ over sensors of each scenario's variance per sample over the square of its reading, (J,).

    Parameters
    ----------
    mean : ndarray, shape (S, G)
        Per sensor the pilot part's mean of each pilot group (one channel).
    m2 : ndarray, shape (S, G, G)
        Its co-moments Σ(x_g − x̄_g)(x_h − x̄_h).
    count : ndarray, shape (S,)
        Samples per sensor.
    levels : ndarray, shape (J, G)
        Each scenario's level of each pilot group.
    total : ndarray, shape (S, G)
        The reading the variance is relative to (direct + indirect means).
    """
    d = np.asarray(levels, np.float64)
    var = np.einsum("jg,sgh,jh->sj", d, np.asarray(m2, np.float64), d) / np.maximum(np.asarray(count) - 1, 1)[:, None]
    m = np.asarray(total, np.float64) @ d.T  # (S, J)
    ok = m > 0
    return np.where(ok, var / np.where(ok, m, 1.0) ** 2, 0.0).sum(axis=0)


def neyman_split(rv_d: float, rv_i: float, c_d: float, c_i: float, k_max: int, min_gain: float) -> tuple[int, float]:
    """K = √(V_i·c_d / (V_d·c_i)) rounded into [1, k_max], 1 where the predicted gain
    (V_d + V_i)(c_d + c_i) / ((V_d + V_i/K)(c_d + K·c_i)) is under ``min_gain``; returns (K, gain)."""
    if rv_i <= 0:
        return 1, 1.0
    k = k_max if rv_d <= 0 else int(np.clip(round(float(np.sqrt(rv_i * c_d / (rv_d * c_i)))), 1, k_max))
    gain = (rv_d + rv_i) * (c_d + c_i) / max((rv_d + rv_i / k) * (c_d + k * c_i), 1e-300)
    return (k, gain) if gain >= min_gain else (1, gain)


def pass_split(per_scenario: list[tuple[int, float]], k_max: int) -> int:
    """The pass's K from each scenario's own (K_j, gain_j): ``k_max`` where any scenario gains by a
    split, else 1 (see Notes of the module: at equal samples no plain run of a scenario, whose
    K ≤ ``k_max``, is then less noisy for want of indirect paths)."""
    return k_max if any(k > 1 for k, _ in per_scenario) else 1
