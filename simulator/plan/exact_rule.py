"""When the planner computes direct light exactly: ``exact`` sensors, and the hybrids ``exact+path`` / ``exact+guided``.

:mod:`simulator.engine.exact` reads the direct light of RectLights,
DiskLights, uniform DomeLights and emissive triangles past any occluders
(Lambert's formula on each emitter's visible part), with no cap on the
occluders or the stage's size. Its cost is paid once per sensor, on the host;
what it saves is paid per sample. The planner weighs the two with a cost
model measured on the development machine (``python
benchmarks/exact_scaling.py`` prints the fit):

    t_exact(s) = Σ over the sensor's emitter polygons (t_job + t_occluder · n_occluders),

n_occluders the triangles the hull of the sensor and the emitter may hold
(a count of the hierarchy's cull by the sensor's own planes, an upper bound on
what the engine then clips, so a sensor's plan does not depend on the others'; a
dome's five half-cube faces count every triangle above the sensor's horizon), against the
time sampling spends on that sensor:

- a **direct-only** irradiance sensor (nothing it sees reflects) whose every
  light can be computed gets ``exact`` where t_exact ≤ :data:`EXACT_MAX_S`
  (its whole reading, with no noise, for less than the ~4,000 ``light``
  samples a penumbra's reading takes to 1%; the run's ``samples`` do not
  enter, so such a sensor's plan is the same at any budget);
- an irradiance sensor that needs **paths** gets the hybrid when the lights
  computed for it cost at most :data:`HYBRID_MAX_S`, a quarter of the time of
  the ~1,000 path samples a reading in a furnished room takes to a few percent
  (computed cheapest first; a light that would pass the budget stays sampled):
  the computed lights leave every sample's variance and rays at the sensor,
  and the reflected light is what is sampled. Whether that pays for a given
  run (its budget or target, the lights' share of the variance) the engine's
  pilot decides (``Engine._hybrid_choice``; the run record's ``hybrid``).

Never computed (their direct light stays sampled): point, sphere, cylinder
and distant lights (the sun), shaped lights, textured domes, and an emitter
a pane or a cut-out stands before for a sensor (the engine finds those); a
spectral run (hero wavelengths) samples everything.
"""

from __future__ import annotations

import numpy as np

from simulator.engine.exact import covered_records, record_polygons, transmitting
from simulator.scene.model import Scene, Sensor, SensorKind

__all__ = ["EXACT_JOB_S", "EXACT_OCCLUDER_S", "EXACT_MAX_S", "PATH_SAMPLE_S", "HYBRID_MAX_S", "RAY_S", "EMISSIVE",
           "exact_plan_refusal", "exact_plan_refusals", "exact_costs", "hybrid_records"]

#: seconds of host time per (sensor, emitter polygon) with nothing in the way (one CPU core;
#: benchmarks/exact_scaling.py)
EXACT_JOB_S = 6e-6
#: ... and per candidate occluder of that pair
EXACT_OCCLUDER_S = 1.2e-5
#: the most host seconds a direct-only sensor's exact reading may cost: ~4,000 ``light`` samples of
#: ~1 µs, what a penumbra of relative variance 0.1 per sample takes to a 1% half-width (1.96²·0.1/0.01²)
EXACT_MAX_S = 4e-3
#: seconds of one path sample in a furnished room (~15 rays at ~0.4 µs: docs/DESIGN.md §Per-sample cost)
PATH_SAMPLE_S = 6e-6
#: the most host seconds a path-traced sensor's computed direct light may cost: a quarter of 1,024
#: path samples (the default ``samples``) at :data:`PATH_SAMPLE_S`
HYBRID_MAX_S = 0.25 * 1024 * PATH_SAMPLE_S
#: seconds per ray of a path sample (6.49 µs over 15.07 rays on the office, docs/DESIGN.md §Per-sample
#: cost): the engine's pilot weighs the computed part, in this model's seconds, against rays counted
#: (so its choice is the same at any thread count or load)
RAY_S = 4.3e-7
#: the name the plan gives the emissive triangles' light record
EMISSIVE = "emissive surfaces"


