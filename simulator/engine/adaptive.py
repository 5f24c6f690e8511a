"""Batches until done: the stopping rule and the loop every reading runs.

A *unit* is what one stopping decision covers: a sensor, or a whole probe
(its pixels all draw the same passes). Each batch draws up to ``want``
more samples of every active unit. A unit stops when it has ``cap``
samples or, in adaptive mode, when the half-width of its confidence
interval is under the target in every channel,

    z·stderr ≤ max(rel_error·|value|, abs_error),

z the two-sided normal quantile of ``confidence`` (0.95 → 1.96). Every
unit stops at ``time_limit_s``. The next batch is what would reach the
target if the variance holds (stderr² ∝ 1/n), with 10% to spare, at least
one block and at most doubling the samples so far.

The first batch is the caller's: a config's ``samples`` where it sets one
(a floor every sensor draws), else what :func:`first_batch_from_pilot`
makes of a short pilot's variances (at most the default ``samples``). A
unit that reads exactly zero in every channel is not taken as converged
before ``dark_floor`` samples (a first batch the engine chose small must
not end a reading that only a rare path lights).

A stop request (Ctrl-C, see :mod:`simulator.interrupts`) ends the loop
between batches: SIGINT is deferred while a batch is drawn and merged, so
the statistics always hold whole batches; ``KeyboardInterrupt`` raised by
the ``report`` callback counts as a stop request too. A caller that passes
no stop flag gets the ``KeyboardInterrupt`` (after the batch) as before.
"""

from __future__ import annotations

import time
from typing import Callable

import numpy as np

from simulator.engine.stats import z_for_confidence
from simulator.interrupts import StopFlag, sigint_deferred

__all__ = ["StoppingRule", "run_batches", "first_batch_from_pilot", "pilot_floor", "PILOT_MIN_BATCH", "PILOT_LOW_BATCH"]

#: fewest samples per sensor in a first batch the engine chooses (a variance
#: from fewer is too rough for the rule to size the next batch by), unless the
#: pilot shows that nearly every sensor needs fewer (:func:`pilot_floor`)
PILOT_MIN_BATCH = 8
#: the least that floor is lowered to: each sensor's own variance then has
#: 3 degrees of freedom
PILOT_LOW_BATCH = 4
#: the share of the pilot's sensors whose need the lowered floor covers (the
#: rest take a second batch sized by their own variance)
PILOT_FLOOR_QUANTILE = 0.9
#: the chosen first batch is this share of the pilot's median need: most
#: sensors then take a second batch sized by their own variance (×1.1), and
#: few overshoot their need by much in the first
PILOT_NEED_SHARE = 0.5


def pilot_floor(need: np.ndarray, pilot_samples: int, lower: int = PILOT_MIN_BATCH) -> int:
    """The fewest samples of a first batch the engine chooses, from the pilot sensors' needs.

    Parameters
    ----------
    need : ndarray, shape (P,)
        Samples each pilot sensor needs, z²·relvar/rel² (finite).
    pilot_samples : int
        Samples per pilot sensor the needs were estimated from (m).
    lower : int
        The floor where the pilot cannot lower it.

    Returns
    -------
    int
        ``clip(⌈q₀.₉·(1 + √(2/(m − 1)))⌉, PILOT_LOW_BATCH, lower)``, q₀.₉ the
        90th percentile of ``need``.

    Notes
    -----
    A need estimated from m samples has the error of the variance it comes
    from: relative standard error √(2/(m − 1)) for normal samples (the
    variance of s² is 2σ⁴/(m − 1)), 53% at m = 8. The 90th percentile of the
    pilot's needs raised by that one standard error is the batch most sensors
    meet the target in; below ``lower`` the floor follows it, so a run whose
    sensors need 2–6 samples does not draw 8 each.
    """
    need = np.asarray(need, np.float64)
    if need.size == 0 or pilot_samples < 2:
        return int(lower)
    q = float(np.quantile(need, PILOT_FLOOR_QUANTILE)) * (1.0 + np.sqrt(2.0 / (pilot_samples - 1)))
    return int(min(lower, max(PILOT_LOW_BATCH, int(np.ceil(q)))))


def first_batch_from_pilot(relvar: np.ndarray, z: float, rel_error: float, upper: int,
                           lower: int = PILOT_MIN_BATCH, pilot_samples: int | None = None) -> int:
    """An adaptive run's first batch per sensor from a pilot's variances.

    Parameters
    ----------
    relvar : ndarray, shape (P,)
        Relative variance per sample (variance/mean²) of each pilot sensor,
        the largest over its channels; NaN where it read zero.
    z : float
        Half-width of the confidence interval, in standard errors.
    rel_error : float
        The relative half-width target.
    upper, lower : int
        Bounds of the batch (``upper``: the config's default ``samples``;
        ``lower``: the floor where the pilot cannot lower it).
    pilot_samples : int, optional
        Samples per pilot sensor; given, the floor is :func:`pilot_floor`'s.

    Returns
    -------
    int
        ``clip(⌈PILOT_NEED_SHARE·median(z²·relvar/rel_error²)⌉, floor,
        upper)``; ``upper`` where no pilot sensor read anything (nothing to
        size a batch by).
    """
    rv = np.asarray(relvar, np.float64)
    rv = rv[np.isfinite(rv)]
    upper = max(1, int(upper))
    if rv.size == 0:
        return upper
    floor = lower if pilot_samples is None else pilot_floor(z * z * rv / rel_error**2, pilot_samples, lower)
    need = z * z * float(np.median(rv)) / rel_error**2
    return int(min(upper, max(min(floor, upper), int(np.ceil(PILOT_NEED_SHARE * need)))))


