"""Light groups: each group's contribution traced once per sensor, recombined for any dimming vector.

Light transport is linear in emission: the reading of a sensor with group
``g`` at level ``d_g`` is ``E(d) = Σ_g d_g · E_g``, where ``E_g`` is the
reading with only group ``g`` lit at its authored emission. So a study
traces each group once and every dimming scenario is a weighted sum.

Notes
-----
With group estimates ``Ê_g`` and their covariance ``C`` (G × G, per sensor
and channel), the recombined estimate and its standard error are

.. math:: \\hat E(d) = d^\\top \\hat E, \\qquad
          \\sigma(d) = \\sqrt{d^\\top C\\, d}.

:func:`trace_groups` traces each group as its own run: a copy of the scene
holding only that group's lights, read by the usual per-sensor plan, with a
seed of its own. The groups' random streams are independent, so ``C`` is
diagonal (``C_gg = σ_g²``; the covariance between groups is zero). The cost
is one run per group. A one-pass kernel that tallies each sample's
contribution per light group (the light index of each next-event estimate
and of each emitter a path hits) would trace all groups on shared paths for
about the cost of one run, and its per-sample group vectors would give the
full covariance; :class:`GroupReadings` is the interface it would fill.

Adaptive targets. With ``rel_error`` set and the trace group's scenarios
given, the target is the recombined reading's, not each group's own: a pilot
of ``samples`` per sensor and group estimates the group readings ``m_g``;
in scenario ``j`` the half-width budget ``rel·E_j`` is shared in proportion
to the contributions ``w_jg = d_jg·m_g / E_j`` (which sum to 1), so that
``Σ_g (d_jg·σ_g)² ≤ (rel·E_j / z)²`` holds when each group meets

.. math:: z\\,\\sigma_g \\le \\mathrm{rel}_g\\, m_g, \\qquad
          \\mathrm{rel}_g = \\mathrm{rel} \\cdot \\min_j \\sqrt{E_j / (d_{jg}\\, m_g)} \\;\\ge\\; \\mathrm{rel}.

A group that gives a tenth of a sensor's light may stop at √10 times the
relative error, about a tenth of the samples. Targets are rounded down to
steps of √2 (sensors with one step are run together) and capped at
:data:`MAX_GROUP_REL_ERROR`. The pilot is an estimate, so the recombined
target is met approximately, as an adaptive run's is.

The engine's light mask (``Engine.set_light_mask``) only culls next-event
estimates at a sensor's first vertex (it is the planner's "light wholly
behind the sensor" switch); light a masked group sends by interreflection
or that a cosine-sampled ray hits would still be counted, so it cannot
switch a group off. That is why a group is traced on its own scene copy.
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass, replace

import numpy as np

from simulator.scene.model import Geometry, Scene, Sensor

__all__ = ["GroupReadings", "trace_groups", "group_scene", "derive_seed", "group_targets", "MAX_GROUP_REL_ERROR"]

#: loosest relative target a group trace is given
MAX_GROUP_REL_ERROR = 0.5


def derive_seed(*parts) -> int:
    """A seed in ``[0, 2**31)`` from any printable parts (SHA-256 of their ``|``-joined text)."""
    h = hashlib.sha256("|".join(str(p) for p in parts).encode()).digest()
    return int.from_bytes(h[:4], "little") & 0x7FFFFFFF


@dataclass
class GroupReadings:
    """Per-group readings of a block of sensors.

    Attributes
    ----------
    names : list of str
        Group names, length G.
    mean : ndarray, shape (G, S, 2)
        Reading of each sensor with only group g lit at its authored level;
        channels (radiometric, photometric) as the engine reports them.
    stderr : ndarray, shape (G, S, 2)
        Standard error of ``mean``.
    cov : ndarray, shape (S, 2, G, G)
        Covariance of the group estimates per sensor and channel.
    samples : ndarray, shape (G, S), int64
    trace_s : ndarray, shape (G,)
        Wall-clock seconds per group trace.
    """

    names: list[str]
    mean: np.ndarray
    stderr: np.ndarray
    cov: np.ndarray
    samples: np.ndarray
    trace_s: np.ndarray

    def combine(self, levels: dict[str, float]) -> tuple[np.ndarray, np.ndarray]:
        """Readings ``(mean, stderr)``, each (S, 2), of the dimming vector ``levels``
        (group name → level; groups not named are off)."""
        d = np.array([float(levels.get(n, 0.0)) for n in self.names])
        mean = np.einsum("g,gsc->sc", d, self.mean)
        var = np.einsum("g,scgh,h->sc", d, self.cov, d)
        return mean, np.sqrt(np.maximum(var, 0.0))


def group_scene(scene: Scene, light_names: list[str]) -> Scene:
    """A copy of ``scene`` with only the named lights and no emissive surfaces."""
    keep = set(light_names)
    g = scene.geometry
    geom = Geometry(g.points, g.triangles, g.albedo, np.zeros_like(g.emission), g.two_sided, g.prim, g.prim_names)
    return replace(scene, geometry=geom, lights=[l for l in scene.lights if l.name in keep], sensors=[], warnings=[])


def group_targets(pilot: np.ndarray, scenarios: list[dict[str, float]], names: list[str], rel_error: float) -> np.ndarray:
    """Per-group, per-sensor relative targets ``rel_g`` (G, S) from pilot readings (see Notes of the module).

    Parameters
    ----------
    pilot : ndarray, shape (G, S, 2)
        Pilot group readings.
    scenarios : list of dict
        Dimming vectors (group name → level) of the trace group.
    names : list of str
        Group order of ``pilot``.
    rel_error : float
        The recombined readings' target.
    """
    m = np.abs(pilot).max(axis=2)  # both channels are proportional for grey scenes; take the larger
    d = np.array([[float(sc.get(n, 0.0)) for n in names] for sc in scenarios])  # (J, G)
    e = np.einsum("jg,gs->js", d, m)  # (J, S)
    out = np.full(m.shape, np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for g in range(len(names)):
            lit = d[:, g] > 0
            if not lit.any():
                continue
            ratio = e[lit] / (d[lit, g][:, None] * m[g][None, :])  # (J_lit, S), >= 1
            out[g] = np.nanmin(np.where(np.isfinite(ratio), ratio, np.inf), axis=0)
    rel = rel_error * np.sqrt(np.maximum(out, 1.0))
    steps = np.floor(2.0 * np.log2(np.minimum(rel, MAX_GROUP_REL_ERROR) / rel_error) + 1e-9)
    return np.minimum(rel_error * 2.0 ** (np.maximum(steps, 0.0) / 2.0), MAX_GROUP_REL_ERROR)


def _run_targets(engine, plan, sim, rel: np.ndarray):
    """Like :func:`simulator.pipeline.run_plan`, with a relative target per sensor (run in groups of equal target)."""
    n = len(plan.sensors)
    mean, stderr, samples = np.zeros((n, 2)), np.zeros((n, 2)), np.zeros(n, np.int64)
    engine.set_light_mask(plan.light_mask([l.name for l in engine.scene.lights]))
    for method, ids in plan.groups().items():
        for r in np.unique(rel[ids]) if method != "analytic" else [None]:
            sub = ids if r is None else ids[rel[ids] == r]
            res = engine.run(
                method, samples=sim.samples, seed=sim.seed, rel_error=None if r is None else float(r), abs_error=sim.abs_error,
                max_samples=sim.sample_cap, time_limit_s=None, max_depth=sim.max_depth, component=sim.component,
                sensor_ids=sub, confidence=sim.confidence,
            )  # fmt: skip
            mean[sub], stderr[sub], samples[sub] = res.mean[sub], res.stderr[sub], res.samples[sub]
    return mean, stderr, samples


def trace_groups(scene: Scene, sensors: list[Sensor], groups: dict[str, list[str]], sim, seeds: dict[str, int],
                 threads: int = 0, scenarios: list[dict[str, float]] | None = None) -> GroupReadings:  # fmt: skip
    """Trace each light group's contribution to every sensor.

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
        Irradiance or radiance sensors (no probes).
    groups : dict of str to list of str
        Group name → light prim paths, in the order the result keeps.
    sim : SimulationConfig-like
        Samples, method, adaptive target; its ``seed`` is replaced per group.
    seeds : dict of str to int
        Seed per group (independent streams).
    threads : int
        CPU worker threads of the engine; 0 = all cores.
    scenarios : list of dict, optional
        The dimming vectors these readings will be recombined into. With an
        adaptive ``sim``, each group's target follows from them (see Notes of
        the module); without, every group must meet ``rel_error`` on its own.

    Returns
    -------
    GroupReadings
        With a diagonal covariance (independent traces; see Notes of the module).
    """
    from simulator.engine.driver import Engine
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan

    names = list(groups)
    n_g, n_s = len(names), len(sensors)
    mean = np.zeros((n_g, n_s, 2))
    stderr = np.zeros((n_g, n_s, 2))
    samples = np.zeros((n_g, n_s), np.int64)
    trace_s = np.zeros(n_g)
    runs = []
    for k, name in enumerate(names):
        sub = group_scene(scene, groups[name])
        t0 = time.perf_counter()
        engine = Engine(sub, sensors, device=sim.device, threads=threads)
        plan = make_plan(sub, sensors, sim.method, sim.component)
        runs.append((engine, plan, replace(sim, seed=int(seeds[name]))))
        trace_s[k] = time.perf_counter() - t0
    if sim.adaptive and scenarios:
        for k, (engine, plan, s) in enumerate(runs):
            t0 = time.perf_counter()
            mean[k] = run_plan(engine, plan, replace(s, rel_error=None)).mean
            trace_s[k] += time.perf_counter() - t0
        rel = group_targets(mean, scenarios, names, sim.rel_error)
        for k, (engine, plan, s) in enumerate(runs):
            t0 = time.perf_counter()
            mean[k], stderr[k], samples[k] = _run_targets(engine, plan, s, rel[k])
            trace_s[k] += time.perf_counter() - t0
    else:
        for k, (engine, plan, s) in enumerate(runs):
            t0 = time.perf_counter()
            res = run_plan(engine, plan, s)
            trace_s[k] += time.perf_counter() - t0
            mean[k], stderr[k], samples[k] = res.mean, res.stderr, res.samples
    cov = np.zeros((n_s, 2, n_g, n_g))
    idx = np.arange(n_g)
    cov[:, :, idx, idx] = np.transpose(stderr**2, (1, 2, 0))
    return GroupReadings(names, mean, stderr, cov, samples, trace_s)
