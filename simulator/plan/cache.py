"""Plans a Python process has made, kept for its next runs of the same scene and sensors.

A plan (:func:`simulator.plan.planner.make_plan`) depends on the scene, the
sensors and the requested method and component only. It is kept under

- the scene's token from :func:`simulator.scene.stage_cache.cached_stage`
  (one per reading of a stage: a changed file, variant, time or light unit
  is a new reading, hence a new token),
- a digest of every sensor's fields (name, kind, position, normal, up, size,
  half-angle, resolution, grid, source), and
- the requested method and component, and the planner's tunable bounds
  (``AUTO_GUIDED``, ``LARGE_SOURCE_SR``, the ``exact`` rule's bounds, the
  emitter pieces' sizes its note states).

A scene without a token (not kept by the stage cache) is planned afresh each
time. The :data:`MAX_ENTRIES` most recently used plans are kept (at most
:data:`MAX_SENSORS` sensors in all). Callers
must not change a plan they are given (the run reads it and writes its
record; nothing changes it).
"""

from __future__ import annotations

import hashlib

import numpy as np

from simulator.memo import Kept

__all__ = ["MAX_ENTRIES", "MAX_SENSORS", "sensors_digest", "cached_plan", "clear"]

#: plans kept (least recently used dropped first)
MAX_ENTRIES = 8
#: sensors in all the kept plans (a plan holds ~1 kB per sensor with its encoded record)
MAX_SENSORS = 1 << 18

_entries = Kept(MAX_ENTRIES, MAX_SENSORS)


def sensors_digest(sensors) -> bytes:
    """SHA-256 over every field of every sensor, in order (positions and directions by their float64 bytes)."""
    h = hashlib.sha256()
    n = len(sensors)
    h.update(n.to_bytes(8, "little"))
    if n:
        for attr in ("position", "normal", "up"):
            h.update(np.array([getattr(s, attr) for s in sensors], np.float64).reshape(n, -1).tobytes())
        h.update(np.array([(*s.size, s.half_angle, *s.resolution) for s in sensors], np.float64).tobytes())
        h.update("\x1f".join(f"{s.name}\x1e{s.kind.name}\x1e{s.grid}\x1e{s.source}" for s in sensors).encode())
    return h.digest()


def _rules() -> tuple:
    """The planner's tunable rules at this moment (a changed bound is a different plan)."""
    from simulator.plan import exact_rule, planner
    from simulator.scene import emitters  # the plan's note on emitter pieces

    return (planner.AUTO_GUIDED, planner.LARGE_SOURCE_SR, exact_rule.EXACT_JOB_S, exact_rule.EXACT_OCCLUDER_S,
            exact_rule.EXACT_MAX_S, exact_rule.PATH_SAMPLE_S, exact_rule.HYBRID_MAX_S, emitters.PIECE_M,
            emitters.SPLIT_M, emitters.MAX_PIECES, emitters.MAX_SPLIT, emitters.PIECES_MIN_GAIN)


def cached_plan(make, token: int | None, sensors, requested: str, component: str):
    """The plan ``make()`` returns, or the one kept for this scene token, sensors, method and component."""
    if token is None:
        return make()
    key = (token, sensors_digest(sensors), requested, component, _rules())
    plan = _entries.get(key)
    if plan is not None:
        return plan
    plan = make()
    if len(plan.sensors) <= MAX_SENSORS:
        _entries.put(key, plan, size=len(plan.sensors))
    return plan


def clear() -> None:
    """Forget every kept plan."""
    _entries.clear()
