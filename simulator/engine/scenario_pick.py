"""The light pick's factors for a pass that serves several dimming scenarios (host side, numpy only).

A study traces the light groups of a trace group in one pass and recombines
each scenario, E_j = Σ_g d_jg·E_g. The light pick
(:mod:`simulator.kernels.light_pick`) draws one light per path vertex with
probability ∝ w_l, w_l = ê_l·f_l (estimate × learned factor); learnt on the
pass's lights at their authored levels, w_l is each light's share of *all*
groups, so where a scenario has the sky at 0 its lamps are picked only as
often as they are bright beside the sky: on the office, a lamp-only
scenario sharing a pass with an overcast sky came out 1.33× the standard
error of a plain run of its lamps at equal samples (1.8× the variance).

Notes
-----
With g_l ≥ 0 a row's pilot estimate of light l's contribution (the
shadowed values the factors were learnt from, Σ weight·value over the
row's vertices), scenario j's own pick would be

.. math:: p^*_{jl} = d_{jl}\\, g_l / S_j, \\qquad S_j = \\textstyle\\sum_k d_{jk}\\, g_k,

(d_jl the level scenario j gives light l's group). The pass picks by the
largest share any scenario gives each light,

.. math:: w'_l \\propto g_l \\max_j \\frac{d_{jl}}{S_j},

i.e. it multiplies f_l by m_l = max_j d_jl / S_j (scenarios with S_j = 0
left out; normalised so that max m = 1). Then p_l ≥ p*_jl / Z for every
scenario, Z = Σ_l max_j p*_jl ≤ the number of distinct lit shares, so no
scenario's picks fall below 1/Z of its own; a lamp-only scenario whose
lamps another scenario also lights keeps its lamps at nearly their own
share. The pick stays unbiased (the kernel divides by the probability it
used and the uniform share α keeps every light possible); only which
scenarios get the low-variance picks changes. A dome split into sky patches
takes, per scenario, the largest level of its slots.

When Z exceeds :data:`MAX_SPREAD` (1.44 = 1.2²) no one pick serves every
scenario within 1.2× of its own standard error, and the pass samples every
light at every vertex instead (pick mode ``off``): L shadow rays a vertex in
place of one, each group then as well sampled as in a run of its own.
Measured on the office (15 work-plane sensors, 1024 samples, guided paths;
window row, corridor row and an overcast sky; scenarios lamps only and
sky + corridor at 0.5; CPU time on a loaded 2-core machine): the authored
pick gave the lamp-only scenario 1.33× a plain run's standard error, the
mixture 1.28× (the overcast 1.13×), Z = 1.9 there; every light sampled gave
0.955× and 0.953× (median over sensors) for 1.29× the pass's CPU time, so
variance × time 1.2× a plain run's against 1.66× with one picked light.
"""

from __future__ import annotations

import numpy as np

__all__ = ["scenario_multipliers", "light_levels", "pick_spread", "MAX_SPREAD"]

#: the most spread Z the mixture pick may have: above it a scenario's picks could fall below
#: 1/Z of its own share (variance up to Z×, standard error √Z× > 1.2×), so the pass samples every light
MAX_SPREAD = 1.44


def light_levels(levels: np.ndarray, light_group: np.ndarray, patch_base: np.ndarray | None, n_slots_of_patch: int = 146) -> np.ndarray:
    """Per scenario and light record its level, (J, L): its group's, a split dome's largest slot, 0 for no group.

    Parameters
    ----------
    levels : ndarray, shape (J, G)
        Dimming vectors over the pass's group slots.
    light_group : ndarray of int, shape (L,)
        Each light record's slot (−1: none).
    patch_base : ndarray of int, shape (L,), or None
        A split dome's first slot (−1 otherwise).
    """
    lv = np.asarray(levels, np.float64)
    lg = np.asarray(light_group, np.int64)
    out = np.zeros((lv.shape[0], len(lg)))
    for l, g in enumerate(lg):
        pb = -1 if patch_base is None or l >= len(patch_base) else int(patch_base[l])
        if pb >= 0:
            out[:, l] = lv[:, pb : pb + n_slots_of_patch].max(axis=1)
        elif g >= 0:
            out[:, l] = lv[:, g]
    return out


def pick_spread(got: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Z = Σ_l max_j p*_jl per row (R,): 1 when every scenario wants the same pick, up to the number of
    scenarios with disjoint lights (see Notes of the module)."""
    g = np.maximum(np.asarray(got, np.float64), 0.0)
    d = np.asarray(d, np.float64)
    s = g @ d.T  # (R, J)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.where(s[:, :, None] > 0, d[None] * g[:, None, :] / np.where(s > 0, s, 1.0)[:, :, None], 0.0)  # (R, J, L)
    z = p.max(axis=1).sum(axis=1)
    return np.where(z > 0, z, 1.0)


def scenario_multipliers(got: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Multipliers m (R, L) of the pick factors' rows (see Notes of the module).

    Parameters
    ----------
    got : ndarray, shape (R, L)
        Per factor row, each light's pilot contribution g_l ≥ 0.
    d : ndarray, shape (J, L)
        Each scenario's level of each light (:func:`light_levels`).

    Returns
    -------
    ndarray, shape (R, L)
        1 where a row has no scenario with light (nothing to steer).
    """
    g = np.maximum(np.asarray(got, np.float64), 0.0)
    d = np.asarray(d, np.float64)
    s = g @ d.T  # (R, J): each scenario's total at each row
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(s[:, :, None] > 0, d[None, :, :] / np.where(s > 0, s, 1.0)[:, :, None], 0.0)  # (R, J, L)
    m = ratio.max(axis=1)
    top = m.max(axis=1, keepdims=True)
    return np.where(top > 0, m / np.where(top > 0, top, 1.0), 1.0)
