"""When the planner reads direct light exactly (method ``exact``).

A sensor whose reading is direct light only (nothing it sees reflects) gets
``exact`` — Lambert's formula on the visible part of each light, penumbrae
exact, no variance (:mod:`simulator.engine.exact`) — when

- it is an irradiance sensor,
- every light that can reach it is an unshaped RectLight and no surface
  emits, and
- at most :data:`EXACT_MAX_OCCLUDERS` triangles stand in front of both the
  sensor and a light's emitting side (the shadows are projected and merged
  per sensor, so the cost grows with them; past this, shadow rays are
  cheaper for the same error).
"""

from __future__ import annotations

import numpy as np

from simulator.engine.exact import exact_refusal
from simulator.scene.model import Scene, Sensor, SensorKind

__all__ = ["EXACT_MAX_OCCLUDERS", "EXACT_MAX_SCENE_TRIANGLES", "exact_plan_refusal", "exact_plan_refusals"]

#: occluder triangles in front of a sensor above which shadow rays are used
#: instead. A chosen bound, not a measured crossover: at a dozen candidates
#: the method costs ~0.4 ms per sensor and light (215 office receivers × 6
#: lamps in 0.53 s), growing with the shadows merged per receiver.
EXACT_MAX_OCCLUDERS = 256

#: stages with more triangles than this are not scanned per sensor for the
#: count above (one numpy pass over every triangle per sensor; at this size
#: that stays in the milliseconds): shadow rays read them
EXACT_MAX_SCENE_TRIANGLES = 20_000


#: sensors × triangles whose heights :func:`exact_plan_refusals` computes at once (~200 bytes each)
_PAIRS = 1 << 18


def exact_plan_refusals(scene: Scene, sensors: list[Sensor], culled: list[list[str]]) -> list[str | None]:
    """:func:`exact_plan_refusal` of each sensor (``culled``: each one's culled lights), the
    per-scene parts computed once and the occluder count of every sensor in stacked products (the
    same arithmetic per sensor, so the same answers)."""
    out: list[str | None] = [None] * len(sensors)
    g = scene.geometry
    pending = []  # sensors that get as far as counting occluders
    refused = bool(g.n_triangles and np.any(g.emission > 0)) or g.has_surfaces  # for every sensor
    for i, (s, c) in enumerate(zip(sensors, culled)):
        if s.kind != SensorKind.IRRADIANCE or refused:
            out[i] = exact_plan_refusal(scene, s, c)
            continue
        lights = [l for l in scene.lights if l.name not in c]
        why = next((w for l in lights if (w := exact_refusal(l)) is not None), None)
        if why is not None or not lights or g.n_triangles == 0:
            out[i] = why
        elif g.n_triangles > EXACT_MAX_SCENE_TRIANGLES:
            out[i] = f"a large stage ({g.n_triangles} triangles): shadow rays"
        else:
            pending.append(i)
    if not pending:
        return out
    pts = g.points[g.triangles]
    tol = 1e-9 * max(1.0, float(np.abs(pts).max()))
    emitting_of = {l.name: np.any((pts - l.position) @ -l.frame[:, 2] > tol, axis=1) for l in scene.lights}
    groups: dict[tuple, int] = {}  # by culled set: the triangles in front of the lights left, one row each
    group = np.array([groups.setdefault(tuple(culled[i]), len(groups)) for i in pending])
    emitting = np.zeros((len(groups), len(pts)), bool)
    for key, k in groups.items():
        for l in scene.lights:
            if l.name not in key:
                emitting[k] |= emitting_of[l.name]
    P = np.array([sensors[i].position for i in pending], float)
    N = np.array([sensors[i].normal for i in pending], float)
    step = max(1, _PAIRS // len(pts))
    counts = np.zeros(len(pending), np.int64)
    for a in range(0, len(pending), step):
        d = pts[None] - P[a : a + step, None, None, :]
        front = np.any((d @ N[a : a + step, None, :, None])[..., 0] > tol, axis=2)  # (s, T), as the scan's products
        counts[a : a + step] = np.count_nonzero(front & emitting[group[a : a + step]], axis=1)
    for i, n in zip(pending, counts.tolist()):
        if n > EXACT_MAX_OCCLUDERS:
            out[i] = f"{n} triangles may block its lights (more than {EXACT_MAX_OCCLUDERS})"
    return out


def exact_plan_refusal(scene: Scene, sensor: Sensor, culled: list[str]) -> str | None:
    """Why ``exact`` cannot read this sensor, or None if it can."""
    if sensor.kind != SensorKind.IRRADIANCE:
        return f"exact direct light reads irradiance sensors, not a {sensor.kind.name.lower()} sensor"
    g = scene.geometry
    if g.n_triangles and np.any(g.emission > 0):
        return "emissive surfaces are lights too"
    if g.has_surfaces:
        return "panes or cut-outs pass part of the light: shadow rays through them"
    lights = [l for l in scene.lights if l.name not in culled]
    if not lights:
        return None
    for l in lights:
        if (why := exact_refusal(l)) is not None:
            return why
    if g.n_triangles == 0:
        return None
    if g.n_triangles > EXACT_MAX_SCENE_TRIANGLES:
        return f"a large stage ({g.n_triangles} triangles): shadow rays"
    pts = g.points[g.triangles]
    tol = 1e-9 * max(1.0, float(np.abs(pts).max()))
    front = np.any((pts - sensor.position) @ sensor.normal > tol, axis=1)
    emitting = np.zeros(len(pts), bool)
    for l in lights:
        emitting |= np.any((pts - l.position) @ -l.frame[:, 2] > tol, axis=1)
    n = int(np.count_nonzero(front & emitting))
    if n > EXACT_MAX_OCCLUDERS:
        return f"{n} triangles may block its lights (more than {EXACT_MAX_OCCLUDERS})"
    return None

