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

__all__ = ["EXACT_MAX_OCCLUDERS", "EXACT_MAX_SCENE_TRIANGLES", "exact_plan_refusal"]

#: occluder triangles in front of a sensor above which shadow rays are used
#: instead. A chosen bound, not a measured crossover: at a dozen candidates
#: the method costs ~0.4 ms per sensor and light (215 office receivers × 6
#: lamps in 0.53 s), growing with the shadows merged per receiver.
EXACT_MAX_OCCLUDERS = 256

#: stages with more triangles than this are not scanned per sensor for the
#: count above (one numpy pass over every triangle per sensor; at this size
#: that stays in the milliseconds): shadow rays read them
EXACT_MAX_SCENE_TRIANGLES = 20_000


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

