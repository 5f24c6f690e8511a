"""Light groups: every group's contribution traced in one pass per sensor, recombined for any dimming vector.

Light transport is linear in emission: the reading of a sensor with group
``g`` at level ``d_g`` is ``E(d) = Σ_g d_g · E_g``, where ``E_g`` is the
reading with only group ``g`` lit at its authored emission. So a study
traces the groups of a trace group once and every dimming scenario is a
weighted sum.

Notes
-----
With group estimates ``Ê_g`` and their covariance ``C`` (G × G, per sensor
and channel), the recombined estimate and its standard error are

.. math:: \\hat E(d) = d^\\top \\hat E, \\qquad
          \\sigma(d) = \\sqrt{d^\\top C\\, d}.

One pass. :func:`trace_groups` traces a copy of the scene holding the
lights of all the groups (no emissive surfaces, no light of no group) once,
by the per-sensor plan of that union of lights. The estimator kernel tallies
every emitted-light contribution to a sample (each next-event estimate, each
light a direction hits, each emitter a path meets) into the slot of its
light's group as well as into the total (``light_contribution`` in
:mod:`simulator.kernels.estimators`), so each sample is a vector
``x = (x_1 … x_G)`` per channel with ``Σ_g x_g`` the sample itself. Each
kernel thread keeps shifted sums ``Σ(x_g − K_g)`` and the lower triangle of
``Σ(x_g − K_g)(x_h − K_h)`` (float64, K its first sample), merged on the
host by the multivariate pairwise update
(:class:`simulator.engine.stats.GroupStats`); ``C = M / (n(n − 1))`` with
``M`` the co-moment matrix. The groups share every path, so ``C`` is the
full covariance: negative where one direction reaches either one group or
another (the sky through the window, or a lamp on the ceiling), positive
where one path carries both groups' interreflected light. The sum of the
group means equals the pass's total to float32 rounding (tested to 1e-5).

Sky patches (daylight coefficients). A group holding one DomeLight named in
``sky_split`` is traced as 146 slots, Tregenza's 145 sky patches and the
ground below the horizon (:mod:`simulator.study.inputs.sky_patches`, names
``group/p000`` … ``group/p144``, ``group/ground``): the dome's call sites in
the kernel pass the direction its light arrives from
(``light_contribution_dir``) and the light goes to that direction's patch.
Any sky is then a recombination, E = Σ_p c_p·L_p/L_dome, σ² = dᵀCd with
d_p = L_p/L_dome; a scenario's level for the group itself (no patch
entries) applies to every slot, the authored dome. With 146 slots the
per-sample cross tally (G(G + 3) float64 pairs a thread, ~20× a plain run's
time, measured) gives way to batch means: each kernel thread's block of 32
samples is a batch and C is their covariance over N(B − 1)
(:class:`simulator.engine.stats.GroupBatchStats`; B − 1 degrees of freedom,
31 at 1024 samples). Measured on the bundled study's 54 sensors (guided
paths, CPU time, medians of 5 on a shared 2-core machine, noisy): a
146-slot pass cost 1.32× one plain run of the dome at 1024 samples and
1.27× at 2048; 1,500 sensors in chunks of 32 at 1024 samples 20 s and
351 MiB peak against 17 s and 291 MiB for the dome whole.

Exactness where a closed form applies: sensors the union's plan reads in
closed form (``analytic``, ``exact``) are read per group in it (standard
error and covariance 0), and where the pass samples direct light only
(``light``, ``mis``), a group whose own lights have a closed form at that
sensor is read in it in place of its sampled estimate.

Adaptive targets. With ``rel_error`` set and the trace group's scenarios
given, a sensor stops when the recombined reading of every scenario meets
the target, ``z·sqrt(dᵀCd) ≤ max(rel·|dᵀÊ|, abs)`` in both channels (the
engine's stopping rule over the J scenarios as 2J channels;
:class:`simulator.engine.driver.LightGroups`); without scenarios, when the
total does. Every scenario's target is met as a run's would be (up to the
sample cap); the pass draws the samples of the sensor's hardest scenario, and
the easier scenarios come out more precise than asked.

Cost (the bundled ``configs/studies/office_study.toml``, 54 sensors, first
trace group 12 scenarios over 3 groups; 2-core CPU shared with other work,
so wall times varied up to 2× between repeats; CPU seconds of the process
are steadier). At a fixed budget of 1024 samples per sensor, the pass cost
0.99–1.01× the CPU time of one run of a scenario with all three groups lit
(the tallies' overhead is within the noise), where one run per group cost
1.32×. Adaptive (5%, at most 4096 samples), the pass cost 1.10–1.17× the
CPU time of one run of the hardest scenario with all groups lit: it drew
1.16× that run's samples, since its hardest scenario (sky without the
window row) asks more. One run
per group, whose groups could stop apart (a group with a small share of a
sensor's light stopped early, the sky alone ran to the cap), cost 0.73×
there, its recombined targets met only approximately and without the
covariance. ``probesim study`` records these figures in ``study.json``
(``cost``: wall and CPU seconds per trace group against the single run,
samples and time per sample).
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass, field, replace

import numpy as np

from simulator.scene.model import Scene, Sensor

__all__ = ["GroupReadings", "trace_groups", "group_scene", "derive_seed", "patch_names", "level_of"]

#: slots of a dome split into sky patches: the 145 Tregenza patches and the ground (below the horizon)
SKY_SLOTS = 146


def patch_names(group: str) -> list[str]:
    """Names of a split sky group's slots: ``group/p000`` … ``group/p144`` and ``group/ground``."""
    return [f"{group}/p{p:03d}" for p in range(SKY_SLOTS - 1)] + [f"{group}/ground"]


