"""The engine: one scene resident on one Warp device, read in batches.

For every sensor kind, probes included, the driver lays out the kernel
threads of a batch, launches them over CPU workers (:mod:`.fanout`), merges
their shifted sums into float64 running statistics (:mod:`.stats`) and
stops each reading when it has its samples or meets its error target
(:mod:`.adaptive`). Uploads are :mod:`.device`'s; what only a probe needs
(its map layout and sphere integrals) is :mod:`.probes`'.

Sensors (irradiance, radiance, patch): each kernel thread draws a block of
``BLOCK`` samples of one sensor. Probes: each kernel thread draws up to
``PASS_BLOCK`` passes (one direction per pixel each) of one pixel.
"""

from __future__ import annotations

import os
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from simulator.engine import probes as P
from simulator.engine import kernel_modules as KM
from simulator.engine.adaptive import PILOT_MIN_BATCH, StoppingRule, first_batch_from_pilot, run_batches
from simulator.engine.device import DeviceScene, cuda_available, models_surfaces, resolve_device, warp, warp_version
from simulator.engine.fanout import fan_out
from simulator.engine.methods import (
    COMPONENTS, GUIDED_METHODS, HYBRID_METHODS, LIGHT_PICK_MODES, METHOD_FLAGS, light_pick_rule, rr_pilot_choice,
    rr_threshold_rule,
)
from simulator.engine.stats import GroupBatchStats, GroupStats, RunningStats, lit_variance, z_for_confidence
from simulator.engine.scenario_split import (
    MAX_PILOT_GROUPS, neyman_split, pass_split, pilot_groups, scenario_relative_variances,
)
from simulator.errors import UserError
from simulator.interrupts import StopFlag
from simulator.scene import emitters
from simulator.scene.model import MAX_PROBE_PIXELS, Scene, Sensor, SensorKind

__all__ = [
    "COMPONENTS", "METHOD_FLAGS", "cuda_available", "warp_version", "Engine", "EngineResult", "LightGroups", "Progress",
    "resolve_device", "load_kernels",
]  # fmt: skip

#: samples one kernel thread draws for one sensor (a block)
BLOCK = 32
#: batches a fixed budget of fewer than 2·BLOCK samples per sensor is cut into, for the light groups'
#: batch-means covariance (GroupBatchStats): smaller blocks, the same samples. B − 1 = 7 degrees of
#: freedom put the error's own relative error near 1/sqrt(2(B − 1)) = 27% (stats.GroupBatchStats, Notes)
MIN_GROUP_BATCHES = 8
#: samples per launch in a batch: big enough to amortise the launch, small
#: enough that the progress bar and time limit are checked often
SAMPLES_PER_LAUNCH = 1 << 18
#: passes one kernel thread draws for one probe pixel
PASS_BLOCK = 16
#: probe kernel threads per launch: bounds the float64 sums held at once (~900 B each)
THREADS_PER_LAUNCH = 1 << 16
#: most bytes of light-group state (16·G·(G + 3) per kernel thread) one launch holds; a batch
#: that needs more is drawn in several launches (only with many groups: G = 20 fits 36,000 threads)
GROUP_STATE_BYTES = 1 << 28
#: samples per sensor of the light pick's pilot (all lights sampled, tallied, then discarded)
PICK_PILOT_SAMPLES = 16
#: a sensor's own first-vertex pick factor is shrunk toward all sensors'
#: by this many pseudo-samples (a sensor's 16 pilot samples are few)
PICK_PRIOR_SAMPLES = 4
#: the per-patch pick pilot's samples per sensor ...
PATCH_PICK_SAMPLES = 32
#: ... over at most this many samples in all (the sensors evenly thinned): it runs on one worker
PATCH_PICK_TOTAL = 1 << 16
#: a patch's factors are shrunk toward row 0's by this many visits' worth of estimate
PATCH_PICK_PRIOR_VISITS = 8
#: the sensors the hybrid's pilot draws (Engine._hybrid_choice), at most
HYBRID_PILOT_SENSORS = 256
#: the split pilot's direct and indirect samples per irradiance sensor (Engine._split_rule) ...
SPLIT_PILOT_SAMPLES = 16
#: ... the most indirect paths a sample may read ...
SPLIT_MAX = 8
#: ... and the least gain predicted, variance × rays, for which a sample is split
SPLIT_MIN_GAIN = 1.2
#: the roulette threshold's pilot (methods.rr_pilot_choice): samples per sensor, at least this many in all,
#: over at most this many sensors (evenly spread over the run's)
RR_PILOT_SAMPLES = 8
RR_PILOT_TOTAL = 256
RR_PILOT_SENSORS = 32


@dataclass
class Progress:
    """What a progress display is told after each batch."""

    sensors_done: int
    sensors_total: int
    samples: int
    elapsed_s: float
    eta_s: float | None


def load_kernels(device: str = "cpu", scene: Scene | None = None) -> None:
    """Compile (or load from the kernel cache) the modules a trace may launch on ``device`` now
    (:mod:`.kernel_modules`): the trace variant of ``scene``'s stage, or both without one, and the
    closed forms. A one-time cost of the process that timings of a trace can then leave out."""
    variants = [False, True] if scene is None else [models_surfaces(scene.geometry)]
    KM.load([KM.trace_module(v) for v in variants] + [KM.analytic_module()], device)


@dataclass
class LightGroups:
    """Which light group each of the scene's lights belongs to, for one-pass group tallies.

    Attributes
    ----------
    light_group : ndarray of int, shape (L,)
        Per light of ``Engine.scene.lights``: its group in ``[0, n_groups)``,
        −1 for none (its light counts in the total only).
    n_groups : int
        G.
    levels : ndarray, shape (J, G), optional
        Dimming vectors the group readings will be recombined into. An
        adaptive run then stops each sensor when every recombined reading
        ``d_jᵀ Ê`` meets the target (with its standard error
        ``sqrt(d_jᵀ C d_j)``); without, when the total does.
    emissive_group : int
        Group of the emissive surfaces (−1: none).
    patch_base : ndarray of int, shape (L,), optional
        Per light: −1, or (a dome split into sky patches) the first of its
        146 groups, ``patch_base + p`` for Tregenza patch p and
        ``patch_base + 145`` below the horizon
        (:mod:`simulator.study.inputs.sky_patches`).
    batch : bool
        Covariance from batch means (each kernel thread's block of samples a
        batch; :class:`~simulator.engine.stats.GroupBatchStats`) in place of
        per-sample cross products: a thread holds 2G slots, not G(G + 3).
        Needed for many groups; ``None`` chooses it when a dome is split.
    """

    light_group: np.ndarray
    n_groups: int
    levels: np.ndarray | None = None
    emissive_group: int = -1
    patch_base: np.ndarray | None = None
    batch: bool | None = None
    #: (J, G) the dimming vectors the light pick serves (simulator.engine.scenario_pick); None: the authored levels
    pick_levels: np.ndarray | None = None

    @property
    def uses_batches(self) -> bool:
        if self.batch is not None:
            return bool(self.batch)
        return self.patch_base is not None and bool(np.any(np.asarray(self.patch_base) >= 0))

    def state_width(self) -> int:
        """Slots of a kernel thread's group state (``group_width`` in the kernels)."""
        return self.width_of(self.n_groups, self.uses_batches)

    @staticmethod
    def width_of(n_groups: int, batch: bool) -> int:
        from simulator.kernels.group_tally import GROUP_TOUCHED

        return 2 * n_groups + 1 + int(GROUP_TOUCHED) if batch else n_groups * (n_groups + 3)


@dataclass
class EngineResult:
    """Per-sensor readings from one run.

    Attributes
    ----------
    mean, stderr : ndarray, shape (S, 2)
        Mean sample value and its standard error; channel 0 radiometric
        (W/m² for irradiance and patch, W m⁻² sr⁻¹ for radiance), channel 1
        its photometric twin (lx, cd/m²).
    samples : ndarray, shape (S,)
    seconds : ndarray, shape (S,)
        Wall time attributed to each sensor in proportion to its samples.
    target_met : ndarray of bool, shape (S,), or None
        Adaptive runs only: whether the error target was reached.
    non_finite : ndarray, shape (S,)
        Samples that came out NaN or Inf (counted, left out of the mean).
    methods : list of str or None
        The method that read each sensor, when they differ (a planned run);
        ``method`` then names them all, joined by "+".
    unfinished : ndarray of bool, shape (S,), or None
        Sensors a stop request (Ctrl-C) left short of their samples or error
        target (None for a closed-form run, which cannot be stopped part way).
    interrupted : bool
        Whether a stop was requested during the run.
    responses, response_mean, response_stderr
        Spectral transport (:meth:`Engine.set_hero_tables`) only: response
        names and their per-sample estimates' means and standard errors,
        shape (S, R); ``mean``/``stderr`` are then the radiometric and
        photopic responses of the same samples.
    """

    method: str
    device: str
    mean: np.ndarray
    stderr: np.ndarray
    samples: np.ndarray
    seconds: np.ndarray
    target_met: np.ndarray | None
    non_finite: np.ndarray
    wall_s: float
    warnings: list[str] = field(default_factory=list)
    methods: list[str] | None = None  #: per sensor, when a plan mixed methods (see run.run_plan)
    unfinished: np.ndarray | None = None
    interrupted: bool = False
    #: spectral transport: the responses estimated per sample (names; radiometric and photopic first),
    #: their means and stderrs, shape (S, R); None for grey transport
    responses: list[str] | None = None
    response_mean: np.ndarray | None = None
    response_stderr: np.ndarray | None = None
    #: with light groups: each group's reading (G, S, 2) and the covariance of those estimates (S, 2, G, G)
    group_mean: np.ndarray | None = None
    group_cov: np.ndarray | None = None