class StoppingRule:
    """The adaptive error target.

    Parameters
    ----------
    rel_error : float
        Relative half-width target.
    abs_error : float
        Absolute half-width target (in the reading's units), for readings near 0.
    confidence : float
        Two-sided confidence of the interval.
    """

    def __init__(self, rel_error: float, abs_error: float = 0.0, confidence: float = 0.95):
        self.rel_error = rel_error
        self.abs_error = abs_error
        self.z = z_for_confidence(confidence)  # half-width of the confidence interval, in standard errors

    def check(self, value: np.ndarray, stderr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(met, target): per unit whether z·stderr ≤ target in every channel,
        and the target, shape (U, C), for ``value`` and ``stderr`` of shape (U, C)."""
        target = np.maximum(self.rel_error * np.abs(value), self.abs_error)
        return np.all(self.z * stderr <= target, axis=1), target

    def next_batch(self, count: np.ndarray, stderr: np.ndarray, target: np.ndarray, block: int) -> np.ndarray:
        """Samples to draw next per unit: enough to reach the target if the
        variance holds (×1.1), at least ``block``, at most doubling ``count``."""
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.max((self.z * stderr / np.maximum(target, 1e-300)) ** 2, axis=1)
        need = np.ceil(count * np.nan_to_num(ratio, nan=2.0, posinf=2.0) * 1.1) - count
        return np.clip(need, block, np.maximum(count, block)).astype(np.int64)


def run_batches(
    step: Callable[[np.ndarray, np.ndarray, np.ndarray], None],
    active: np.ndarray,
    want: np.ndarray,
    cap: int,
    *,
    block: int,
    rule: StoppingRule | None = None,
    measure: Callable[[], tuple[np.ndarray, np.ndarray]] | None = None,
    time_limit_s: float | None = None,
    t_start: float | None = None,
    report: Callable[[np.ndarray, np.ndarray, float], None] | None = None,
    stop: StopFlag | None = None,
    dark_floor: int = 0,
) -> tuple[np.ndarray, np.ndarray]:
    """Draw batches until every unit has stopped.

    Parameters
    ----------
    step : callable
        ``step(ids, first, count)`` draws samples ``[first[i], first[i] +
        count[i])`` of unit ``ids[i]`` and merges them into the caller's statistics.
    active : ndarray of bool, shape (U,)
        Units to read (changed in place: False once stopped).
    want : ndarray of int, shape (U,)
        First batch per unit; the rule replaces it after each batch.
    cap : int
        Most samples per unit.
    block : int
        Smallest batch the rule asks for.
    rule : StoppingRule, optional
        Adaptive stopping; None draws ``cap`` samples.
    measure : callable, optional
        With a rule: ``measure() -> (value, stderr)``, each shape (U, C),
        from the caller's statistics after the batch.
    time_limit_s : float, optional
        Stop everything once this long has passed since ``t_start``.
    t_start : float, optional
        ``time.perf_counter()`` the time limit counts from; default now.
    report : callable, optional
        ``report(count, active, elapsed_s)`` after each batch.
    stop : StopFlag, optional
        Checked before each batch; once requested the loop returns, leaving
        ``active`` True for the units it did not finish. SIGINT during a
        batch, or ``KeyboardInterrupt`` from ``report``, requests it.
        Without it, SIGINT raises ``KeyboardInterrupt`` once the batch is done.
    dark_floor : int
        With a rule: a unit reading 0 in every channel counts as meeting the
        target only once it has this many samples (0: at once).

    Returns
    -------
    count : ndarray of int, shape (U,)
        Samples drawn per unit.
    met : ndarray of bool, shape (U,)
        Whether the rule's target was reached (all False without a rule).
    """
    t0 = time.perf_counter() if t_start is None else t_start
    own = stop is None  # no caller wants partial results: an interrupt is raised, after the batch
    stop = StopFlag() if own else stop
    count = np.zeros(len(active), np.int64)
    met = np.zeros(len(active), bool)
    while active.any() and not stop.requested:
        with sigint_deferred(stop):  # a batch is drawn and merged whole
            ids = np.flatnonzero(active)
            first = count[ids]
            n = np.minimum(want[ids], cap - first)
            step(ids, first, n)
            count[ids] += n
            done = count >= cap
            if rule is not None:
                value, se = measure()
                ok, target = rule.check(value, se)
                dark = np.all(value == 0, axis=1) & (count < dark_floor) if dark_floor else None
                if dark is not None:
                    ok &= ~dark
                met |= ok & active
                done |= ok
                want = rule.next_batch(count, se, target, block)
                if dark is not None:  # nothing to size it by: double toward the floor
                    want = np.where(dark, np.maximum(want, np.minimum(count, dark_floor - count)), want)
            active &= ~done
            elapsed = time.perf_counter() - t0
            if time_limit_s is not None and elapsed >= time_limit_s:
                active[:] = False
        if own and stop.requested:
            raise KeyboardInterrupt
        if report is not None:
            try:
                report(count, active, elapsed)
            except KeyboardInterrupt:
                if own:
                    raise
                stop.request()
    return count, met
