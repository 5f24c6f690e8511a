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

__all__ = ["GroupReadings", "trace_groups", "group_scene", "derive_seed"]


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
        Samples per sensor (one pass: the same for every group).
    trace_s : ndarray, shape (G,)
        Wall-clock seconds of the pass, shared evenly among the groups (their sum is the pass's time).
    trace_cpu_s : float
        CPU seconds of the pass (this process, all its threads): a cost figure
        less sensitive than wall time to other work on the machine.
    """

    names: list[str]
    mean: np.ndarray
    stderr: np.ndarray
    cov: np.ndarray
    samples: np.ndarray
    trace_s: np.ndarray
    trace_cpu_s: float = 0.0

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


#: methods that read direct light only: a group whose light has a closed form there may be read in it
_DIRECT_METHODS = ("light", "mis", "bsdf")


def _closed_forms_of_groups(sub: Scene, sensors: list[Sensor], names: list[str], groups: dict[str, list[str]], plan, sim,
                            threads: int, mean: np.ndarray, cov: np.ndarray) -> None:  # fmt: skip
    """Where the pass read a sensor by direct-light sampling, read each group that has a closed form
    there on its own (the planner's choice for that group's lights alone), in place of its sampled
    estimate: ``mean[g, s]`` exact, its covariance row and column 0. The sampled estimate held
    direct light only (the method does not bounce), so the exact value replaces it wholly."""
    from simulator.engine.driver import Engine
    from simulator.plan.planner import make_plan

    direct = np.array([i for i, sp in enumerate(plan.sensors) if sp.method in _DIRECT_METHODS], np.int64)
    if not len(direct) or len(names) < 2:
        return  # one group: the union's plan is that group's own
    ss = [sensors[i] for i in direct]
    for k, n in enumerate(names):
        keep = set(groups[n])
        gs = replace(sub, lights=[l for l in sub.lights if l.name in keep])
        gp = make_plan(gs, ss, "auto", sim.component)
        closed = {m: ids for m, ids in gp.groups().items() if m in ("analytic", "exact")}
        if not closed:
            continue
        eng = Engine(gs, ss, device=sim.device, threads=threads)
        eng.set_light_mask(gp.light_mask([l.name for l in gs.lights]))
        for m, ids in closed.items():
            r = eng.run(m, samples=0, seed=0, sensor_ids=ids, component=sim.component)
            rows = direct[ids]
            mean[k, rows] = r.mean[ids]
            cov[rows, :, k, :] = 0.0
            cov[rows, :, :, k] = 0.0


def trace_groups(scene: Scene, sensors: list[Sensor], groups: dict[str, list[str]], sim, seed: int,
                 threads: int = 0, scenarios: list[dict[str, float]] | None = None) -> GroupReadings:  # fmt: skip
    """Trace every light group's contribution to every sensor in one pass.

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
        Irradiance or radiance sensors (no probes).
    groups : dict of str to list of str
        Group name → light prim paths, in the order the result keeps.
    sim : SimulationConfig-like
        Samples, method, adaptive target; its ``seed`` is replaced by ``seed``.
    seed : int
        Seed of the pass (all groups share its paths).
    threads : int
        CPU worker threads of the engine; 0 = all cores.
    scenarios : list of dict, optional
        The dimming vectors these readings will be recombined into. With an
        adaptive ``sim`` a sensor stops when every one of them meets
        ``rel_error`` (see Notes of the module); without, when the total does.

    Returns
    -------
    GroupReadings
        With the full covariance between groups (shared paths).
    """
    from simulator.engine.driver import Engine, LightGroups, load_kernels
    from simulator.plan.planner import make_plan

    load_kernels(sim.device)  # once per process: not part of the pass's time
    names = list(groups)
    n_g, n_s = len(names), len(sensors)
    owner = {l: k for k, n in enumerate(names) for l in groups[n]}
    t0, c0 = time.perf_counter(), time.process_time()
    sub = group_scene(scene, list(owner))
    engine = Engine(sub, sensors, device=sim.device, threads=threads)
    plan = make_plan(sub, sensors, sim.method, sim.component)
    light_group = np.array([owner[l.name] for l in sub.lights], np.int64)
    levels = None
    if sim.adaptive and scenarios:
        levels = np.array([[float(sc.get(n, 0.0)) for n in names] for sc in scenarios])
    lg = LightGroups(light_group, n_g, levels)
    mean = np.zeros((n_g, n_s, 2))
    cov = np.zeros((n_s, 2, n_g, n_g))
    samples = np.zeros(n_s, np.int64)
    engine.set_light_mask(plan.light_mask([l.name for l in sub.lights]))
    for method, ids in plan.groups().items():
        r = engine.run_groups(
            method, lg, samples=sim.samples, seed=int(seed), rel_error=sim.rel_error, abs_error=sim.abs_error,
            max_samples=sim.sample_cap, time_limit_s=None, max_depth=sim.max_depth, component=sim.component,
            sensor_ids=ids, confidence=sim.confidence,
        )  # fmt: skip
        mean[:, ids], cov[ids], samples[ids] = r.group_mean[:, ids], r.group_cov[ids], r.samples[ids]
    if sim.method == "auto":
        _closed_forms_of_groups(sub, sensors, names, groups, plan, sim, threads, mean, cov)
    stderr = np.sqrt(np.maximum(np.transpose(np.diagonal(cov, axis1=2, axis2=3), (2, 0, 1)), 0.0))
    trace_s = np.full(n_g, (time.perf_counter() - t0) / max(n_g, 1))
    return GroupReadings(names, mean, stderr, cov, np.broadcast_to(samples, (n_g, n_s)).copy(), trace_s, time.process_time() - c0)
