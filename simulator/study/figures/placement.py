"""Choosing K sensors: greedy selection with lazy evaluation, score errors, separability.

Each target zone ``z`` is predicted by the best sensor of the chosen set
after that sensor's own linear calibration. With a per-(sensor, zone) gain
``q[s, z] ≥ 0`` the set's value is the facility-location function

.. math:: F(S) = \\tfrac1Z \\textstyle\\sum_z \\max_{s \\in S} q[s, z],

which is monotone and submodular, so greedy selection is within
``(1 − 1/e)`` of the best K-set (Nemhauser, Wolsey and Fisher 1978), and
lazy evaluation (Minoux 1978) may skip re-evaluating a candidate whose stale
gain is already below the best fresh one, because gains only shrink.

Gains: ``correlation`` uses ``q = max(ρ, 0)``; ``max_rel_error`` and
``p95_rel_error`` use the error of the best constant predictor (no sensor)
minus the sensor's error, floored at 0, so the reported score of a set is
that error after its best sensor per zone.

Score errors come from a parametric bootstrap: every reading and target is
redrawn from a normal with its standard error (fixed seed), the gains are
recomputed, and the standard deviation over replicates is the error. Two
candidates are *not separable* when the best one's lead in marginal gain is
under twice the bootstrap standard deviation of that lead.

References
----------
Nemhauser, G. L., Wolsey, L. A. and Fisher, M. L. (1978). An analysis of
approximations for maximizing submodular set functions. Math. Programming 14, 265–294.
Minoux, M. (1978). Accelerated greedy algorithms for maximizing submodular
set functions. Optimization Techniques, LNCIS 7, 234–243.
Krause, A., Singh, A. and Guestrin, C. (2008). Near-optimal sensor
placements in Gaussian processes. JMLR 9, 235–284.
"""

from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass, field

import numpy as np

from simulator.study.figures.objectives import calibrated_errors

__all__ = ["gains", "set_value", "greedy_lazy", "brute_force", "Placement", "Step", "place_sensors"]


def _error_of(rel: np.ndarray, objective: str) -> np.ndarray:
    """(..., C) error over scenarios from (..., C, J) relative errors."""
    if objective == "max_rel_error":
        return np.nanmax(rel, axis=-1)
    return np.nanpercentile(rel, 95.0, axis=-1, method="linear")


def gains(r: np.ndarray, t: np.ndarray, objective: str) -> tuple[np.ndarray, np.ndarray]:
    """Gains ``q`` (..., C, Z) and the no-sensor baseline (..., Z).

    Parameters
    ----------
    r : ndarray, shape (..., C, J)
        Candidate readings per scenario.
    t : ndarray, shape (..., Z, J)
        Targets per zone and scenario.
    """
    qs, base = [], []
    for z in range(t.shape[-2]):
        corr, rel = calibrated_errors(r, t[..., z, :])
        if objective == "correlation":
            qs.append(np.maximum(corr, 0.0))
            base.append(np.zeros(corr.shape[:-1]))
        else:
            tz = t[..., z, :]
            with np.errstate(divide="ignore", invalid="ignore"):
                rel0 = np.where(tz > 0, np.abs(tz.mean(axis=-1, keepdims=True) - tz) / np.where(tz > 0, tz, 1.0), np.nan)
            e0 = _error_of(rel0[..., None, :], objective)[..., 0]
            qs.append(np.maximum(e0[..., None] - _error_of(rel, objective), 0.0))
            base.append(e0)
    return np.stack(qs, axis=-1), np.stack(base, axis=-1)


def set_value(q: np.ndarray, chosen: list[int]) -> np.ndarray:
    """``F(S)`` for gains ``q`` (..., C, Z): mean over zones of the best chosen gain (0 for an empty set)."""
    if not chosen:
        return np.zeros(q.shape[:-2])
    return q[..., chosen, :].max(axis=-2).mean(axis=-1)


def greedy_lazy(q: np.ndarray, k: int) -> tuple[list[int], list[float], int]:
    """Greedy maximisation of ``F`` with lazy evaluation.

    Parameters
    ----------
    q : ndarray, shape (C, Z)
    k : int

    Returns
    -------
    chosen : list of int
    gains : list of float
        Marginal gain of each pick.
    evaluations : int
        Marginal-gain evaluations done (C at the first step, usually far
        fewer than ``C·k`` in all).

    Notes
    -----
    Ties go to the lower index, so the result does not depend on heap order.
    """
    c = q.shape[0]
    best = np.zeros(q.shape[1])
    heap = [(-float(q[i].mean()), i) for i in range(c)]
    heapq.heapify(heap)
    evals = c
    fresh = {i: 0 for i in range(c)}  # step at which each bound was computed
    chosen, picked_gains = [], []
    for step in range(min(k, c)):
        while True:
            neg, i = heapq.heappop(heap)
            if fresh[i] == step:
                chosen.append(i)
                picked_gains.append(-neg)
                best = np.maximum(best, q[i])
                break
            g = float(np.maximum(q[i] - best, 0.0).mean())
            evals += 1
            fresh[i] = step
            heapq.heappush(heap, (-g, i))
    return chosen, picked_gains, evals


