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
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from simulator.engine import probes as P
from simulator.engine.adaptive import StoppingRule, run_batches
from simulator.engine.device import DeviceScene, cuda_available, resolve_device, warp, warp_version
from simulator.engine.fanout import fan_out
from simulator.engine.methods import COMPONENTS, LIGHT_PICK_MODES, METHOD_FLAGS, light_pick_rule, rr_threshold_rule
from simulator.engine.stats import RunningStats
from simulator.errors import UserError
from simulator.interrupts import StopFlag
from simulator.scene.model import MAX_PROBE_PIXELS, Scene, Sensor, SensorKind

__all__ = [
    "COMPONENTS", "METHOD_FLAGS", "cuda_available", "warp_version", "Engine", "EngineResult", "Progress",
    "resolve_device",
]  # fmt: skip

#: samples one kernel thread draws for one sensor (a block)
BLOCK = 32
#: samples per launch in a batch: big enough to amortise the launch, small
#: enough that the progress bar and time limit are checked often
SAMPLES_PER_LAUNCH = 1 << 18
#: passes one kernel thread draws for one probe pixel
PASS_BLOCK = 16
#: probe kernel threads per launch: bounds the float64 sums held at once (~900 B each)
THREADS_PER_LAUNCH = 1 << 16
#: samples per sensor of the light pick's pilot (all lights sampled, tallied, then discarded)
PICK_PILOT_SAMPLES = 16
#: a sensor's own first-vertex pick factor is shrunk toward all sensors'
#: by this many pseudo-samples (a sensor's 16 pilot samples are few)
PICK_PRIOR_SAMPLES = 4