def level_of(levels: dict, name: str) -> float:
    """A slot's level: its own entry, else (a sky patch ``group/…``) its group's, else 0."""
    if name in levels:
        return float(levels[name])
    if "/" in name:
        return float(levels.get(name.split("/", 1)[0], 0.0))
    return 0.0


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
    methods : list of str
        The method each sensor was read by in the pass (the union's plan), length S.
    """

    names: list[str]
    mean: np.ndarray
    stderr: np.ndarray
    cov: np.ndarray
    samples: np.ndarray
    trace_s: np.ndarray
    trace_cpu_s: float = 0.0
    methods: list = field(default_factory=list)

    def combine(self, levels: dict[str, float]) -> tuple[np.ndarray, np.ndarray]:
        """Readings ``(mean, stderr)``, each (S, 2), of the dimming vector ``levels``
        (group name → level; groups not named are off)."""
        from simulator.engine.stats import lit_variance

        d = np.array([level_of(levels, n) for n in self.names])
        mean = np.einsum("g,gsc->sc", d, self.mean)
        return mean, np.sqrt(np.maximum(lit_variance(d, self.cov), 0.0))


def group_scene(scene: Scene, light_names: list[str]) -> Scene:
    """A copy of ``scene`` with only the named lights and no emissive surfaces."""
    keep = set(light_names)
    g = scene.geometry
    geom = replace(g, emission=np.zeros_like(g.emission))  # every other field kept (colours, measured curves)
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
        if n not in groups:
            continue  # a sky patch: no closed form of its own
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
                 threads: int = 0, scenarios: list[dict[str, float]] | None = None,
                 sky_split: tuple[str, ...] = ()) -> GroupReadings:  # fmt: skip
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
        A split sky's slots take their own entry (``sky/p012``) or the group's.
    sky_split : tuple of str
        Groups, each one dome light, whose sky is split into Tregenza's 145
        patches and the ground: the result names their slots
        (:func:`patch_names`) in place of the group, and the covariance comes
        from batch means (see Notes of the module).

    Returns
    -------
    GroupReadings
        With the full covariance between groups (shared paths).
    """
    from simulator.engine.driver import Engine, LightGroups, load_kernels
    from simulator.plan.planner import make_plan

    load_kernels(sim.device, scene)  # once per process: not part of the pass's time
    from simulator.scene.model import LightKind

    names: list[str] = []
    owner: dict[str, int] = {}
    split_lights: dict[str, int] = {}  # dome -> its first slot
    for n in groups:
        if n in sky_split:
            domes = [l for l in scene.lights if l.name in groups[n]]
            if len(groups[n]) != 1 or len(domes) != 1 or domes[0].kind != LightKind.DOME:
                raise ValueError(f"group {n!r}: a sky split into patches must hold one DomeLight")
            split_lights[groups[n][0]] = len(names)
            owner[groups[n][0]] = len(names) + SKY_SLOTS - 1  # the ground slot: any call site without a direction
            names += patch_names(n)
        else:
            owner.update({l: len(names) for l in groups[n]})
            names.append(n)
    n_g, n_s = len(names), len(sensors)
    t0, c0 = time.perf_counter(), time.process_time()
    sub = group_scene(scene, list(owner))
    engine = Engine(sub, sensors, device=sim.device, threads=threads)
    plan = make_plan(sub, sensors, sim.method, sim.component, hybrid=False)  # every light tallied on the paths
    light_group = np.array([owner[l.name] for l in sub.lights], np.int64)
    patch_base = np.array([split_lights.get(l.name, -1) for l in sub.lights], np.int64) if split_lights else None
    levels = pick = None
    if scenarios:
        pick = np.array([[level_of(sc, n) for n in names] for sc in scenarios])
        levels = pick if sim.adaptive else None
    lg = LightGroups(light_group, n_g, levels, patch_base=patch_base, pick_levels=pick)
    mean = np.zeros((n_g, n_s, 2))
    cov = np.zeros((n_s, 2, n_g, n_g))
    samples = np.zeros(n_s, np.int64)
    engine.set_light_mask(plan.light_mask([l.name for l in sub.lights]))
    for method, ids in plan.groups().items():
        if split_lights and method in ("analytic", "exact"):
            method = "mis"  # a closed form reads the dome whole, not per patch
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
    methods = [sp.method for sp in plan.sensors]
    if split_lights:
        methods = ["mis" if m in ("analytic", "exact") else m for m in methods]
    return GroupReadings(names, mean, stderr, cov, np.broadcast_to(samples, (n_g, n_s)).copy(), trace_s, time.process_time() - c0,
                         methods)  # fmt: skip
