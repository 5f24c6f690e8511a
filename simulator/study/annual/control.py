"""Photosensor control of a zone's lamps over a year: dimming levels, relative energy, hours below target.

Per occupied hour h a zone has a mean work-plane daylight illuminance D(h);
its photosensor reads a daylight signal s(h). With the controlled light
groups at full output the zone's mean electric illuminance is E_e and the
photosensor's electric signal S_e. The control sets a level u(h) (0…1,
light output and power relative to full; linear dimming, ballast losses
left out) for a target E_t:

closed_loop
    Proportional control of the sensor's total signal s + u·S_e (it sees
    the lamps it dims), calibrated at night: the set point is the signal of
    the lamps alone at the level that gives the target,
    SP = S_e · min(1, E_t / E_e), so u = clip((SP − s)/S_e, u_min, 1).
open_loop
    The sensor sees daylight only; its gain k = D_ov / s_ov is commissioned
    under the CIE overcast sky (the daylight-factor sky) and
    u = clip((E_t − k·s)/E_e, u_min, 1).
switched
    On/off with a deadband on the open-loop daylight estimate k·s: off once
    k·s ≥ E_t·(1 + deadband), on again once k·s < E_t, unchanged between
    (starting on); on is full output.

The zone's illuminance is D + u·E_e; an hour is *below target* when that is
under E_t (by more than 1e-9 relative, rounding). Relative lighting energy is
Σu / N over the N occupied hours: 1 for lamps at full output every hour.
"Best annual control" ranks photosensor candidates by
``relative energy + hours below target / N`` (an under-lit hour costs as
much as an hour of full lighting), lower is better.

References
----------
Rubinstein, F., Ward, G. and Verderber, R. (1989). Improving the
performance of photo-electrically controlled lighting systems. Journal of
the IES 18(1), 70–94 (closed- and open-loop proportional control, night
calibration).
docs/REFERENCES.md §Photosensor control.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["MODELS", "ControlOutcome", "levels", "outcome"]

MODELS = ("closed_loop", "open_loop", "switched")
_REL_TOL = 1e-9


@dataclass(frozen=True)
class ControlOutcome:
    """One control's year: levels per hour, relative energy, hours below target, the ranking score."""

    level: np.ndarray
    relative_energy: float
    hours_below: float
    score: float


def levels(model: str, daylight_signal: np.ndarray, lamp_signal: float, lamp_zone_lx: float, target_lx: float,
           min_level: float = 0.1, deadband: float = 0.2, gain: float = 1.0) -> np.ndarray:  # fmt: skip
    """Dimming level u(h), shape (H,), of one control model (see the module's Notes).

    Parameters
    ----------
    daylight_signal : ndarray, shape (H,)
        The photosensor's daylight reading s(h).
    lamp_signal : float
        S_e, its reading of the controlled lamps at full output (closed loop).
    lamp_zone_lx : float
        E_e, the zone's mean illuminance from those lamps at full output.
    gain : float
        k of the open-loop and switched models (zone daylight per unit of signal).
    """
    s = np.asarray(daylight_signal, np.float64)
    if np.ndim(lamp_signal) or np.ndim(lamp_zone_lx):
        return _levels_hourly(model, s, np.broadcast_to(np.asarray(lamp_signal, np.float64), s.shape),
                              np.broadcast_to(np.asarray(lamp_zone_lx, np.float64), s.shape), target_lx, min_level, deadband, gain)
    if lamp_zone_lx <= 0:
        return np.ones_like(s)
    if model == "closed_loop":
        if lamp_signal <= 0:
            return np.ones_like(s)  # the sensor sees none of its lamps: nothing to regulate on
        sp = lamp_signal * min(1.0, target_lx / lamp_zone_lx)
        return np.clip((sp - s) / lamp_signal, min_level, 1.0)
    est = gain * s
    if model == "open_loop":
        return np.clip((target_lx - est) / lamp_zone_lx, min_level, 1.0)
    if model == "switched":
        u = np.empty_like(s)
        on = True
        for h, e in enumerate(est):
            if on and e >= target_lx * (1.0 + deadband):
                on = False
            elif not on and e < target_lx:
                on = True
            u[h] = 1.0 if on else 0.0
        return u
    raise ValueError(f"unknown control model {model!r} (expected one of {', '.join(MODELS)})")


def _levels_hourly(model: str, s: np.ndarray, lamp_signal: np.ndarray, lamp_zone_lx: np.ndarray, target_lx: float,
                   min_level: float, deadband: float, gain: float) -> np.ndarray:  # fmt: skip
    """:func:`levels` where the lamps' signal and zone illuminance change hour by hour (operable shading: each
    hour's state reflects the lamps' light differently); the same rules, hour by hour."""
    ok = lamp_zone_lx > 0
    if model == "closed_loop":
        ok &= lamp_signal > 0
        sig = np.where(ok, lamp_signal, 1.0)
        sp = sig * np.minimum(1.0, target_lx / np.where(ok, lamp_zone_lx, 1.0))
        return np.where(ok, np.clip((sp - s) / sig, min_level, 1.0), 1.0)
    est = gain * s
    if model == "open_loop":
        return np.where(ok, np.clip((target_lx - est) / np.where(ok, lamp_zone_lx, 1.0), min_level, 1.0), 1.0)
    if model == "switched":
        u = levels("switched", s, 1.0, 1.0, target_lx, min_level, deadband, gain)
        return np.where(ok, u, 1.0)
    raise ValueError(f"unknown control model {model!r} (expected one of {', '.join(MODELS)})")


def outcome(u: np.ndarray, zone_daylight_lx: np.ndarray, lamp_zone_lx: float, target_lx: float) -> ControlOutcome:
    """Relative energy, hours below target and score of levels ``u`` over the hours of ``zone_daylight_lx``."""
    n = max(len(u), 1)
    lit = np.asarray(zone_daylight_lx, np.float64) + u * lamp_zone_lx
    below = float(np.sum(lit < target_lx * (1.0 - _REL_TOL)))
    energy = float(np.sum(u)) / n
    return ControlOutcome(u, energy, below, energy + below / n)