def _names(scene: Scene) -> list[str]:
    """Each light record's name: the scene's lights, then the emissive triangles."""
    return [l.name for l in scene.lights] + ([EMISSIVE] if len(covered_records(scene)) > len(scene.lights) else [])


def exact_costs(scene: Scene, sensors: list[Sensor], records: list[list[int]]) -> tuple[np.ndarray, np.ndarray]:
    """Predicted seconds of the exact direct light of each (sensor, record), by the module's cost model,
    and whether a pane or a cut-out may stand in its way (its direct light is then sampled).

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
        Irradiance sensors.
    records : list of list of int
        Per sensor, the light records to cost (indices over the scene's lights, then the emissive
        triangles).

    Returns
    -------
    (seconds, blocked) : ndarray (S, R), ndarray of bool (S, R)
        Seconds (0 where not asked); a transmitting face among the candidates (conservative: one
        its hull with the emitter may hold).
    """
    from simulator.engine.exact import occluder_index
    from simulator.engine.occluders import pyramid_planes

    n_rec = len(_names(scene))
    out = np.zeros((len(sensors), n_rec))
    blocked = np.zeros((len(sensors), n_rec), bool)
    if not sensors:
        return out, blocked
    trans = transmitting(scene.geometry)
    tidx = occluder_index(scene, trans) if trans.any() else None
    P = np.array([s.position for s in sensors], float)
    N = np.array([s.normal for s in sensors], float)
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    idx = occluder_index(scene)
    for r in range(n_rec):
        who = np.array([i for i, rs in enumerate(records) if r in rs], np.int64)
        if not len(who):
            continue
        polys = record_polygons(scene, r)
        if polys is None:  # a dome: five faces, each may hold what is above the horizon
            pl = np.concatenate([N[who], np.einsum("sd,sd->s", N[who], P[who])[:, None]], axis=1)[:, None]
            n_occ = idx.cull(pl, count_only=True) if idx.n else np.zeros(len(who), np.int64)
            out[who, r] = 5 * EXACT_JOB_S + 1.5 * EXACT_OCCLUDER_S * n_occ
            if tidx is not None:
                blocked[who, r] = tidx.cull(pl, count_only=True) > 0
            continue
        for q in range(len(polys.cnt)):
            V, c = polys.V[q], int(polys.cnt[q])
            m = np.cross(V[1] - V[0], V[2] - V[0])
            side = (P[who] - V[0]) @ m
            sees = (np.abs(side) > 0) & (~polys.one_sided[q] | (side > 0))
            sees &= np.any((V[:c][None] - P[who][:, None]) @ N[who][:, :, None] > 0, axis=(1, 2))
            w = who[sees]
            if not len(w):
                continue
            if polys.combine == "bound" and q == 1:
                out[w, r] *= 2.0  # the outer polygon costs what the inner did
                continue
            if not idx.n:
                out[w, r] += EXACT_JOB_S
                continue
            # each receiver's own candidate count (its planes', not its cluster's: the same whatever
            # sensors a plan is asked for)
            pl = pyramid_planes(P[w], N[w], np.broadcast_to(V, (len(w), *V.shape)), np.full(len(w), c))
            out[w, r] += EXACT_JOB_S + EXACT_OCCLUDER_S * idx.cull(pl, count_only=True)
            if tidx is not None:
                blocked[w, r] |= tidx.cull(pl, count_only=True) > 0
    return out, blocked


def _coverable(scene: Scene, culled: list[str]) -> tuple[list[int], list[int], str | None]:
    """(records computable, records that reach the sensor but are not computable, why the first of
    those is not)."""
    ok, not_ok, why = [], [], None
    names = _names(scene)
    for r, reason in covered_records(scene):
        if names[r] in culled:
            continue
        if reason is None:
            ok.append(r)
        else:
            not_ok.append(r)
            why = why or reason
    return ok, not_ok, why