def brute_force(q: np.ndarray, k: int) -> tuple[tuple[int, ...], float]:
    """The best K-set by trying every one (for tests on small cases)."""
    best, arg = -1.0, ()
    for combo in itertools.combinations(range(q.shape[0]), k):
        v = float(set_value(q, list(combo)))
        if v > best + 1e-15:
            best, arg = v, combo
    return arg, best


@dataclass
class Step:
    """One greedy pick."""

    k: int
    sensor: str
    gain: float
    gain_se: float
    score: float
    score_se: float
    runner_up: str | None
    lead: float
    lead_se: float

    @property
    def separable(self) -> bool:
        return self.runner_up is None or self.lead > 2.0 * self.lead_se


@dataclass
class Placement:
    objective: str
    zones: list[str]
    candidates: int
    scenarios: int
    steps: list[Step] = field(default_factory=list)
    assignment: dict[str, str] = field(default_factory=dict)  #: zone -> chosen sensor predicting it
    evaluations: int = 0
    replicates: int = 0
    baseline: float = 0.0  #: score with no sensor (0 for correlation; the constant predictor's error otherwise)

    @property
    def chosen(self) -> list[str]:
        return [s.sensor for s in self.steps]


def _score(value: np.ndarray, base: np.ndarray, objective: str) -> np.ndarray:
    """Reported score: mean correlation, or the zones' mean error after the set's best sensors."""
    return value if objective == "correlation" else base.mean(axis=-1) - value


def place_sensors(names: list[str], r: np.ndarray, r_se: np.ndarray, t: np.ndarray, t_se: np.ndarray, zones: list[str],
                  k: int, objective: str, replicates: int, seed: int) -> Placement:  # fmt: skip
    """Choose ``k`` of the candidates ``names`` with readings ``r`` (C, J) to predict targets ``t`` (Z, J).

    ``r_se`` and ``t_se`` are the standard errors used by the bootstrap.
    """
    q, base = gains(r, t, objective)
    chosen, step_gains, evals = greedy_lazy(q, k)
    rng = np.random.default_rng(seed)
    rb = r[None] + r_se[None] * rng.standard_normal((replicates,) + r.shape)
    tb = t[None] + t_se[None] * rng.standard_normal((replicates,) + t.shape)
    qb, baseb = gains(rb, tb, objective)
    out = Placement(objective, zones, len(names), r.shape[1], evaluations=evals, replicates=replicates,
                    baseline=float(_score(np.zeros(()), base, objective)))  # fmt: skip
    for j, i in enumerate(chosen):
        prev = chosen[:j]
        best_prev = q[prev].max(axis=0) if prev else np.zeros(q.shape[1])
        marg = np.maximum(q - best_prev, 0.0).mean(axis=1)
        marg[prev] = -np.inf
        order = np.argsort(-marg, kind="stable")
        ru = next((int(c) for c in order if c != i and np.isfinite(marg[c])), None)
        bprev = qb[:, prev].max(axis=1) if prev else np.zeros((replicates, q.shape[1]))
        gb_i = np.maximum(qb[:, i] - bprev, 0.0).mean(axis=1)
        val_b = set_value(qb, chosen[: j + 1])
        sc_b = _score(val_b, baseb, objective)
        lead, lead_se = 0.0, 0.0
        if ru is not None:
            gb_r = np.maximum(qb[:, ru] - bprev, 0.0).mean(axis=1)
            lead, lead_se = float(marg[i] - marg[ru]), float(np.std(gb_i - gb_r, ddof=1))
        sc = float(_score(set_value(q, chosen[: j + 1]), base, objective))
        out.steps.append(Step(j + 1, names[i], float(step_gains[j]), float(np.std(gb_i, ddof=1)), sc, float(np.std(sc_b, ddof=1)),
                              None if ru is None else names[ru], lead, lead_se))  # fmt: skip
    for zi, z in enumerate(zones):
        out.assignment[z] = names[chosen[int(np.argmax(q[chosen, zi]))]]
    return out