@dataclass
class Progress:
    """What a progress display is told after each batch."""

    sensors_done: int
    sensors_total: int
    samples: int
    elapsed_s: float
    eta_s: float | None


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
        self._light_mask: np.ndarray | None = None
        self._device_scene: DeviceScene | None = None
        #: next-event estimation by one picked light: "auto" (methods.light_pick_rule) or a methods.LIGHT_PICK_MODES key
        self.light_pick = "auto"
        #: Russian roulette threshold of path throughput; None: methods.rr_threshold_rule
        self.rr_threshold: float | None = None
        self._pick_key: tuple | None = None
        self._mask_version = 0

    def _upload(self) -> DeviceScene:
        """Import Warp, load the kernels and upload the scene, on first need: a
        run read wholly on the host (``exact``) never pays for it."""
        if self._device_scene is None:
            wp = warp()
            from simulator.kernels import estimators as K
            from simulator.kernels import probe as KP

            self._kernels = (K, KP)
            # compile (or load from the kernel cache) before worker threads launch
            wp.load_module(K, device=self.device)
            self._device_scene = DeviceScene(self.scene, self.sensors, self.device)
            if self._light_mask is not None:
                self._device_scene.set_light_mask(self._light_mask)
        return self._device_scene

    @property
    def _dev(self) -> DeviceScene:
        return self._upload()

    @property
    def _K(self):
        self._upload()
        return self._kernels[0]

    @property
    def _KP(self):
        self._upload()
        return self._kernels[1]

    @property
    def scene_rec(self):
        """The scene's device record (``kernels.lights.SceneRec``), for kernels."""
        return self._dev.rec

    @property
    def emissive_light(self) -> int:
        """Index of the light record standing for all emissive triangles, −1 if none."""
        return self._dev.emissive_light

    def set_light_mask(self, mask: np.ndarray) -> None:
        """Lights to skip per sensor at its first vertex: ``mask`` (S, L) over
        the scene's lights, 0 = wholly behind the sensor (see plan.lights_behind)."""
        mask = np.asarray(mask)
        if self._light_mask is None or not np.array_equal(self._light_mask, mask):
            self._mask_version += 1  # the light pick learns again (a plan run again keeps what it learnt)
        self._light_mask = mask
        if self._device_scene is not None:
            self._device_scene.set_light_mask(mask)

    def trace_params(self, method: str, seed: int, max_depth: int = -1, component: str = "total"):
        """The kernels' ``TraceParams`` for ``method`` (light, bsdf, mis or path)."""
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
        p.pick_light = 0
        p.tally_pick = 0
        p.rr_threshold = float(self.rr_threshold if self.rr_threshold is not None else rr_threshold_rule(self.scene)[0])
        return p

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
        wp = warp()
        dev = self._dev
        n_l = int(dev.rec.n_lights)
        params = self.trace_params(method, (seed + 0x3C6EF372) & 0x7FFFFFFF, max_depth, component)
        params.tally_pick = 1
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
        dev.set_pick_factors(factors)
        self._pick_key = key

    # ------------------------------------------------------------ sensors

    def _launch(self, params, sensor_ids: np.ndarray, first: np.ndarray, count: np.ndarray, tally: bool = False):
        """Draw count[i] samples of sensor_ids[i], starting at sample first[i].

        Returns (sensors, counts, means, m2s, non_finite) for the batch; with
        ``tally`` (a light-pick pilot, ``params.tally_pick``) instead each
        kernel thread's sensor and its pick tally, (threads × 2 × L) vec2."""
        wp = warp()
        nblk = (count + BLOCK - 1) // BLOCK
        t_sensor = np.repeat(sensor_ids, nblk).astype(np.int32)
        starts = np.repeat(np.cumsum(nblk) - nblk, nblk)
        within = np.arange(len(t_sensor)) - starts
        t_first = (np.repeat(first, nblk) + within * BLOCK).astype(np.int32)
        t_count = np.minimum(BLOCK, np.repeat(first + count, nblk) - t_first).astype(np.int32)
        n = len(t_sensor)
        rec = self._dev.rec
        with wp.ScopedDevice(self.device):
            a_sensor = wp.array(t_sensor, dtype=wp.int32)
            a_first = wp.array(t_first, dtype=wp.int32)
            a_count = wp.array(t_count, dtype=wp.int32)
            if params.count_rays:
                rec.ray_counts = wp.zeros(n, dtype=wp.int32)
            if tally:
                rec.pick_tally = wp.zeros(n * 2 * int(rec.n_lights), dtype=wp.vec2)
            shift = wp.empty(n, dtype=wp.vec2d)
            s1 = wp.empty(n, dtype=wp.vec2d)
            s2 = wp.empty(n, dtype=wp.vec2d)
            bad = wp.empty(n, dtype=wp.int32)

            def run(offset: int, dim: int):
                wp.launch(
                    self._K.estimate_kernel,
                    dim=dim,
                    inputs=[rec, self._dev.sensors, params, a_sensor, a_first, a_count, offset],
                    outputs=[shift, s1, s2, bad],
                )

            fan_out(self.threads, run, n)
            wp.synchronize_device()
            if tally:
                counts = rec.pick_tally.numpy()
                rec.pick_tally = wp.zeros(1, dtype=wp.vec2)
                return t_sensor, counts
            out = RunningStats.reduce_blocks(t_sensor, t_count, shift.numpy(), s1.numpy(), s2.numpy())
            if params.count_rays:
                self.rays_traced += int(rec.ray_counts.numpy().sum())
            nonfinite = np.add.reduceat(bad.numpy(), np.flatnonzero(np.r_[True, t_sensor[1:] != t_sensor[:-1]]))
        return (*out, nonfinite)

    def _run_analytic(self, sensor_ids: np.ndarray) -> EngineResult:
        """Closed-form readings (the caller has checked they apply): exact up
        to float32 rounding, so the standard error is 0 and no samples are drawn."""
        wp = warp()
        n_s = len(self.sensors)
        t0 = time.perf_counter()
        mean = np.zeros((n_s, 2))
        with wp.ScopedDevice(self.device):
            ids = wp.array(sensor_ids.astype(np.int32), dtype=wp.int32)
            out = wp.empty(len(sensor_ids), dtype=wp.vec2d)
            if len(sensor_ids):
                wp.launch(self._K.analytic_kernel, dim=len(sensor_ids), inputs=[self._dev.rec, self._dev.sensors, ids], outputs=[out])
                mean[sensor_ids] = out.numpy().astype(np.float64)
        wall = time.perf_counter() - t0
        return EngineResult(
            method="analytic",
            device=self.device,
            mean=mean,
            stderr=np.zeros((n_s, 2)),
            samples=np.zeros(n_s, np.int64),
            seconds=np.full(n_s, wall / max(n_s, 1)),
            target_met=None,
            non_finite=np.zeros(n_s, np.int64),
            wall_s=wall,
            warnings=list(self.warnings),
        )

    def _run_exact(self, sensor_ids: np.ndarray) -> EngineResult:
        """Direct light from RectLights by Lambert's formula on their visible
        parts (:mod:`.exact`; the planner has checked it applies): no samples,
        standard error 0, on the host in float64."""
        from simulator.engine.exact import exact_direct

        n_s = len(self.sensors)
        t0 = time.perf_counter()
        mean = exact_direct(self.scene, self.sensors, sensor_ids, self._light_mask)
        wall = time.perf_counter() - t0
        return EngineResult(
            method="exact",
            device="cpu",
            mean=mean,
            stderr=np.zeros((n_s, 2)),
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
        count_rays: bool = False,
        sensor_ids: np.ndarray | None = None,
        confidence: float = 0.95,
        stop: StopFlag | None = None,
    ) -> EngineResult:
        """Estimate every sensor with ``method`` (analytic, exact, light, bsdf, mis or path).

        Fixed budget (``rel_error`` None): ``samples`` per sensor. Adaptive:
        ``samples`` is the first batch; a sensor stops when
        z·stderr ≤ max(rel_error·|mean|, abs_error) in both channels (z for
        ``confidence``, see :mod:`.adaptive`), or at ``max_samples``; all stop
        at ``time_limit_s``.

        ``component``: ``total``; ``direct`` (light straight from emitters,
        and for a radiance meter its first surface's reflection of it); or
        ``indirect`` (the rest: light that has been reflected on the way).

        ``stop``: once requested (by Ctrl-C during a batch, or by
        ``KeyboardInterrupt`` from ``progress``) no further batch is drawn;
        the result holds the whole batches drawn so far, ``interrupted`` is
        True and ``unfinished`` marks the sensors stopped short. Without
        ``stop``, Ctrl-C raises ``KeyboardInterrupt`` once the batch is done.
        """
        if component not in COMPONENTS:
            raise UserError(f"simulation.component: {component!r} is not one of {', '.join(COMPONENTS)}")
        if component == "indirect" and method in METHOD_FLAGS and not METHOD_FLAGS[method][3]:
            raise UserError(f"simulation.component: 'indirect' needs method path, not {method!r}")
        if any(s.spec.reader != "estimate" for s in self.sensors):
            raise ValueError("probe sensors are read by Engine.run_probes, not Engine.run")
        ids_all = np.arange(len(self.sensors)) if sensor_ids is None else np.asarray(sensor_ids, np.int64)
        if method == "analytic":
            return self._run_analytic(ids_all)
        if method == "exact":
            return self._run_exact(ids_all)
        if method not in METHOD_FLAGS:
            raise UserError(f"method {method!r} has no Monte Carlo kernel (expected one of {sorted(METHOD_FLAGS)})")
        n_s = len(self.sensors)
        params = self.trace_params(method, seed, max_depth, component)
        params.count_rays = 1 if count_rays else 0
        params.pick_light = LIGHT_PICK_MODES[self.light_pick_mode(method)]
        if params.pick_light:
            self._prepare_pick(method, seed, max_depth, component, ids_all)
        self.rays_traced = 0  # shadow and path rays, counted when count_rays
        stats = RunningStats(n_s)
        seconds = np.zeros(n_s)
        nonfinite = np.zeros(n_s, np.int64)
        adaptive = rel_error is not None
        cap = max_samples if adaptive else samples
        active = np.zeros(n_s, bool)
        active[ids_all] = True
        n_run = len(ids_all)
        want = np.full(n_s, min(samples, cap), np.int64)  # next batch per sensor
        if not adaptive:
            per = max(BLOCK, SAMPLES_PER_LAUNCH // max(n_run, 1))
            want = np.minimum(want, per)

        def step(ids, first, count):
            tb = time.perf_counter()
            sens, cnt, mean, m2, bad = self._launch(params, ids, first, count)
            dt = time.perf_counter() - tb
            stats.merge(sens, cnt, mean, m2)
            seconds[sens] += dt * cnt / cnt.sum()
            nonfinite[sens] += bad

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
            measure=lambda: (stats.mean, stats.stderr()), time_limit_s=time_limit_s, t_start=t0, report=report,
            stop=stop,
        )  # fmt: skip
        wall = time.perf_counter() - t0
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
        )

    # ------------------------------------------------------------ probes

    def _launch_passes(self, rec, params, n_pix: int, first_pass: int, n_passes: int):
        """Draw passes [first_pass, first_pass + n_passes) of every pixel of
        the probe ``rec``. Returns per-pixel (counts, means, m2s) of shape
        (P,), (P, 2Q), (P, 2Q) and the number of non-finite samples."""
        wp = warp()
        width = P.N_QUANTITIES * P.N_CHANNELS
        blocks = (n_passes + PASS_BLOCK - 1) // PASS_BLOCK
        counts_blk = np.minimum(PASS_BLOCK, n_passes - PASS_BLOCK * np.arange(blocks))
        pix_per_launch = max(1, THREADS_PER_LAUNCH // blocks)
        counts = np.full(n_pix, n_passes, np.int64)
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

                def run(offset: int, dim: int):
                    wp.launch(
                        self._KP.probe_kernel,
                        dim=dim,
                        inputs=[self._dev.rec, rec, params, 0, first_pass, n_passes, PASS_BLOCK, blocks, p0, offset],
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
        width = P.N_QUANTITIES * P.N_CHANNELS
        with wp.ScopedDevice(self.device):
            d_shift = wp.zeros((1, width), dtype=wp.float64)
            d_sum = wp.zeros((1, width), dtype=wp.float64)
            d_sq = wp.zeros((1, width), dtype=wp.float64)
            d_bad = wp.zeros(1, dtype=wp.int32)
            wp.launch(self._KP.probe_kernel, dim=1, inputs=[self._dev.rec, rec, params, 1, 0, 0, 1, 1, 0, 0],
                      outputs=[d_shift, d_sum, d_sq, d_bad])  # fmt: skip
            return d_sum.numpy()[0].reshape(P.N_QUANTITIES, P.N_CHANNELS)

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
            raise UserError(f"method {method!r} cannot read probes (use light, bsdf, mis, path or auto)")
        wp = warp()
        wp.load_module(self._KP, device=self.device)
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
            stats = RunningStats(n_pix, P.N_QUANTITIES * P.N_CHANNELS)
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