class Engine:
    """A scene and its sensors, resident on one Warp device.

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
        Sensors :meth:`run` reads (not probes: :meth:`run_probes` takes those).
    device : str
        ``cpu``, ``cuda`` or ``auto``.
    threads : int
        CPU worker threads; 0 = all cores.
    """

    def __init__(self, scene: Scene, sensors: list[Sensor], device: str = "cpu", threads: int = 0):
        self.device = resolve_device(device)
        self.scene = scene
        self.sensors = sensors
        self.threads = threads if threads > 0 else (os.cpu_count() or 1)
        if self.device != "cpu":
            self.threads = 1
        self.warnings: list[str] = []
        self.rays_traced = 0
        self.shadow_rays_traced = 0  #: the shadow rays among rays_traced (next-event tests, image connections)
        self._light_mask: np.ndarray | None = None
        self._device_scene: DeviceScene | None = None
        self._hero = None  # simulator.spectra.hero.HeroTables when tracing spectrally
        self.guide = None  #: GuideInfo once a guided run has built the guide (once per engine)
        #: why the latest guided run read its sensors without a guide (None: it had one, or was not guided)
        self.guide_skipped: str | None = None
        #: next-event estimation by one picked light: "auto" (methods.light_pick_rule) or a methods.LIGHT_PICK_MODES key
        self.light_pick = "auto"
        #: Russian roulette threshold of path throughput; None: methods.rr_threshold_rule
        self.rr_threshold: float | None = None
        self._rr_rule_t: float | None = None  # methods.rr_threshold_rule's, once asked (_rr_rule)
        self._pick_key: tuple | None = None
        #: the roulette pilot's findings per (method, depth, component, sensors, target):
        #: {"threshold", "rule", "tried": [(t, relvar_mean, relvar_max, rays)], "seconds"}
        self._rr_found: dict[tuple, dict] = {}
        self.rr_pilot: dict | None = None  #: the roulette pilot's finding for the latest path run (None: none ran)
        #: per method, how the latest adaptive run sized its batches (see :meth:`run`, ``choose_first_batch``)
        self.batch_plans: dict[str, dict] = {}
        self.piece_factors: np.ndarray | None = None  #: the emitter pieces' learned factors (None: not learnt)
        self.pick_spread: float | None = None  #: a group pass's pick spread (scenario_pick), None before one
        #: emitter pieces: "auto" (kept where the pick pilot predicts they pay, :meth:`_choose_pieces`),
        #: True (always, as a stage has them) or False (the scene's triangles, one piece)
        self.emitter_pieces: str | bool = "auto"
        self._pieces_on = True  # the device scene's emitters are in pieces
        #: the emitter pieces' table per cell (engine.piece_table.PieceTable) once the device scene has
        #: pieces; None: none (one piece, or not yet uploaded); False: never built (each receiver weighs
        #: the pieces one by one, as before the table)
        self.piece_table = None
        #: what the pieces' choice measured (None: no choice made yet, or nothing to choose)
        self.pieces_pilot: dict | None = None
        self._piece_tally: np.ndarray | None = None  # the latest pick pilot's per-piece sums, (K, 4) (tally_pick)
        self._piece_pilot: tuple | None = None  # the latest pick pilot's readings and per-sensor moments
        self._pick_learnt: tuple | None = None  # (factors, per-row gains) of the latest pick pilot
        self._pick_scaled = False  # the device's pick factors are steered by a group pass's scenarios
        self._mask_version = b""  # which light mask the device holds: a digest of which lights are culled ...
        self._mask_full = b""  # ... and of all of it
        #: per sensor (S, 2): the direct light computed on the host that a hybrid run adds to its samples
        #: (``exact+path``, ``exact+guided``); the pilots' relative variances and the stopping rule read
        #: the whole reading, samples plus this. None outside such a run.
        self._offset: np.ndarray | None = None
        self.exact_seconds = 0.0  #: the host's time on the latest hybrid run's computed direct light
        self.hybrid_pilot: dict | None = None  #: what the latest hybrid run's pilot measured and chose (_hybrid_choice)
        #: hybrid runs: "auto" (the pilot decides whether computing the direct light pays), True (always
        #: computed) or False (always sampled)
        self.hybrid: str | bool = "auto"
        self._computed: np.ndarray | None = None  # the plan's computed direct light (set_computed)
        #: paths: learn the light pick's factors per surface patch too, for the vertices past the first
        #: (kernels.light_pick; docs/DESIGN.md §Next-event estimation); False: one row serves them all
        self.patch_pick = True
        #: paths: each irradiance sample reads its direct light once and the mean of K indirect paths;
        #: "auto": K by a pilot (:meth:`_split_rule`), an int: that K (1: no split)
        self.split_indirect: int | str = "auto"
        self._split_found: dict[tuple, dict] = {}
        self.split_pilot: dict | None = None  #: what the split pilot measured for the latest path run

    def _upload(self) -> DeviceScene:
        """Import Warp, load the kernels and upload the scene, on first need: a
        run read wholly on the host (``exact``) never pays for it."""
        if self._device_scene is None:
            wp = warp()
            from simulator.kernels import estimators as K

            self._kernels = K
            on = self._pieces_on and self.emitter_pieces is not False
            self._device_scene = DeviceScene(self.scene, self.sensors, self.device, pieces=on)
            # compile (or load from the kernel cache) the stage's trace variant before worker threads launch
            KM.load([KM.trace_module(K.trace_for(self._device_scene.rec.surfaces).surfaces)], self.device)
            with wp.ScopedDevice(self.device):  # placeholder for TraceParams.group_state while tallies are off
                self._no_groups = wp.zeros(1, dtype=wp.vec2d)
            if self._light_mask is not None:
                self._device_scene.set_light_mask(self._light_mask)
            if self._hero is not None:
                self._device_scene.set_hero_tables(self._hero)
            if self.piece_table is not False:  # emitter pieces: each cell's own pick (engine.piece_table)
                from simulator.engine.piece_table import piece_table

                self.piece_table = piece_table(self) or None
        return self._device_scene

    @property
    def _dev(self) -> DeviceScene:
        return self._upload()

    @property
    def _K(self):
        self._upload()
        return self._kernels

    @property
    def _KP(self):
        """The probe kernels (imported with the trace modules, whose probe kernel each holds: :mod:`.kernel_modules`)."""
        self._upload()
        from simulator.kernels import probe as KP

        return KP

    @property
    def scene_rec(self):
        """The scene's device record (``kernels.lights.SceneRec``), for kernels."""
        return self._dev.rec

    @property
    def trace_variant(self):
        """The kernels this stage is traced with (``kernels.estimators.Trace``): those compiled without
        the surface model where ``SceneRec.surfaces`` is 0 (no pane, cut-out or glossy face), else those
        with it (``kernels.estimators.trace_for``; docs/DESIGN.md §Trace variants)."""
        return self._K.trace_for(self._dev.rec.surfaces)

    @property
    def emissive_light(self) -> int:
        """Index of the light record standing for all emissive triangles, −1 if none."""
        return self._dev.emissive_light

    def set_hero_tables(self, tables) -> None:
        """Trace spectrally with these tables (:func:`simulator.spectra.hero.hero_tables`): Monte Carlo
        runs then estimate every response per sample (``EngineResult.responses``); None: grey transport."""
        self._hero = tables
        if self._device_scene is not None:
            self._device_scene.set_hero_tables(tables)

    @property
    def hero_tables(self):
        """The tables of spectral transport, None for grey transport (see :meth:`set_hero_tables`)."""
        return self._hero

    @property
    def spectral(self) -> bool:
        """Whether Monte Carlo runs trace hero wavelengths."""
        return self._hero is not None

    def set_light_mask(self, mask: np.ndarray) -> None:
        """Lights to skip per sensor at its first vertex: ``mask`` (S, L) over
        the scene's lights, 0 = wholly behind the sensor (see plan.lights_behind)."""
        mask = np.asarray(mask)
        if self._light_mask is None or not np.array_equal(self._light_mask, mask):
            import hashlib

            def digest(m):
                return hashlib.blake2b(repr(m.shape).encode() + np.ascontiguousarray(m, np.int32).tobytes(),
                                       digest_size=16).digest()  # fmt: skip

            # the light pick learns again for other culled lights (a plan run again keeps what it learnt; a
            # hybrid's computed lights, mask 2, change only the first vertex, where paths do not pick);
            # the split and roulette pilots, which measure the samples themselves, for any change
            self._mask_version = digest(mask != 0)
            self._mask_full = digest(mask)
        self._light_mask = mask
        if self._device_scene is not None:
            self._device_scene.set_light_mask(mask)

    def set_computed(self, computed: np.ndarray | None) -> None:
        """The plan's choice for hybrid runs: (S, R) bool, per sensor and light record (the scene's
        lights, then the emissive triangles), the direct light to compute on the host
        (:meth:`_run_hybrid`); None: every light that can be."""
        self._computed = None if computed is None else np.asarray(computed, bool)

    def trace_params(self, method: str, seed: int, max_depth: int = -1, component: str = "total"):
        """The kernels' ``TraceParams`` for ``method`` (light, bsdf, mis, path or guided)."""
        from simulator.engine import guide as G

        nee, bsdf, mis, bounces = METHOD_FLAGS[method]
        p = self._K.TraceParams()
        p.nee, p.bsdf, p.mis = nee, bsdf, mis
        p.bounces = max_depth if bounces and component != "direct" else 0
        p.skip_direct = 1 if component == "indirect" else 0
        p.emissive_light = self.emissive_light
        p.seed = int(seed) & 0x7FFFFFFF
        p.count_rays = 0
        p.thread = 0
        p.mask_row = -1
        p.spectral = 1 if self._hero is not None else 0
        p.hero = warp().vec4i(0, 0, 0, 0)
        p.tint = warp().vec4(1.0, 1.0, 1.0, 1.0)
        p.group_tally = 0
        p.n_groups = 0
        p.group_batch = 0
        p.group_state = self._no_groups
        # panes and cut-outs on a guided segment pass light at their transmittance, glossy vertices mix the
        # guide with their lobes, and mirror vertices never use it (docs/DESIGN.md §Surface guide)
        guided = method in GUIDED_METHODS
        p.guide_c = G.GUIDE_C if guided else 0.0
        p.guide_first = G.GUIDE_FIRST
        p.guide_depth = G.GUIDE_DEPTH
        p.tally = 0
        p.tally_chunk = 1
        p.pick_light = 0
        p.tally_pick = 0
        p.split_indirect = 0
        p.optics = 0  # set per sensor by the estimator kernel (a probe's: 0, the cosine at every vertex)
        p.optics_x = warp().vec3(1.0, 0.0, 0.0)
        p.rr_threshold = float(self.rr_threshold if self.rr_threshold is not None else self._rr_rule())
        return p

    def _rr_rule(self) -> float:
        """The rule's roulette threshold (``methods.rr_threshold_rule``), found once per engine: it sums
        every triangle's area, and each run asks for it twice."""
        if self._rr_rule_t is None:
            self._rr_rule_t = rr_threshold_rule(self.scene)[0]
        return self._rr_rule_t

    def ensure_guide(self, seed: int, sensor_ids: np.ndarray | None = None, max_depth: int = -1,
                     groups: LightGroups | None = None):  # fmt: skip
        """Build the surface guide from a pilot over ``sensor_ids`` (default
        all), once: later guided runs reuse it. Returns its GuideInfo. A light-group pass with
        scenarios (``groups.pick_levels``) learns it per pilot group and serves every scenario
        (:func:`simulator.engine.guide.scenario_tally`)."""
        if self.guide is None:
            from simulator.engine.guide import build_guide

            ids = np.arange(len(self.sensors)) if sensor_ids is None else np.asarray(sensor_ids, np.int64)
            lit = levels = None
            pilot = self._split_pilot_groups(groups)
            if pilot is not None and pilot[1].shape[1] > 1 and self._hero is None:  # spectral: rows not scaled
                g_of, lv = pilot
                keep = np.flatnonzero(lv.max(axis=0) > 0)  # groups some scenario lights
                lit = (g_of[None, :] == keep[:, None]).astype(np.float64)
                levels = lv[:, keep]
            self.guide = build_guide(self, seed, ids, max_depth, lit, levels)
        return self.guide

    def _guide_pays(self, samples: int, rel_error: float | None, groups) -> bool:
        """Whether a guided run of ``samples`` per sensor builds the guide. Not where the engine's sensors
        (all of them, whichever group runs first) draw a fixed budget of fewer samples in all than the
        guide's pilot alone would (``guide.PILOT_MIN_TOTAL``, however few the sensors): a lone sensor's 256
        samples paid 16,384 pilot samples, 64 times their own cost, which no gain of the guide's can
        return. The run is then read by plain paths (a guided trace with no guide is one, draw for draw);
        ``guide_skipped`` says so, and a later run that can pay builds it."""
        from simulator.engine import guide as G

        total = len(self.sensors) * samples
        if self.guide is not None or rel_error is not None or groups is not None or total >= G.PILOT_MIN_TOTAL:
            self.guide_skipped = None
            return True
        self.guide_skipped = (f"guide not built: the run draws {total:,} samples, fewer than its pilot would "
                              f"({G.PILOT_MIN_TOTAL:,}); read by plain paths")
        return False

    def light_pick_mode(self, method: str) -> str:
        """How :meth:`run` samples lights for ``method``: a key of
        ``methods.LIGHT_PICK_MODES`` (``light_pick`` "auto": the rule)."""
        if self.light_pick == "auto":
            return light_pick_rule(method, self.scene)[0]
        if self.light_pick not in LIGHT_PICK_MODES:
            raise ValueError(f"light_pick: {self.light_pick!r} is not auto or one of {sorted(LIGHT_PICK_MODES)}")
        return self.light_pick if METHOD_FLAGS[method][0] else "off"

    def fix_pick_factors(self, factors: np.ndarray) -> None:
        """Use these light-pick factors, (1 + S, L) over the light records
        (see :meth:`_prepare_pick`), instead of learning them by a pilot."""
        self._dev.set_pick_factors(np.asarray(factors, np.float64))
        self._dev.use_patch_pick(False)
        self._pick_key = "fixed"

    def _prepare_pick(self, method: str, seed: int, max_depth: int, component: str, ids: np.ndarray) -> None:
        """Learn the light pick's factors (kernels.light_pick) for these
        sensors from a pilot that samples every light: per light, Σ weight ×
        shadowed value / Σ weight × estimate ê, over path vertices past the
        first (row 0) and over each sensor's first vertex (row 1 + s, shrunk
        toward all sensors' by PICK_PRIOR_SAMPLES). A light never estimated
        keeps 1. The pilot's samples are discarded, drawn from other random
        streams than the run's, so the readings stay unbiased whatever it
        learns. Done once per (method, depth, component, sensors, mask)."""
        key = (method, max_depth, component, ids.tobytes(), self._mask_version)
        if self._pick_key in (key, "fixed"):
            return
        dev = self._dev
        n_l = int(dev.rec.n_lights)
        params = self.trace_params(method, (seed + 0x3C6EF372) & 0x7FFFFFFF, max_depth, component)
        params.tally_pick = 1
        per_patch = bool(self.patch_pick and dev.layout.usable and METHOD_FLAGS[method][3] and params.bounces != 0
                         and self.light_pick_mode(method) != "off")
        if per_patch:  # first: its launch resets the per-thread tallies the rows are learnt from below
            self._patch_pick_pilot(method, seed, max_depth, component, ids)
        count = np.full(len(ids), PICK_PILOT_SAMPLES, np.int64)
        t_sensor, tally = self._launch(params, ids, np.zeros(len(ids), np.int64), count, tally=True)
        tally = tally.reshape(len(t_sensor), 2, n_l, 2).astype(np.float64)
        factors = np.ones((1 + len(self.sensors), n_l))

        def ratio(sums, fallback):
            est, got = sums[..., 0], sums[..., 1]
            return np.where(est > 0, got / np.where(est > 0, est, 1.0), fallback)

        factors[0] = ratio(tally[:, 1].sum(0), 1.0)
        first = np.zeros((len(self.sensors), n_l, 2))
        np.add.at(first, t_sensor, tally[:, 0])
        overall = ratio(first.sum(0), factors[0])
        mean_est = first[..., 0] / PICK_PILOT_SAMPLES
        prior = PICK_PRIOR_SAMPLES * mean_est
        est = first[..., 0] + prior
        got = first[..., 1] + prior * overall
        factors[1:] = np.where(est > 0, got / np.where(est > 0, est, 1.0), overall)
        pieces = self._piece_tally
        if pieces is not None:
            # emitter pieces learn their own factors (one row: the piece's pdf is read at any vertex
            # without its depth); the emissive record's estimate is their sum, so its own factor stays 1
            pf = ratio(pieces[:, :2], 1.0)
            dev.set_piece_factors(pf)
            self.piece_factors = pf
            factors[:, self.emissive_light] = 1.0
        dev.set_pick_factors(factors)
        if per_patch:
            dev.set_patch_pick_factors(patch_pick_factors(dev.read_patch_pick_tally(), factors[0]))
        else:
            dev.use_patch_pick(False)
        self._pick_key = key
        # what each light gave per row, for a pass serving several scenarios (scenario_pick)
        self._pick_learnt = (factors, np.concatenate([tally[:, 1].sum(0)[None, :, 1], got], axis=0))
        self._pick_scaled = False

    def _choose_pieces(self, method: str, seed: int, max_depth: int, component: str, ids: np.ndarray) -> None:
        """Keep the emitter pieces or go back to one piece and the scene's own triangles, once per
        engine, from the pick pilot (:meth:`_prepare_pick`, which learns the pieces' factors; a guided
        method's pilot is the path's, the guide not yet built). Over its light samples of the pieces,
        kernels.light_pick.piece_moments sums the second moments of each vertex's MIS estimate with the
        pieces' pick and with a pick ∝ power (importance reweighting of the same samples); their
        difference per sample, Δ_s, is what one piece would add to sensor s's variance per sample V_s
        (the paths unchanged), so the pieces cut the mean relative variance by

            G = Σ_s (V_s + Δ_s)/m_s² / Σ_s V_s/m_s²,

        V_s and the mean m_s the pilot's own (as W + lm/683, the pick's importance). They stay where
        G ≥ emitters.PIECES_MIN_GAIN: where the receivers see the emitters unevenly, as through a window, not
        in an enclosure seen whole from everywhere, where they cost more CPU than they give back.
        Unbiased either way: the choice changes only the pdf."""
        dev = self._dev
        if dev.pieces is None or dev.pieces.n <= 1 or self._pick_key == "fixed":
            return
        tb = time.perf_counter()
        self._prepare_pick("path" if method in GUIDED_METHODS else method, seed, max_depth, component, ids)
        if self._piece_pilot is None:
            return
        sensors, cnt, mean, m2, moments = self._piece_pilot
        n = np.maximum(cnt, 1).astype(np.float64)
        delta = (moments[..., 1].sum(axis=1) - moments[..., 0].sum(axis=1)) / n  # < 0: one piece would do better
        var = m2 / np.maximum(n - 1, 1)[:, None]
        m = mean[:, 0] + mean[:, 1] / emitters.PICK_LM_PER_W
        v = (np.sqrt(var[:, 0]) + np.sqrt(var[:, 1]) / emitters.PICK_LM_PER_W) ** 2  # the channels' errors move together
        ok = m > 0
        base = float(np.sum(v[ok] / m[ok] ** 2))
        with_one = float(np.sum((v[ok] + delta[ok]) / m[ok] ** 2))
        gain = with_one / base if base > 0 else (np.inf if with_one > 0 else 1.0)  # inf: no noise with pieces
        keep = gain >= emitters.PIECES_MIN_GAIN
        self.pieces_pilot = {
            "pieces": int(dev.pieces.n), "triangles": int(dev.rec.tris.shape[0] // 3), "elements": int(dev.n_elements),
            "predicted_gain": gain if np.isfinite(gain) else None,
            "min_gain": emitters.PIECES_MIN_GAIN, "kept": bool(keep), "pilot_s": time.perf_counter() - tb,
            "why": (f"one piece would have {gain:.2f}× the pieces' relative variance (pilot)"
                    + (f", ≥ {emitters.PIECES_MIN_GAIN:g}: pieces kept" if keep else
                       f", < {emitters.PIECES_MIN_GAIN:g}: one piece over the scene's own triangles")),
        }  # fmt: skip
        if keep and self.piece_table:
            self.pieces_pilot["table"] = self.piece_table.summary()
        if not keep:
            tr = time.perf_counter()
            self._pieces_on = False
            self._device_scene = None
            self._pick_key, self._pick_learnt, self._piece_tally, self.piece_factors = None, None, None, None
            self._piece_pilot = None
            self._upload()
            self.pieces_pilot["rebuild_s"] = time.perf_counter() - tr

    def _patch_pick_pilot(self, method: str, seed: int, max_depth: int, component: str, ids: np.ndarray) -> None:
        """The per-patch sums of the light pick (kernels.light_pick.tally_patch_pick), on the device:
        PATCH_PICK_SAMPLES samples of every light at every vertex for up to PATCH_PICK_TOTAL /
        PATCH_PICK_SAMPLES of these sensors (evenly spread over them), on one CPU worker (the sums
        are then the same bytes whatever the thread count), from a seed stream of their own."""
        params = self.trace_params(method, (seed + 0x78DDE6E6) & 0x7FFFFFFF, max_depth, component)
        params.tally_pick = 2
        k = max(1, PATCH_PICK_TOTAL // PATCH_PICK_SAMPLES)
        sub = ids if len(ids) <= k else np.unique(ids[np.linspace(0, len(ids) - 1, k).round().astype(np.int64)])
        self._dev.start_patch_pick_tally()
        with _fields_set(self, threads=1):
            self._launch(params, sub, np.zeros(len(sub), np.int64), np.full(len(sub), PATCH_PICK_SAMPLES, np.int64),
                         tally=True)  # fmt: skip

    def _split_rule(self, params, ids: np.ndarray, groups: LightGroups | None = None) -> int:
        """K, the indirect paths per irradiance sample (kernels.estimators.split_irradiance), from a
        pilot of SPLIT_PILOT_SAMPLES direct and as many indirect samples of each irradiance sensor in
        ``ids`` (their own seed stream): with V_d, V_i the relative variances per sample summed over
        the sensors (over the square of the total reading) and c_d, c_i the rays per sample,
        K = √(V_i·c_d / (V_d·c_i)) (the Neyman allocation: the cost c_d + K·c_i times the variance
        V_d + V_i/K is least there), rounded, within [1, SPLIT_MAX]; 1 where the predicted gain
        (V_d + V_i)(c_d + c_i) / ((V_d + V_i/K)(c_d + K·c_i)) is under SPLIT_MIN_GAIN. Once per (run's
        strategies, sensors, scenarios). A light-group pass with scenarios (``groups.pick_levels``) takes
        the largest of the scenarios' own K (:mod:`simulator.engine.scenario_split`), so a lamp-only
        scenario is split as its plain run would be."""
        ids = np.asarray([i for i in ids if self.sensors[i].kind == SensorKind.IRRADIANCE], np.int64)
        if not len(ids) or params.spectral:
            return 1  # spectral transport: the pilot reads the grey channels only, not the responses
        key = (params.nee, params.bsdf, params.bounces, params.guide_c, params.pick_light, params.rr_threshold,
               params.seed, ids.tobytes(), self._mask_full)  # fmt: skip
        pilot = self._split_pilot_groups(groups)
        if pilot is not None:
            key += (pilot[0].tobytes(), pilot[1].tobytes())
        if key in self._split_found:
            self.split_pilot = self._split_found[key]
            return self.split_pilot["k"]
        tb = time.perf_counter()
        parts = []
        depth, rays_kept, shadow_kept = params.bounces, self.rays_traced, self.shadow_rays_traced
        shadow = []  # each part's shadow rays per sample
        tally = {} if pilot is None else {"group_tally": 1, "n_groups": int(pilot[1].shape[1]), "group_batch": 0}
        try:
            with _fields_set(params, seed=(int(params.seed) + 0x1B873593) & 0x7FFFFFFF, count_rays=1,
                             split_indirect=0, bounces=depth, skip_direct=params.skip_direct, **tally):
                if pilot is not None:
                    self._upload_light_groups(pilot[0], None)  # the pass's own groups are set after the pilot
                for bounces, skip in ((0, 0), (depth, 1)):
                    params.bounces, params.skip_direct = bounces, skip
                    self.rays_traced = self.shadow_rays_traced = 0
                    _, cnt, mean, m2, _, _, _, g_mean, g_m2 = self._launch(
                        params, ids, np.zeros(len(ids), np.int64), np.full(len(ids), SPLIT_PILOT_SAMPLES, np.int64))
                    rays = self.rays_traced / max(1, int(cnt.sum()))
                    shadow.append(self.shadow_rays_traced / max(1, int(cnt.sum())))
                    parts.append((mean[:, 1], m2[:, 1] / np.maximum(cnt - 1, 1), max(rays, 1.0), cnt,
                                  None if g_mean is None else g_mean[:, 1], None if g_m2 is None else g_m2[:, 1]))
        finally:
            self.rays_traced, self.shadow_rays_traced = rays_kept, shadow_kept
        (m_d, v_d, c_d, *g_d), (m_i, v_i, c_i, *g_i) = parts
        m = m_d + m_i
        if self._offset is not None:  # a hybrid run: relative to the whole reading
            m = m + self._offset[ids, 1]
        ok = m > 0
        rv_d = float((v_d[ok] / m[ok] ** 2).sum())
        rv_i = float((v_i[ok] / m[ok] ** 2).sum())
        k, gain = neyman_split(rv_d, rv_i, c_d, c_i, SPLIT_MAX, SPLIT_MIN_GAIN)
        self.split_pilot = {"k": k, "relvar_direct": rv_d / max(1, int(ok.sum())),
                            "relvar_indirect": rv_i / max(1, int(ok.sum())), "rays_direct": c_d, "rays_indirect": c_i,
                            "shadow_rays_direct": shadow[0], "shadow_rays_indirect": shadow[1],
                            "predicted_gain": gain, "seconds": time.perf_counter() - tb}  # fmt: skip
        if pilot is not None:
            # each scenario's own K from its recombined pilot; the pass draws the largest (scenario_split)
            (cnt_d, gm_d, g2_d), (cnt_i, gm_i, g2_i) = g_d, g_i
            both = gm_d + gm_i
            rvd = scenario_relative_variances(gm_d, g2_d, cnt_d, pilot[1], both)
            rvi = scenario_relative_variances(gm_i, g2_i, cnt_i, pilot[1], both)
            # no gain threshold: at the pass's dearer rays a scenario's own run would gain more (scenario_split)
            per = [neyman_split(float(a), float(b), c_d, c_i, SPLIT_MAX, 1.0) for a, b in zip(rvd, rvi)]
            k = pass_split(per, SPLIT_MAX)
            self.split_pilot.update(k=k, k_of_scenarios=[kj for kj, _ in per],
                                    predicted_gain_of_scenarios=[float(gj) for _, gj in per])  # fmt: skip
        self._split_found[key] = self.split_pilot
        return k

    def _levels_of_lights(self, groups: LightGroups) -> np.ndarray:
        """(J, L) each scenario's level of each light record of the device scene (``groups.pick_levels``)."""
        from simulator.engine.scenario_pick import light_levels

        n_l = int(self._dev.rec.n_lights)
        lg = np.full(n_l, -1, np.int64)
        lg[: len(groups.light_group)] = groups.light_group
        if self.emissive_light >= 0:
            lg[self.emissive_light] = groups.emissive_group
        pb = None
        if groups.patch_base is not None:
            pb = np.full(n_l, -1, np.int64)
            pb[: len(groups.patch_base)] = groups.patch_base
        return light_levels(groups.pick_levels, lg, pb)

    def _split_pilot_groups(self, groups: LightGroups | None):
        """The split pilot's groups for a pass with scenarios: (group of each light record, levels (J, G')),
        or None (no scenarios, or more than ``MAX_PILOT_GROUPS``: the total decides)."""
        if groups is None or groups.pick_levels is None:
            return None
        g, lv = pilot_groups(self._levels_of_lights(groups))
        return None if lv.shape[1] > MAX_PILOT_GROUPS else (g, lv)

    def _upload_light_groups(self, light_group: np.ndarray, patch_base: np.ndarray | None) -> None:
        """Each light record's tally slot (and a split dome's first slot, −1 for none) on the device."""
        wp = warp()
        n_l = int(self._dev.rec.n_lights)
        lg = np.full(max(n_l, 1), -1, np.int32)
        lg[: len(light_group)] = light_group
        pb = np.full(max(n_l, 1), -1, np.int32)
        if patch_base is not None:
            pb[: len(patch_base)] = patch_base
        with wp.ScopedDevice(self.device):
            self._dev.rec.light_group = wp.array(lg, dtype=wp.int32)
            self._dev.rec.patch_base = wp.array(pb, dtype=wp.int32)

    def _scenario_pick(self, groups: LightGroups | None, mode: int) -> int:
        """Steer the learnt pick toward the scenarios a group pass serves (``groups.pick_levels``,
        :mod:`simulator.engine.scenario_pick`), or back to the learnt factors. Returns the pick mode
        to use: ``mode``, or 0 (every light sampled) where no one pick serves all the scenarios."""
        learnt = self._pick_learnt
        if learnt is None or self._pick_key == "fixed":
            return mode
        factors, got = learnt
        if groups is None or groups.pick_levels is None:
            if self._pick_scaled:
                self._dev.set_pick_factors(factors)
                self._dev.use_patch_pick(True)
                self._pick_scaled = False
            return mode
        from simulator.engine.scenario_pick import MAX_SPREAD, pick_spread, scenario_multipliers

        d = self._levels_of_lights(groups)  # factors are (1 + S, L) over the same light records
        self._dev.set_pick_factors(factors * scenario_multipliers(got, d))
        self._dev.use_patch_pick(False)  # the patches' factors are not steered by the scenarios: the rows serve
        self._pick_scaled = True
        rows = got[:1] if mode == LIGHT_PICK_MODES["after_first"] else got  # the rows the mode reads
        self.pick_spread = float(pick_spread(rows, d).max())
        return 0 if self.pick_spread > MAX_SPREAD else mode

    def _prepare_rr(self, params, method: str, max_depth: int, component: str, ids: np.ndarray,
                    first_batch: int, z: float, rel_error: float | None) -> float:
        """The Russian roulette threshold for this run: the rule's, lowered
        where a pilot measures that it pays (``methods.rr_pilot_choice``).

        The pilot draws :data:`RR_PILOT_SAMPLES` samples (at least
        :data:`RR_PILOT_TOTAL` in all) of up to :data:`RR_PILOT_SENSORS` of
        the run's sensors per threshold tried, counting rays, on random
        streams of its own, and is discarded: any threshold leaves the
        readings unbiased, the pilot only picks the cheaper one. Done once
        per (method, depth, component, sensors, target); with
        ``rr_threshold`` set the pilot does not run."""
        t_rule = self._rr_rule()
        key = (method, max_depth, component, ids.tobytes(), first_batch, rel_error, self._mask_full)
        if key not in self._rr_found:
            tb = time.perf_counter()
            pick, count = self._pilot_pick(ids)
            per_sensor = {}  # t -> each pilot sensor's relative variance per sample (NaN: read 0)

            def measure(t: float) -> tuple[float, float, float]:
                params.rr_threshold = float(t)
                self.rays_traced = 0
                rv, n_drawn = self._pilot_relvar(params, pick, count)
                per_sensor[float(t)] = rv
                rv = np.where(np.isnan(rv), 0.0, rv)
                return float(rv.mean()), float(rv.max()), self.rays_traced / max(1, n_drawn)

            with _fields_set(params, seed=(int(params.seed) + 0x5851F42D) & 0x7FFFFFFF, count_rays=1,
                             rr_threshold=params.rr_threshold):
                t, tried = rr_pilot_choice(t_rule, measure, first_batch, z, rel_error)
            self.rays_traced = 0
            self._rr_found[key] = {"threshold": t, "rule": t_rule, "tried": tried, "seconds": time.perf_counter() - tb,
                                   "relvar": per_sensor[float(t)]}
        self.rr_pilot = self._rr_found[key]
        return self.rr_pilot["threshold"]

    def _pilot_relvar(self, params, pick: np.ndarray, count: np.ndarray) -> tuple[np.ndarray, int]:
        """Each of ``pick``'s relative variance per sample (m2/(n − 1)/mean²,
        the largest over the channels that read anything; NaN where none
        did) from ``count`` samples drawn with ``params``; and the samples drawn."""
        sens, cnt, mean, m2 = self._launch(params, pick, np.zeros(len(pick), np.int64), count)[:4]
        if self._offset is not None:  # a hybrid run: relative to the whole reading
            mean = mean + self._offset[sens]
        n = cnt[:, None].astype(np.float64)
        with np.errstate(divide="ignore", invalid="ignore"):
            rv = np.where(np.abs(mean) > 0, m2 / np.maximum(n - 1, 1) / mean**2, np.nan)
        dark = np.isnan(rv).all(axis=1)
        rv = np.nanmax(np.where(dark[:, None], 0.0, rv), axis=1)
        return np.where(dark, np.nan, rv), int(cnt.sum())

    def _pilot_pick(self, ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The pilots' sensors (up to RR_PILOT_SENSORS, evenly spread over
        ``ids``) and their samples each (at least RR_PILOT_TOTAL in all)."""
        spread = np.linspace(0, len(ids) - 1, min(len(ids), RR_PILOT_SENSORS)).round().astype(np.int64)
        pick = ids[np.unique(spread)]
        return pick, np.full(len(pick), max(RR_PILOT_SAMPLES, -(-RR_PILOT_TOTAL // len(pick))), np.int64)

    def _first_batch(self, params, method: str, ids: np.ndarray, upper: int, z: float, rel_error: float,
                     rr_ran: bool) -> dict:
        """An adaptive run's first batch, chosen from a pilot (see
        ``adaptive.first_batch_from_pilot``): the roulette pilot's variances
        at the threshold it chose where it ran, else a pilot of its own (the
        roulette pilot's size, the run's settings, streams of its own,
        discarded). Returns the plan for the run record."""
        tb = time.perf_counter()
        pick, count = self._pilot_pick(ids)  # the roulette pilot's sensors and samples too
        if rr_ran:
            rv = self.rr_pilot["relvar"]
        else:
            with _fields_set(params, seed=(int(params.seed) + 0x1B873593) & 0x7FFFFFFF):
                rv, _ = self._pilot_relvar(params, pick, count)
        first = first_batch_from_pilot(rv, z, rel_error, upper, pilot_samples=int(count.min()))
        finite = rv[np.isfinite(rv)]
        return {"first_batch": first, "chosen_by": "pilot", "upper": int(upper), "pilot_samples": int(count.min()),
                "pilot_relvar_median": float(np.median(finite)) if finite.size else None,
                "pilot_relvar_max": float(finite.max()) if finite.size else None,
                "seconds": time.perf_counter() - tb}

    # ------------------------------------------------------------ sensors

    def _launch(self, params, sensor_ids: np.ndarray, first: np.ndarray, count: np.ndarray, tally: bool = False,
                block: int = BLOCK):  # fmt: skip
        """Draw count[i] samples of sensor_ids[i], starting at sample first[i], ``block`` per kernel thread
        (each sample has its own random stream, so the split changes no sample).

        Returns (sensors, counts, means, m2s, non_finite, response_means,
        response_m2s, group_means, group_m2s) for the batch: the responses are
        None for grey transport; with group tallies on (``params.group_tally``)
        the per-sensor group means (S', C, G) and co-moments (S', C, G, G),
        else None. With ``tally`` (a light-pick pilot, ``params.tally_pick``)
        instead each kernel thread's sensor and its pick tally, (threads × 2 ×
        L) vec2."""
        wp = warp()
        nblk = (count + block - 1) // block
        t_sensor = np.repeat(sensor_ids, nblk).astype(np.int32)
        starts = np.repeat(np.cumsum(nblk) - nblk, nblk)
        within = np.arange(len(t_sensor)) - starts
        t_first = (np.repeat(first, nblk) + within * block).astype(np.int32)
        t_count = np.minimum(block, np.repeat(first + count, nblk) - t_first).astype(np.int32)
        n = len(t_sensor)
        rec = self._dev.rec
        with wp.ScopedDevice(self.device):
            a_sensor = wp.array(t_sensor, dtype=wp.int32)
            a_first = wp.array(t_first, dtype=wp.int32)
            a_count = wp.array(t_count, dtype=wp.int32)
            if params.count_rays:
                rec.ray_counts = wp.zeros(2 * n, dtype=wp.int32)  # per thread: path rays, shadow rays
            n_pc = int(rec.n_pieces)
            if tally:
                rec.pick_tally = wp.zeros(n * 2 * int(rec.n_lights), dtype=wp.vec2)
                if n_pc > 1:
                    rec.piece_tally = wp.zeros(n * n_pc, dtype=wp.vec4)
            shift = wp.empty(n, dtype=wp.vec2d)
            s1 = wp.empty(n, dtype=wp.vec2d)
            s2 = wp.empty(n, dtype=wp.vec2d)
            bad = wp.empty(n, dtype=wp.int32)
            n_resp = self._dev.n_responses if params.spectral else 0
            r_shape = (n, n_resp) if n_resp else (1, 1)
            r_shift, r_s1, r_s2 = (wp.zeros(r_shape, dtype=wp.float64) for _ in range(3))
            if n_resp:
                rec.response_lanes = wp.zeros(n, dtype=wp.vec4)
            n_g = int(params.n_groups)
            width = LightGroups.width_of(n_g, bool(params.group_batch))
            if params.group_tally:
                params.group_state = wp.zeros(n * width, dtype=wp.vec2d)
            kernel = self.trace_variant.estimate_kernel

            def run(offset: int, dim: int):
                wp.launch(
                    kernel,
                    dim=dim,
                    inputs=[rec, self._dev.sensors, params, a_sensor, a_first, a_count, offset],
                    outputs=[shift, s1, s2, bad, r_shift, r_s1, r_s2],
                )

            # a guide pilot tallies per chunk of kernel threads: no chunk is cut between two workers
            fan_out(self.threads, run, n, align=int(params.tally_chunk) if params.tally else 1)
            wp.synchronize_device()
            if tally:
                counts = rec.pick_tally.numpy()
                rec.pick_tally = wp.zeros(1, dtype=wp.vec2)
                self._piece_tally = self._piece_pilot = None
                if n_pc > 1:
                    per_thread = rec.piece_tally.numpy().reshape(n, n_pc, 4).astype(np.float64)
                    self._piece_tally = per_thread.sum(axis=0)
                    rec.piece_tally = wp.zeros(1, dtype=wp.vec4)
                    # per sensor: the moments' sums and the pilot's own readings, for _choose_pieces
                    sensors, cnt, mean, m2 = RunningStats.reduce_blocks(t_sensor, t_count, shift.numpy(), s1.numpy(),
                                                                        s2.numpy())  # fmt: skip
                    moments = np.zeros((len(self.sensors), n_pc, 2))
                    np.add.at(moments, t_sensor, per_thread[:, :, 2:])
                    self._piece_pilot = (sensors, cnt, mean, m2, moments[sensors])
                return t_sensor, counts
            out = RunningStats.reduce_blocks(t_sensor, t_count, shift.numpy(), s1.numpy(), s2.numpy())
            if params.count_rays:
                by_kind = rec.ray_counts.numpy().reshape(n, 2).sum(axis=0)
                self.rays_traced += int(by_kind.sum())
                self.shadow_rays_traced += int(by_kind[1])
            nonfinite = np.add.reduceat(bad.numpy(), np.flatnonzero(np.r_[True, t_sensor[1:] != t_sensor[:-1]]))
            r_mean = r_m2 = None
            if n_resp:
                _, _, r_mean, r_m2 = RunningStats.reduce_blocks(t_sensor, t_count, r_shift.numpy(), r_s1.numpy(),
                                                                r_s2.numpy())
            if not params.group_tally:
                return (*out, nonfinite, r_mean, r_m2, None, None)
            st = params.group_state.numpy().reshape(n, width, 2)
            if params.group_batch:
                return (*out, nonfinite, r_mean, r_m2, (t_sensor, t_count, st[:, n_g : 2 * n_g]), None)
            _, _, g_mean, g_m2 = GroupStats.reduce_blocks(
                t_sensor, t_count, st[:, n_g : 2 * n_g], st[:, 2 * n_g : 3 * n_g], st[:, 3 * n_g :].reshape(n, n_g, n_g, 2),
            )  # fmt: skip
        return (*out, nonfinite, r_mean, r_m2, g_mean, g_m2)

    def _run_analytic(self, sensor_ids: np.ndarray) -> EngineResult:
        """Closed-form readings (the caller has checked they apply): exact up
        to float32 rounding, so the standard error is 0 and no samples are drawn.
        Where every sensor and light has a host closed form (:mod:`.analytic`)
        they are read on the host in float64, and Warp is not imported."""
        from simulator.engine.analytic import host_analytic

        n_s = len(self.sensors)
        t0 = time.perf_counter()
        mean = host_analytic(self.scene, self.sensors, sensor_ids, self._light_mask)
        if mean is None:
            mean = self._kernel_analytic(sensor_ids)
        wall = time.perf_counter() - t0
        return EngineResult(
            method="analytic",
            device=self.device if self._device_scene is not None else "cpu",
            mean=mean,
            stderr=np.zeros((n_s, 2)),
            samples=np.zeros(n_s, np.int64),
            seconds=np.full(n_s, wall / max(n_s, 1)),
            target_met=None,
            non_finite=np.zeros(n_s, np.int64),
            wall_s=wall,
            warnings=list(self.warnings),
        )

    def _kernel_analytic(self, sensor_ids: np.ndarray) -> np.ndarray:
        """The closed forms by the analytic kernel, (S, 2)."""
        wp = warp()
        n_s = len(self.sensors)
        mean = np.zeros((n_s, 2))
        with wp.ScopedDevice(self.device):
            ids = wp.array(sensor_ids.astype(np.int32), dtype=wp.int32)
            out = wp.empty(len(sensor_ids), dtype=wp.vec2d)
            if len(sensor_ids):
                KM.load([KM.analytic_module()], self.device)
                wp.launch(self._K.analytic_kernel, dim=len(sensor_ids), inputs=[self._dev.rec, self._dev.sensors, ids], outputs=[out])
                mean[sensor_ids] = out.numpy().astype(np.float64)
        return mean

    def _run_hybrid(self, method: str, ids: np.ndarray, kw: dict) -> EngineResult:
        """``exact+path`` / ``exact+guided``: each irradiance sensor's direct light from the emitters
        :mod:`.exact` reads computed on the host, the rest sampled by the paths in one pass.

        The computed (sensor, light) pairs take 2 in the device's light mask: at the sensor's own
        vertex those lights are neither light-sampled nor counted where a direction meets them
        (``kernels.light_pick.computed_at``), so a sample holds the reflected light and the direct
        light of the lights not computed (point, shaped, distant, sphere lights, a textured dome,
        emitters a pane may stand before), each once. Reading = sampled + computed; standard error
        = the samples' + the computed part's float error bound. The pilots and the stopping rule
        judge the whole reading (``_offset``). Sensors other than irradiance ones, and a spectral
        run, are read by the paths alone."""
        from simulator.engine.exact import exact_direct

        base = HYBRID_METHODS[method]
        n_s = len(self.sensors)
        irr = np.array([i for i in ids if self.sensors[i].kind == SensorKind.IRRADIANCE
                        and getattr(self.sensors[i], "optics", None) is None], np.int64)  # the computed part reads the cosine
        if self._hero is not None or kw["component"] != "total" or not len(irr):
            r = self.run(base, sensor_ids=ids, **kw)
            r.method = method
            return r
        from simulator.engine.exact import covered_records

        n_rec = int(self._dev.rec.n_lights)  # the device scene (uploaded here if not yet) counts the records
        kept = self._light_mask
        full = np.ones((n_s, n_rec), np.int32)
        if kept is not None:
            full[:, : kept.shape[1]] = kept
        # the plan's choice (set_computed) where it made one for these sensors, else every light that can be
        if self._computed is not None and self._computed[irr].any():
            want = np.zeros((n_s, n_rec), bool)
            want[:, : min(n_rec, self._computed.shape[1])] = self._computed[:, :n_rec]
        else:
            want = np.zeros((n_s, n_rec), bool)
            for r_, why in covered_records(self.scene):
                want[irr, r_] = why is None and r_ < n_rec
        want &= full != 0
        t_exact = 0.0
        try:
            if self.hybrid == "auto":  # decided before computing anything: the pilot reads the mask it would run
                mask = full.copy()
                mask[want] = 2
                choice = self._hybrid_choice(base, irr, kw, full, mask, want)
            else:
                self.hybrid_pilot = choice = {"computed": bool(self.hybrid), "chosen_by": "Engine.hybrid"}
            if not choice["computed"]:  # the pilot finds that sampling it all is cheaper: nothing is computed
                r = self.run(base, sensor_ids=ids, **kw)
                return r
            t0 = time.perf_counter()
            ex = exact_direct(self.scene, self.sensors, irr, full, want)
            t_exact = self.exact_seconds = time.perf_counter() - t0
            mask = full.copy()
            mask[:, : ex.covered.shape[1]][ex.covered[:, :n_rec]] = 2  # what a pane keeps from the host stays sampled
            self.set_light_mask(mask)
            self._offset = ex.mean
            r = self.run(base, sensor_ids=ids, **kw)
        finally:
            self._offset = None
            if kept is None:
                self._light_mask = None
                self._dev.set_light_mask(np.ones((n_s, n_rec), np.int32))
                self._mask_version = self._mask_full = b""
            else:
                self.set_light_mask(kept)
        r.method = method
        r.mean = r.mean + ex.mean
        r.stderr = r.stderr + ex.bound
        r.wall_s += t_exact
        r.seconds = r.seconds + np.where(np.isin(np.arange(n_s), irr), t_exact / max(len(irr), 1), 0.0)
        return r

    def _hybrid_choice(self, base: str, ids: np.ndarray, kw: dict, plain: np.ndarray, hybrid: np.ndarray,
                       covered: np.ndarray) -> dict:  # fmt: skip
        """Whether computing the direct light pays for this run, from a pilot (``hybrid_pilot`` keeps it).

        On up to :data:`HYBRID_PILOT_SENSORS` of the sensors (evenly spread), :data:`SPLIT_PILOT_SAMPLES`
        samples each, counting rays, on a seed stream of their own: the direct light with every light
        sampled (V_d, c_d: relative variance per sample over the whole reading's square, summed over the
        sensors, and rays per sample), the direct light with the computed lights left out (V_d', c_d'),
        and the reflected light (V_i, c_i), as the split pilot draws them. With the split's Neyman
        allocation K (kernels.estimators.split_irradiance) each way, the cost of a given error is

            sampled:   (V_d + V_i/K)·(c_d + K·c_i)
            computed:  (V_d' + V_i/K')·(c_d' + K'·c_i + x/n),

        x the computed part's time in rays per sensor (the planner's cost model of it,
        ``plan.exact_rule.exact_costs``, over ``RAY_S``: counts, not seconds, so the choice is the same
        at any thread count or load) and n the samples per sensor the run will draw (its
        ``samples``, or in an adaptive run the pilot's need z²·V/rel² where larger). The exact part
        is kept where it costs less."""
        from simulator.engine.scenario_split import neyman_split
        from simulator.plan.exact_rule import RAY_S, exact_costs

        tb = time.perf_counter()
        seed, depth = int(kw["seed"]), int(kw["max_depth"])
        # the preparations run() makes first (each done once per engine or kept): pieces, guide, pick
        if METHOD_FLAGS[base][0] and self.emitter_pieces == "auto" and self.pieces_pilot is None:
            self._choose_pieces(base, seed, depth, "total", ids)
        if base in GUIDED_METHODS and self._guide_pays(int(kw["samples"]), kw["rel_error"], None):
            self.ensure_guide(seed, ids, depth)
        self.set_light_mask(plain)
        params = self.trace_params(base, (seed + 0x2545F491) & 0x7FFFFFFF, depth, "total")
        params.pick_light = LIGHT_PICK_MODES[self.light_pick_mode(base)]
        if params.pick_light or (params.nee and int(self._dev.rec.n_pieces) > 1):
            self._prepare_pick(base, seed, depth, "total", ids)
        spread = np.linspace(0, len(ids) - 1, min(len(ids), HYBRID_PILOT_SENSORS)).round().astype(np.int64)
        pick = ids[np.unique(spread)]
        count = np.full(len(pick), SPLIT_PILOT_SAMPLES, np.int64)
        parts = []
        rays_kept = self.rays_traced
        try:
            params.count_rays = 1
            for mask, bounces, skip in ((plain, 0, 0), (hybrid, 0, 0), (plain, depth, 1)):
                self.set_light_mask(mask)
                params.bounces, params.skip_direct = bounces, skip
                self.rays_traced = 0
                _, cnt, mean, m2 = self._launch(params, pick, np.zeros(len(pick), np.int64), count)[:4]
                parts.append((mean[:, 1], m2[:, 1] / np.maximum(cnt - 1, 1), max(self.rays_traced / max(1, int(cnt.sum())), 1.0)))
        finally:
            self.rays_traced = rays_kept
            self.set_light_mask(plain)
        (m_d, v_d, c_d), (_, v_h, c_h), (m_i, v_i, c_i) = parts
        m = m_d + m_i
        ok = m > 0
        rv = [float((v[ok] / m[ok] ** 2).sum()) for v in (v_d, v_h, v_i)]
        k_p, _ = neyman_split(rv[0], rv[2], c_d, c_i, SPLIT_MAX, SPLIT_MIN_GAIN)
        k_h, _ = neyman_split(rv[1], rv[2], c_h, c_i, SPLIT_MAX, SPLIT_MIN_GAIN)
        var_p, ray_p = rv[0] + rv[2] / k_p, c_d + k_p * c_i
        var_h, ray_h = rv[1] + rv[2] / k_h, c_h + k_h * c_i
        n = float(kw["samples"])
        if kw["rel_error"] is not None:  # adaptive: the samples the mean pilot sensor needs
            z = z_for_confidence(kw["confidence"])
            n = max(n, z * z * var_h / max(int(ok.sum()), 1) / kw["rel_error"] ** 2)
        recs = [np.flatnonzero(covered[i]).tolist() for i in ids]
        x = float(exact_costs(self.scene, [self.sensors[i] for i in ids], recs)[0].sum()) / max(len(ids), 1) / RAY_S
        cost_p, cost_h = var_p * ray_p, var_h * (ray_h + x / max(n, 1.0))
        self.hybrid_pilot = {"computed": bool(cost_h < cost_p), "relvar_direct_sampled": rv[0] / max(int(ok.sum()), 1),
                             "relvar_direct_left": rv[1] / max(int(ok.sum()), 1),
                             "relvar_indirect": rv[2] / max(int(ok.sum()), 1), "rays_direct_sampled": c_d,
                             "rays_direct_left": c_h, "rays_indirect": c_i, "k_sampled": k_p, "k_computed": k_h,
                             "exact_rays_per_sensor": x, "samples_per_sensor": n, "cost_sampled": cost_p,
                             "cost_computed": cost_h, "seconds": time.perf_counter() - tb}  # fmt: skip
        return self.hybrid_pilot

    def _run_exact(self, sensor_ids: np.ndarray) -> EngineResult:
        """Direct light by Lambert's formula on the visible parts of the emitters :mod:`.exact` reads
        (the planner has checked that they are all a sensor's lights): no samples, on the host in
        float64; the standard error is 0 (as for analytic: rounding only), or with a DiskLight its polygons' bound."""
        from simulator.engine.exact import exact_direct

        n_s = len(self.sensors)
        t0 = time.perf_counter()
        ex = exact_direct(self.scene, self.sensors, sensor_ids, self._light_mask)
        mean = ex.mean
        wall = time.perf_counter() - t0
        return EngineResult(
            method="exact",
            device="cpu",
            mean=mean,
            stderr=ex.disk_bound,  # float rounding (~1e-13 of a reading) is not reported, as for analytic
            samples=np.zeros(n_s, np.int64),
            seconds=np.full(n_s, wall / max(len(sensor_ids), 1)),
            target_met=None,
            non_finite=np.zeros(n_s, np.int64),
            wall_s=wall,
            warnings=list(self.warnings),
        )

    def run(
        self,
        method: str,
        *,
        samples: int,
        seed: int,
        rel_error: float | None = None,
        abs_error: float = 0.0,
        max_samples: int = 1 << 20,
        time_limit_s: float | None = None,
        max_depth: int = -1,
        component: str = "total",
        progress: Callable[[Progress], None] | None = None,
        count_rays: bool | int = False,
        sensor_ids: np.ndarray | None = None,
        confidence: float = 0.95,
        stop: StopFlag | None = None,
        groups: LightGroups | None = None,
        choose_first_batch: bool = False,
    ) -> EngineResult:
        """Estimate every sensor with ``method`` (analytic, exact, light, bsdf, mis, path or guided).

        ``guided`` builds the surface guide on its first run (a pilot over
        ``sensor_ids``, :meth:`ensure_guide`; its cost is ``self.guide.seconds``,
        not part of ``wall_s``) and reuses it afterwards.

        Fixed budget (``rel_error`` None): ``samples`` per sensor. Adaptive:
        ``samples`` is the first batch (with ``choose_first_batch``, its
        upper bound: the batch is sized from a short pilot,
        ``adaptive.first_batch_from_pilot``, and the roulette pilot tuned
        to the target with :data:`adaptive.PILOT_MIN_BATCH` as the floor
        instead of ``samples``; ``batch_plans[method]`` says what it chose
        and, after the run, the samples the slowest sensor needed and
        spent); a sensor stops when
        z·stderr ≤ max(rel_error·|mean|, abs_error) in both channels (z for
        ``confidence``, see :mod:`.adaptive`) and, when tracing spectrally, in
        every response of the hero tables (so each reported response column
        meets the target), or at ``max_samples``; all stop at ``time_limit_s``.

        ``component``: ``total``; ``direct`` (light straight from emitters,
        and for a radiance meter its first surface's reflection of it); or
        ``indirect`` (the rest: light that has been reflected on the way).

        ``stop``: once requested (by Ctrl-C during a batch, or by
        ``KeyboardInterrupt`` from ``progress``) no further batch is drawn;
        the result holds the whole batches drawn so far, ``interrupted`` is
        True and ``unfinished`` marks the sensors stopped short. Without
        ``stop``, Ctrl-C raises ``KeyboardInterrupt`` once the batch is done.

        ``count_rays``: count the rays traced in ``rays_traced`` (True or 1:
        every ray; 2: shadow rays only, so two runs of the same samples split
        them by kind, as ``benchmarks/profile_office.py`` does).

        ``groups``: also tally every sample's light per light group on the
        same paths (one pass), giving ``group_mean`` and ``group_cov``; with
        ``groups.levels`` an adaptive run stops on the recombined readings
        (see :class:`LightGroups`). Closed-form methods read each group on
        its own (exact, covariance 0). See :meth:`run_groups`.
        """
        if component not in COMPONENTS:
            raise UserError(f"simulation.component: {component!r} is not one of {', '.join(COMPONENTS)}")
        if component == "indirect" and method in METHOD_FLAGS and not METHOD_FLAGS[method][3]:
            raise UserError(f"simulation.component: 'indirect' needs method path, not {method!r}")
        if any(s.spec.reader != "estimate" for s in self.sensors):
            raise ValueError("probe sensors are read by Engine.run_probes, not Engine.run")
        ids_all = np.arange(len(self.sensors)) if sensor_ids is None else np.asarray(sensor_ids, np.int64)
        if groups is not None and method in ("analytic", "exact"):
            return self._closed_form_groups(method, ids_all, groups)
        if method == "analytic":
            return self._run_analytic(ids_all)
        if method == "exact":
            return self._run_exact(ids_all)
        if method in HYBRID_METHODS:
            if groups is not None:  # a light-group pass tallies every light on its paths: all sampled
                method = HYBRID_METHODS[method]
            else:
                return self._run_hybrid(method, ids_all, dict(
                    samples=samples, seed=seed, rel_error=rel_error, abs_error=abs_error, max_samples=max_samples,
                    time_limit_s=time_limit_s, max_depth=max_depth, component=component, progress=progress,
                    count_rays=count_rays, confidence=confidence, stop=stop, choose_first_batch=choose_first_batch))
        if method not in METHOD_FLAGS:
            raise UserError(f"method {method!r} has no Monte Carlo kernel (expected one of {sorted(METHOD_FLAGS)})")
        n_s = len(self.sensors)
        if METHOD_FLAGS[method][0] and self.emitter_pieces == "auto" and self.pieces_pilot is None:
            self._choose_pieces(method, seed, max_depth, component, ids_all)  # before the guide: it may rebuild
        if method in GUIDED_METHODS and self._guide_pays(samples, rel_error, groups):
            self.ensure_guide(seed, ids_all, max_depth, groups)
        params = self.trace_params(method, seed, max_depth, component)
        params.count_rays = int(count_rays)  # True: every ray; 2: shadow rays only (kernels.rays)
        params.pick_light = LIGHT_PICK_MODES[self.light_pick_mode(method)]
        if params.pick_light or (params.nee and int(self._dev.rec.n_pieces) > 1):
            self._prepare_pick(method, seed, max_depth, component, ids_all)  # and the emitter pieces' factors
            params.pick_light = self._scenario_pick(groups, params.pick_light)
        self.split_pilot = None
        if METHOD_FLAGS[method][3] and params.bounces != 0 and component == "total":
            # before the roulette and first-batch pilots, so that they measure the samples the run draws
            k = self.split_indirect
            if k == "auto":
                k = self._split_rule(params, ids_all, groups)
            params.split_indirect = int(k) if int(k) > 1 else 0
        adaptive = rel_error is not None
        choose = adaptive and choose_first_batch
        z = z_for_confidence(confidence)
        first_batch = min(samples, max_samples) if adaptive else samples
        floor = min(PILOT_MIN_BATCH, first_batch) if choose else first_batch
        rr_ran = False
        if METHOD_FLAGS[method][3] and params.bounces != 0 and self.rr_threshold is None:
            params.rr_threshold = self._prepare_rr(params, method, max_depth, component, ids_all, floor, z, rel_error)
            rr_ran = True
        plan = None
        if choose:
            plan = self._first_batch(params, method, ids_all, first_batch, z, rel_error, rr_ran)
            first_batch = plan["first_batch"]
        elif adaptive:
            plan = {"first_batch": int(first_batch), "chosen_by": "samples"}
        self.rays_traced = self.shadow_rays_traced = 0  # shadow and path rays, counted when count_rays
        stats = RunningStats(n_s)
        n_resp = self._dev.n_responses if params.spectral else 0
        rstats = RunningStats(n_s, n_resp) if n_resp else None
        gstats = None
        if groups is not None:
            gstats = (GroupBatchStats if groups.uses_batches else GroupStats)(n_s, groups.n_groups)
            self._set_groups(params, groups)
        seconds = np.zeros(n_s)
        nonfinite = np.zeros(n_s, np.int64)
        cap = max_samples if adaptive else samples
        active = np.zeros(n_s, bool)
        active[ids_all] = True
        n_run = len(ids_all)
        want = np.full(n_s, min(first_batch, cap), np.int64)  # next batch per sensor
        if not adaptive:
            per = max(BLOCK, SAMPLES_PER_LAUNCH // max(n_run, 1))
            want = np.minimum(want, per)

        # batch means need batches: a fixed budget too small for two whole blocks per sensor is cut into
        # MIN_GROUP_BATCHES smaller ones (one block of 16 samples left every sky patch's error infinite)
        block = BLOCK
        if isinstance(gstats, GroupBatchStats) and not adaptive and cap < 2 * BLOCK:
            block = max(1, cap // MIN_GROUP_BATCHES)

        def step(ids, first, count):
            parts = [(ids, first, count)]
            if gstats is not None:
                width = groups.state_width()
                parts = _split_batch(ids, first, count, max(1, GROUP_STATE_BYTES // (16 * width)) * block, block)
            for p_ids, p_first, p_count in parts:
                tb = time.perf_counter()
                sens, cnt, mean, m2, bad, r_mean, r_m2, g_mean, g_m2 = self._launch(params, p_ids, p_first, p_count,
                                                                                     block=block)  # fmt: skip
                dt = time.perf_counter() - tb
                stats.merge(sens, cnt, mean, m2)
                if rstats is not None:
                    rstats.merge(sens, cnt, r_mean, r_m2)
                if isinstance(gstats, GroupBatchStats):
                    gstats.merge_blocks(*g_mean)
                elif gstats is not None:
                    gstats.merge(sens, cnt, g_mean, g_m2)
                seconds[sens] += dt * cnt / cnt.sum()
                nonfinite[sens] += bad

        def measure():
            if gstats is None or groups.levels is None:
                value, se = stats.mean, stats.stderr()
                if self._offset is not None:  # a hybrid run: the target is the whole reading's
                    value = value + self._offset
            else:
                value, se = _recombined(gstats.mean, gstats.cov(), groups.levels)
            if rstats is None:
                return value, se
            # spectral transport: every requested response (PPFD, melanopic EDI, ...) meets the target too
            return np.concatenate([value, rstats.mean], axis=1), np.concatenate([se, rstats.stderr()], axis=1)

        def report(count, active, elapsed):
            if progress is None:
                return
            done_n = n_run - int(active.sum())
            frac = stats.count.sum() / max(1, cap * n_run) if not adaptive else done_n / max(n_run, 1)
            eta = elapsed / frac * (1 - frac) if frac > 0 and active.any() else 0.0
            progress(Progress(done_n, n_run, int(stats.count.sum()), elapsed, eta))

        t0 = time.perf_counter()
        _, met = run_batches(
            step, active, want, cap, block=BLOCK,
            rule=StoppingRule(rel_error, abs_error, confidence) if adaptive else None,
            measure=measure, time_limit_s=time_limit_s, t_start=t0, report=report,
            stop=stop, dark_floor=min(samples, cap) if choose else 0,
        )  # fmt: skip
        wall = time.perf_counter() - t0
        if plan is not None:
            plan.update(_economy(stats, measure, ids_all, met, rel_error, abs_error, z))
            self.batch_plans[method] = plan
        warnings = list(self.warnings)
        if method == "bsdf" and any(l.is_delta for l in self.scene.lights):
            names = ", ".join(l.name for l in self.scene.lights if l.is_delta)
            warnings.append(f"method bsdf cannot see point or angle-0 distant lights; they add nothing: {names}")
        if nonfinite.any():
            warnings.append(f"{int(nonfinite.sum())} non-finite samples were dropped")
        return EngineResult(
            method=method,
            device=self.device,
            mean=stats.mean.copy(),
            stderr=stats.stderr(),
            samples=stats.count.copy(),
            seconds=seconds,
            target_met=met if adaptive else None,
            non_finite=nonfinite,
            wall_s=wall,
            warnings=warnings,
            unfinished=active.copy(),
            interrupted=stop is not None and stop.requested,
            responses=None if rstats is None else [r.name for r in self._hero.responses],
            response_mean=None if rstats is None else rstats.mean.copy(),
            response_stderr=None if rstats is None else rstats.stderr(),
            group_mean=None if gstats is None else np.transpose(gstats.mean, (2, 0, 1)).copy(),
            group_cov=None if gstats is None else gstats.cov(),
        )

    def run_groups(self, method: str, groups: LightGroups, **kw) -> EngineResult:
        """Each light group's reading of every sensor, and their covariance, from one pass.

        Every sample's light is tallied per group as the kernel adds it up
        (``light_contribution``), so the groups share paths: the pass costs
        about one :meth:`run`, and the per-sample group vectors give the full
        covariance between groups. ``mean`` and ``stderr`` are the total's
        (all lights at their authored level); ``group_mean`` (G, S, 2) and
        ``group_cov`` (S, 2, G, G) the groups'. Keywords as for :meth:`run`.
        """
        return self.run(method, groups=groups, **kw)

    def _set_groups(self, params, groups: LightGroups) -> None:
        lg = np.full(max(int(self._dev.rec.n_lights), 1), -1, np.int64)
        lg[: len(groups.light_group)] = groups.light_group
        if self.emissive_light >= 0:
            lg[self.emissive_light] = groups.emissive_group
        params.group_tally = 1
        params.n_groups = int(groups.n_groups)
        params.group_batch = 1 if groups.uses_batches else 0
        self._upload_light_groups(lg, groups.patch_base)

    def _closed_form_groups(self, method: str, ids: np.ndarray, groups: LightGroups) -> EngineResult:
        """Closed-form readings per light group: each group's lights alone (exact, so the covariance is 0)."""
        from dataclasses import replace

        n_s, n_g = len(self.sensors), groups.n_groups
        g_mean = np.zeros((n_g, n_s, 2))
        wall = 0.0
        for g in range(n_g):
            keep = np.flatnonzero(np.asarray(groups.light_group) == g)
            if not len(keep):
                continue
            sub = replace(self.scene, lights=[self.scene.lights[i] for i in keep])
            eng = Engine(sub, self.sensors, device=self.device, threads=self.threads)
            if self._light_mask is not None:
                eng.set_light_mask(self._light_mask[:, keep])
            r = eng.run(method, samples=0, seed=0, sensor_ids=ids)
            g_mean[g] = r.mean
            wall += r.wall_s
        return EngineResult(
            method=method, device=self.device, mean=g_mean.sum(axis=0), stderr=np.zeros((n_s, 2)),
            samples=np.zeros(n_s, np.int64), seconds=np.full(n_s, wall / max(len(ids), 1)), target_met=None,
            non_finite=np.zeros(n_s, np.int64), wall_s=wall, warnings=list(self.warnings), group_mean=g_mean,
            group_cov=np.zeros((n_s, 2, n_g, n_g)),
        )  # fmt: skip

    # ------------------------------------------------------------ probes

    def _launch_passes(self, rec, params, n_pix: int, first_pass: int, n_passes: int):
        """Draw passes [first_pass, first_pass + n_passes) of every pixel of
        the probe ``rec``. Returns per-pixel (counts, means, m2s) of shape
        (P,), (P, K), (P, K) and the number of non-finite samples; K = 2Q, and
        3 more (linear sRGB) with spectral transport."""
        wp = warp()
        width = P.probe_width(bool(params.spectral))
        blocks = (n_passes + PASS_BLOCK - 1) // PASS_BLOCK
        counts_blk = np.minimum(PASS_BLOCK, n_passes - PASS_BLOCK * np.arange(blocks))
        pix_per_launch = max(1, THREADS_PER_LAUNCH // blocks)
        counts = np.full(n_pix, n_passes, np.int64)
        rec_scene = self._dev.rec
        probe_kernel = self._KP.probe_kernel_for(rec_scene.surfaces)  # the stage's trace variant
        means = np.empty((n_pix, width))
        m2s = np.empty((n_pix, width))
        bad_total = 0
        with wp.ScopedDevice(self.device):
            for p0 in range(0, n_pix, pix_per_launch):
                p1 = min(n_pix, p0 + pix_per_launch)
                n = (p1 - p0) * blocks
                shift = wp.empty((n, width), dtype=wp.float64)
                s1 = wp.empty((n, width), dtype=wp.float64)
                s2 = wp.empty((n, width), dtype=wp.float64)
                bad = wp.empty(n, dtype=wp.int32)
                if params.spectral:
                    rec_scene.response_lanes = wp.zeros(n, dtype=wp.vec4)

                def run(offset: int, dim: int):
                    wp.launch(
                        probe_kernel,
                        dim=dim,
                        inputs=[rec_scene, rec, params, 0, first_pass, n_passes, PASS_BLOCK, blocks, p0, offset],
                        outputs=[shift, s1, s2, bad],
                    )

                fan_out(self.threads, run, n)
                wp.synchronize_device()
                block_pix = np.repeat(np.arange(p0, p1), blocks)
                block_cnt = np.tile(counts_blk, p1 - p0)
                _, _, m, v = RunningStats.reduce_blocks(block_pix, block_cnt, shift.numpy(), s1.numpy(), s2.numpy())
                means[p0:p1] = m
                m2s[p0:p1] = v
                bad_total += int(bad.numpy().sum())
        return counts, means, m2s, bad_total

    def _probe_delta(self, rec, params) -> np.ndarray:
        """The delta lights' exact contributions to a probe's integrals, (Q, C)."""
        wp = warp()
        width = P.probe_width(bool(params.spectral))
        with wp.ScopedDevice(self.device):
            d_shift = wp.zeros((1, width), dtype=wp.float64)
            d_sum = wp.zeros((1, width), dtype=wp.float64)
            d_sq = wp.zeros((1, width), dtype=wp.float64)
            d_bad = wp.zeros(1, dtype=wp.int32)
            wp.launch(self._KP.probe_kernel_for(self._dev.rec.surfaces), dim=1,
                      inputs=[self._dev.rec, rec, params, 1, 0, 0, 1, 1, 0, 0], outputs=[d_shift, d_sum, d_sq, d_bad])
            return d_sum.numpy()[0][: P.N_QUANTITIES * P.N_CHANNELS].reshape(P.N_QUANTITIES, P.N_CHANNELS)

    # probe passes over a layout of the caller's (glare views: simulator.engine.glare)

    def probe_record(self):
        """An empty ``ProbeRec`` to fill with a layout of one's own, the probe kernels loaded."""
        KM.load([KM.trace_module(self.trace_variant.surfaces)], self.device)
        return self._KP.ProbeRec()

    def probe_passes(self, rec, params, first_pass: int, n_passes: int):
        """Passes [first_pass, first_pass + n_passes) of every pixel of ``rec``: per-pixel
        ``(counts, means, m2s, non_finite)`` as :meth:`run_probes` merges them."""
        return self._launch_passes(rec, params, int(rec.width) * int(rec.height), first_pass, n_passes)

    def probe_delta(self, rec, params) -> np.ndarray:
        """The delta lights' exact part of the probe integrals at ``rec.position``, (22, 2)."""
        return self._probe_delta(rec, params)

    def run_probes(
        self,
        probes: list[Sensor],
        method: str,
        *,
        samples: int,
        seed: int,
        stream_ids: list[int] | None = None,
        rel_error: float | None = None,
        confidence: float = 0.95,
        abs_error: float = 0.0,
        max_samples: int = 1 << 20,
        time_limit_s: float | None = None,
        max_depth: int = -1,
        component: str = "total",
        progress: Callable | None = None,
        stop: StopFlag | None = None,
    ) -> list[P.ProbeResult]:
        """Lat-long maps and sphere integrals of PROBE sensors (which
        :meth:`run` does not read) with ``method`` (light, bsdf, mis or path);
        the estimator is described in :mod:`simulator.engine.probes`.

        Parameters
        ----------
        probes : list of Sensor
            Sensors of kind PROBE.
        samples : int
            Directions per probe, rounded up to whole passes (one direction per
            pixel each), at least :data:`~simulator.engine.probes.MIN_PASSES`
            passes. In adaptive mode the first batch.
        seed : int
            Run seed.
        stream_ids : list of int, optional
            Random-stream index of each probe (its index among all the run's
            sensors); default ``range(len(probes))``.
        rel_error, abs_error, confidence, max_samples, time_limit_s
            Adaptive stopping as for :meth:`run`, applied to the probe's
            scalar irradiance (both channels); ``max_samples`` caps the
            directions per probe. ``time_limit_s`` counts from the start of
            this call; a probe past it still finishes its current batch (at
            least ``MIN_PASSES`` passes).
        max_depth, component
            As for :meth:`run`.
        progress : callable, optional
            Receives :class:`Progress` after each batch.
        stop : StopFlag, optional
            As for :meth:`run`: once requested, no further probe is started;
            the probe being read keeps its whole batches (at least one) with
            ``target_met`` False, and one stopped before its first batch is
            left out.

        Returns
        -------
        list of ProbeResult
            One per probe read, in order: all of them unless stopped.
        """
        if method not in METHOD_FLAGS:
            raise UserError(f"method {method!r} cannot read probes (use light, bsdf, mis, path, guided or auto)")
        warp()  # initialised before the probe kernel's module loads
        KM.load([KM.trace_module(self.trace_variant.surfaces)], self.device)  # the probe kernel is in its variant's module
        params = self.trace_params(method, seed, max_depth, component)
        stream_ids = list(range(len(probes))) if stream_ids is None else list(stream_ids)
        frame = P.probe_frame(self.scene.up_axis)
        rule = StoppingRule(rel_error, abs_error, confidence) if rel_error is not None else None
        out: list[P.ProbeResult] = []
        t_start = time.perf_counter()
        total_samples = 0
        for k, s in enumerate(probes):
            if stop is not None and stop.requested:
                break
            if s.kind != SensorKind.PROBE:
                raise ValueError(f"{s.name}: not a probe")
            w, h = s.resolution
            n_pix = int(w) * int(h)
            if n_pix < 1 or n_pix > MAX_PROBE_PIXELS:
                raise UserError(f"{s.source}: probe {s.name!r}: resolution {w} x {h} must have 1 to {MAX_PROBE_PIXELS} pixels")
            t0 = time.perf_counter()
            rec = P.probe_record(self._KP.ProbeRec(), s, frame, P.stream_key(seed, stream_ids[k]))
            omega = P.pixel_solid_angles(w, h).reshape(-1)
            delta = self._probe_delta(rec, params)  # delta lights: exact, once
            stats = RunningStats(n_pix, P.probe_width(bool(params.spectral)))
            first_batch = max(P.MIN_PASSES, -(-samples // n_pix))
            cap = max(P.MIN_PASSES, -(-max_samples // n_pix)) if rule is not None else first_batch
            bad = [0]

            def step(ids, first, count):
                counts, means, m2s, b = self._launch_passes(rec, params, n_pix, int(first[0]), int(count[0]))
                stats.merge(np.arange(n_pix), counts, means, m2s)
                bad[0] += b

            def measure():
                val, se = P.integrals(stats, omega, delta)
                return val[0][None, :], se[0][None, :]

            def report(count, active, elapsed):
                if progress is not None:
                    done = not active[0]
                    progress(Progress(k + int(done), len(probes), total_samples + int(stats.count.sum()), elapsed, None))

            active = np.ones(1, bool)
            passes, met = run_batches(
                step, active, np.array([min(first_batch, cap)], np.int64), cap, block=PASS_BLOCK, rule=rule,
                measure=measure, time_limit_s=time_limit_s, t_start=t_start, report=report, stop=stop,
            )  # fmt: skip
            if passes[0] == 0:  # stopped before its first batch: nothing to report
                break
            total_samples += int(passes[0]) * n_pix
            target_met = False if active[0] else (bool(met[0]) if rule is not None else None)
            out.append(P.probe_result(s, frame, stats, omega, delta, int(passes[0]), time.perf_counter() - t0, bad[0],
                                      target_met))  # fmt: skip
            out[-1].interrupted = bool(active[0])
        return out


def _economy(stats: RunningStats, measure, ids: np.ndarray, met: np.ndarray, rel_error: float,
             abs_error: float, z: float) -> dict:
    """What an adaptive run spent against what its sensors needed: a
    sensor's need is z²·stderr²·n/target² (the samples that meet the target
    at its measured variance), the largest over its channels. Over the
    sensors that met the target: the largest need and the samples the
    sensor with it drew, and all samples drawn over all needs."""
    value, se = measure()
    n = stats.count[ids].astype(np.float64)
    target = np.maximum(rel_error * np.abs(value[ids]), abs_error)
    with np.errstate(divide="ignore", invalid="ignore"):
        need = np.nan_to_num(np.max((z * se[ids]) ** 2 * n[:, None] / target**2, axis=1), nan=0.0, posinf=0.0)
    ok = met[ids]
    if not ok.any():
        return {"needed_max": None, "spent_at_needed_max": None, "spent_over_needed": None}
    k = int(np.argmax(np.where(ok, need, -1.0)))
    return {"needed_max": float(need[k]), "spent_at_needed_max": int(n[k]), "spent_max": int(n[ok].max()),
            "spent_over_needed": float(n[ok].sum() / max(need[ok].sum(), 1e-300))}


def _recombined(mean: np.ndarray, cov: np.ndarray, levels: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Readings ``d_jᵀ x̄`` and standard errors ``sqrt(d_jᵀ C d_j)`` of the dimming vectors ``levels`` (J, G),
    from group means (S, C, G) and covariance (S, C, G, G); both (S, J·C), the stopping rule's channels."""
    d = np.asarray(levels, np.float64)
    val = np.einsum("jg,scg->sjc", d, mean)
    var = np.stack([lit_variance(dj, cov) for dj in d], axis=1)  # (S, J, C); an unlit unknown group adds 0
    se = np.sqrt(np.maximum(var, 0.0))
    return val.reshape(len(val), -1), se.reshape(len(se), -1)


@contextmanager
def _fields_set(rec, **values):
    """Set attributes of ``rec`` (the launch parameters, a Warp struct, or the engine) for a pilot's
    launches and restore the run's values after, however the block ends; the launch parameters are
    changed in place because a struct's copy would share its array fields with the original."""
    kept = {name: getattr(rec, name) for name in values}
    for name, value in values.items():
        setattr(rec, name, value)
    try:
        yield rec
    finally:
        for name, value in kept.items():
            setattr(rec, name, value)


def _split_batch(ids: np.ndarray, first: np.ndarray, count: np.ndarray, max_samples: int, block: int = BLOCK) -> list[tuple]:
    """A batch ``(ids, first, count)`` cut into launches of at most ``max_samples`` samples (a multiple
    of ``block``, the samples per kernel thread), each sensor at most once per launch, samples in order
    (the random streams are per sample, so the cut changes no sample)."""
    out, cur, room = [], ([], [], []), max_samples
    for i, f, c in zip(ids, first, count):
        f, c = int(f), int(c)
        while c > 0:
            take = min(c, room)
            cur[0].append(i), cur[1].append(f), cur[2].append(take)
            f, c, room = f + take, c - take, room - -(-take // block) * block
            if room <= 0:
                out.append(cur)
                cur, room = ([], [], []), max_samples
    if cur[0]:
        out.append(cur)
    return [(np.asarray(a, np.int64), np.asarray(b, np.int64), np.asarray(c, np.int64)) for a, b, c in out]


def patch_pick_factors(tally: np.ndarray, row0: np.ndarray) -> np.ndarray:
    """The light pick's factors per patch, (N, L): Σ w·value / Σ w·ê over the pilot's vertices on
    each patch, shrunk toward row 0's factors ``row0`` (L,) by PATCH_PICK_PRIOR_VISITS visits' worth
    of the patch's mean estimate; a patch the pilot never reached keeps row 0's. ``tally``: (N, L, 3)
    sums of (w·ê, w·value, visits)."""
    est, got, visits = tally[..., 0], tally[..., 1], tally[..., 2]
    mean_est = np.where(visits > 0, est / np.where(visits > 0, visits, 1.0), 0.0)
    prior = PATCH_PICK_PRIOR_VISITS * mean_est
    den = est + prior
    return np.where(den > 0, (got + prior * row0[None]) / np.where(den > 0, den, 1.0), row0[None])

