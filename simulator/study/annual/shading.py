"""Operable shading: a window group's states as USD variants, and the rule that picks one every hour.

``[shading]`` names a variant set of the stage and, in ``states``, its
variants from the least shaded to the most (LM-83's "shades up", then
"down"). Each state is a stage of its own (that variant selected), traced
once for the year (:mod:`simulator.study.annual.year`); every hour then reads
the readings of the state the rule picks, the first of ``states`` that
satisfies it, or the last when none does:

``lm83`` (IES LM-83-12 §2.2.7, the LEED v4 option for operable shading)
    A state satisfies the hour when no more than ``share`` (2%) of the
    analysis points (the ``zones``' candidates, default every zone's) get
    more than ``ase_lx`` (1000 lx) of *direct sunlight* in it (the exact
    direct sun of :mod:`simulator.study.annual.sunlight`, no sky, no
    interreflection): the shades close when more than 2% of the points are
    in the sun. ASE itself is read with the first state all year
    (LM-83: "blinds open").
``glare``
    A state satisfies the hour when the DGP at every judging glare view
    (``views``, default all) is at most ``dgp_limit``
    (:mod:`simulator.study.annual.glare`).
``schedule``
    ``schedule = { state = [[month from, month to, hour from, hour to], ...] }``:
    an hour whose centre lies in those months (a range may wrap over the new
    year) and hours (local standard time, hour from ≤ h < hour to) is in the
    first state, in ``states``' order, whose list holds it; any other hour
    in the first state.

The rule is applied every analysed hour; the metrics read the occupied ones.
Sources: docs/REFERENCES.md §Operable shading.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError

__all__ = ["ShadeState", "shading_states", "lm83_choice", "glare_choice", "schedule_choice", "state_hours"]


@dataclass
class ShadeState:
    """One shading state: its name, the variant selection, its trace keys' suffix and the stage as read in it."""

    name: str
    variants: dict
    suffix: str  #: appended to the annual trace keys ("" for the first state: the keys of a study without shading)
    scene: object
    diffusers: list = field(default_factory=list)  #: simulator.study.annual.diffusers.Diffuser


def shading_states(study, stage: Path, base, label: str) -> list[ShadeState]:
    """The study's states, each read from the stage (a bad variant is a one-line error naming
    ``shading.states[k]``); without ``[shading]``, the stage as it is."""
    from simulator.scene.usd import load_stage
    from simulator.study.annual.diffusers import diffusers_of

    sh = study.shading
    if sh is None:
        return [ShadeState("", {}, "", base)]
    out = []
    for k, name in enumerate(sh.states):
        variants = {sh.variant_set: name}
        try:
            scene = load_stage(stage, light_units=study.light_units, radiometric_spectrum="E", variants=variants)
        except UserError as exc:
            key = "shading.variant_set" if "no prim has a variant set" in str(exc) else f"shading.states[{k}]"
            raise UserError(f"{label}: {key}: {exc}") from None
        out.append(ShadeState(name, variants, "" if k == 0 else f";state={name}", scene, diffusers_of(scene, sh.diffusers, label)))
    for path in sh.diffusers:
        if not any(d.prim == path for s in out for d in s.diffusers):
            raise UserError(f"{label}: shading.diffusers.{path}: no prim at that path with faces in any state "
                            f"({', '.join(sh.states)})")  # fmt: skip
    return out


def lm83_choice(direct: list[np.ndarray], lx: float, share: float) -> np.ndarray:
    """Each hour's state by LM-83's rule (module docstring).

    Parameters
    ----------
    direct : list of ndarray, shape (H, N) each
        Per state, the direct sun at the N analysis points, lux.
    lx, share : float
        A point is in the sun above ``lx``; a state fails the hour when more than ``share`` of the points are.
    """
    n_h = direct[0].shape[0]
    out = np.full(n_h, len(direct) - 1, np.int64)
    todo = np.ones(n_h, bool)
    for k, e in enumerate(direct):
        ok = todo & (np.mean(e > lx, axis=1) <= share)
        out[ok] = k
        todo &= ~ok
    return out


def glare_choice(dgp: list[np.ndarray], limit: float) -> np.ndarray:
    """Each hour's state by the glare rule: the first whose DGP (H, V) is at most ``limit`` at every view."""
    n_h = dgp[0].shape[0]
    out = np.full(n_h, len(dgp) - 1, np.int64)
    todo = np.ones(n_h, bool)
    for k, g in enumerate(dgp):
        ok = todo & np.all(g <= limit, axis=1)
        out[ok] = k
        todo &= ~ok
    return out


def schedule_choice(states: list[str], schedule: dict, month: np.ndarray, hour: np.ndarray) -> np.ndarray:
    """Each hour's state by the schedule (module docstring); ``month`` 1–12 and ``hour`` (of day, LST) of each hour's centre."""
    month = np.asarray(month)
    hour = np.asarray(hour, np.float64)
    out = np.zeros(len(month), np.int64)
    todo = np.ones(len(month), bool)
    for k, name in enumerate(states):
        held = np.zeros(len(month), bool)
        for m0, m1, h0, h1 in schedule.get(name, []):
            in_m = (month >= m0) & (month <= m1) if m0 <= m1 else (month >= m0) | (month <= m1)
            held |= in_m & (hour >= h0) & (hour < h1)
        ok = todo & held
        out[ok] = k
        todo &= ~ok
    return out


def state_hours(choice: np.ndarray, occupied: np.ndarray, n_states: int, hour_weight: float = 1.0) -> np.ndarray:
    """Occupied hours spent in each state, shape (n_states,)."""
    return np.bincount(np.asarray(choice)[np.asarray(occupied, bool)], minlength=n_states).astype(np.float64) * hour_weight