def exact_plan_refusals(scene: Scene, sensors: list[Sensor], culled: list[list[str]]) -> list[str | None]:
    """:func:`exact_plan_refusal` of each sensor (``culled``: each one's culled lights), the costs of
    all of them in one clustered pass."""
    out: list[str | None] = [None] * len(sensors)
    pending, recs = [], []
    g = scene.geometry
    for i, (s, c) in enumerate(zip(sensors, culled)):
        why = _static_refusal(scene, s, c)
        if why is not None:
            out[i] = why
            continue
        ok, _, _ = _coverable(scene, c)
        if ok and g.n_triangles:
            pending.append(i)
            recs.append(ok)
    if not pending:
        return out
    cost = exact_costs(scene, [sensors[i] for i in pending], recs)[0].sum(axis=1)
    for i, t in zip(pending, cost.tolist()):
        if t > EXACT_MAX_S:
            out[i] = f"computing its direct light would take ~{1e3 * t:.2g} ms (more than {1e3 * EXACT_MAX_S:g} ms): light sampling"
    return out


def _static_refusal(scene: Scene, sensor: Sensor, culled: list[str]) -> str | None:
    """The refusals that do not depend on cost."""
    if sensor.kind != SensorKind.IRRADIANCE:
        return f"exact direct light reads irradiance sensors, not a {sensor.kind.name.lower()} sensor"
    if transmitting(scene.geometry).any():
        return "panes or cut-outs pass part of the light: shadow rays through them"
    ok, not_ok, why = _coverable(scene, culled)
    if not_ok:
        return why
    return None


def exact_plan_refusal(scene: Scene, sensor: Sensor, culled: list[str]) -> str | None:
    """Why ``exact`` cannot read this sensor (all its direct light), or None if it can."""
    return exact_plan_refusals(scene, [sensor], [culled])[0]


def hybrid_records(scene: Scene, sensors: list[Sensor], culled: list[list[str]]) -> list[tuple[list[int], str]]:
    """Per sensor that needs paths: the light records whose direct light the hybrid computes for it
    (empty: none; read by paths alone) and why.

    A record is computed where it can be (:func:`simulator.engine.exact.covered_records`) and no
    pane or cut-out may stand in its way, cheapest first while the total stays within
    :data:`HYBRID_MAX_S`."""
    out: list[tuple[list[int], str]] = [([], "")] * len(sensors)
    names = _names(scene)
    pending, recs = [], []
    for i, (s, c) in enumerate(zip(sensors, culled)):
        if s.kind != SensorKind.IRRADIANCE:
            continue
        ok, _, _ = _coverable(scene, c)
        if ok:
            pending.append(i)
            recs.append(ok)
    if not pending:
        return out
    cost, blocked = exact_costs(scene, [sensors[i] for i in pending], recs)
    budget = HYBRID_MAX_S
    for row, blk, i, ok in zip(cost, blocked, pending, recs):
        chosen, total = [], 0.0
        for r in sorted((r for r in ok if not blk[r]), key=lambda r: row[r]):
            if total + row[r] <= budget:
                chosen.append(r)
                total += row[r]
        chosen.sort()  # in the records' order
        left = [names[r] for r in ok if r not in chosen and not blk[r]]
        why = (f"direct light of {len(chosen)} emitter(s) computed (~{1e3 * total:.2g} ms, within {1e3 * budget:.2g} ms)"
               if chosen else "")
        if chosen and left:
            why += f"; sampled to keep within it: {', '.join(left)}"
        if chosen and blk.any():
            why += f"; sampled where a pane or a cut-out may stand in the way: {', '.join(names[r] for r in ok if blk[r])}"
        out[i] = (chosen, why)
    return out

