"""The engine: uploads a scene to a Warp device once, then launches sample batches.

Per batch it lays out thread blocks (one sensor, ``BLOCK`` samples each),
splits a CPU launch over worker threads (Warp's CPU launches release the
GIL), merges the blocks' shifted sums into float64 running statistics, and
stops each sensor when it has its samples or, in adaptive mode, when the
half-width of its 95% confidence interval is under the target.

Only this module and ``simulator.kernels`` import ``warp``.
"""

from __future__ import annotations

import contextlib
import math
import os
import sys
import threading
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from simulator.errors import UserError
from simulator.scene.model import Light, LightKind, Scene, Sensor, SensorKind
from simulator.engine.stats import RunningStats, z_for_confidence

__all__ = ["COMPONENTS", "METHOD_FLAGS", "cuda_available", "warp_version", "Engine", "EngineResult", "Progress", "resolve_device"]

#: samples one kernel thread draws for one sensor (a block)
BLOCK = 32
#: samples per launch in a batch: big enough to amortise the launch, small
#: enough that the progress bar and time limit are checked often
SAMPLES_PER_LAUNCH = 1 << 18

#: which light a reading counts
COMPONENTS = ("total", "direct", "indirect")

#: method → (next-event estimation, cosine directions, MIS, interreflection)
METHOD_FLAGS = {
    "light": (1, 0, 0, False),
    "bsdf": (0, 1, 0, False),
    "mis": (1, 1, 1, False),
    "path": (1, 1, 1, True),
}

_wp = None


@contextlib.contextmanager
def _stderr_silenced():
    """Silence native writes to fd 2 (Warp's loader notes that no CUDA driver
    exists are noise on a CPU machine; real failures still raise)."""
    sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


def _warp():
    """Import and initialise Warp once, quietly."""
    global _wp
    if _wp is None:
        import warp as wp

        wp.config.quiet = True
        wp.config.log_level = 30  # warnings and errors only: no banner, no per-module load lines
        with _stderr_silenced():
            wp.init()
        _wp = wp
    return _wp


def warp_version() -> str:
    """The Warp version in use (for run records)."""
    return _warp().config.version


def cuda_available() -> bool:
    """Whether Warp finds a CUDA device on this machine."""
    return _warp().get_cuda_device_count() > 0


def resolve_device(requested: str) -> str:
    """Warp device name for ``cpu``, ``cuda`` or ``auto`` (CUDA when present)."""
    wp = _warp()
    has_cuda = wp.get_cuda_device_count() > 0
    if requested == "auto":
        return "cuda:0" if has_cuda else "cpu"
    if requested == "cuda":
        if not has_cuda:
            raise UserError("--device cuda: no CUDA device is available on this machine (use cpu or auto)")
        return "cuda:0"
    if requested == "cpu":
        return "cpu"
    raise UserError(f"--device: unknown device {requested!r} (expected cpu, cuda or auto)")


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


class Engine:
    """A scene and its sensors, resident on one Warp device.

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
    device : str
        ``cpu``, ``cuda`` or ``auto``.
    threads : int
        CPU worker threads; 0 = all cores.
    """

    def __init__(self, scene: Scene, sensors: list[Sensor], device: str = "cpu", threads: int = 0):
        wp = _warp()
        from simulator.kernels import estimators as K

        self._K = K
        self.device = resolve_device(device)
        self.scene = scene
        self.sensors = sensors
        self.threads = threads if threads > 0 else (os.cpu_count() or 1)
        if self.device != "cpu":
            self.threads = 1
        self.warnings: list[str] = []
        # compile (or load from the kernel cache) before worker threads launch
        wp.load_module(K, device=self.device)
        with wp.ScopedDevice(self.device):
            self._scene_rec = self._upload_scene(wp, K)
            self._sensor_arr = self._upload_sensors(wp, K)

    # ------------------------------------------------------------ upload

    def _upload_scene(self, wp, K):
        g = self.scene.geometry
        rec = K.SceneRec()
        # Ray origins are pushed off surfaces by 1e-5 × max(1 m, |p|∞) (see
        # kernels.estimators.offset_length): 170× float32 resolution, 10 µm at
        # room scale.
        rec.eps = 1.0e-5
        rec.ray_counts = wp.zeros(1, dtype=wp.int32)
        rec.light_mask = wp.ones(max(1, len(self.sensors) * (len(self.scene.lights) + 1)), dtype=wp.int32)
        n_tri = g.n_triangles
        pts = g.points.astype(np.float32) if n_tri else np.zeros((3, 3), np.float32)
        tris = g.triangles.astype(np.int32) if n_tri else np.array([[0, 1, 2]], np.int32)
        self._points = wp.array(pts, dtype=wp.vec3)
        self._tris = wp.array(tris.reshape(-1), dtype=wp.int32)
        self._mesh = wp.Mesh(points=self._points, indices=self._tris) if n_tri else None
        rec.mesh = self._mesh.id if n_tri else wp.uint64(0)
        rec.has_mesh = 1 if n_tri else 0
        rec.points = self._points
        rec.tris = self._tris

        def arr(a, dtype):
            return wp.array(a, dtype=dtype) if len(a) else wp.zeros(1, dtype=dtype)

        albedo = g.albedo.astype(np.float32) if n_tri else np.zeros(1, np.float32)
        emission = g.emission.astype(np.float32) if n_tri else np.zeros((1, 2), np.float32)
        two_sided = g.two_sided.astype(np.int32) if n_tri else np.zeros(1, np.int32)
        rec.albedo = arr(albedo, float)
        rec.emission = arr(emission, wp.vec2)
        rec.two_sided = arr(two_sided, wp.int32)

        # Emissive triangles: picked with probability ∝ emitted power
        # (radiance × area × sides), the best choice when all are visible.
        emit_ids = np.flatnonzero(np.any(emission > 0, axis=1)) if n_tri else np.zeros(0, np.int64)
        prob = np.zeros(max(n_tri, 1), np.float64)
        self._map_arrays = []  # textured domes' device arrays, referenced only by pointer from LightRec
        lights = [self._light_rec(K, l) for l in self.scene.lights]
        self.emissive_light = -1
        if len(emit_ids):
            p = g.points[g.triangles[emit_ids]]
            area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
            power = area * g.emission[emit_ids, 0] * np.where(g.two_sided[emit_ids], 2.0, 1.0)
            if power.sum() <= 0:
                power = area * g.emission[emit_ids, 1]
            prob[emit_ids] = power / power.sum()
            cdf = np.cumsum(prob[emit_ids])
            cdf /= cdf[-1]
            rec.emit_tris = wp.array(emit_ids.astype(np.int32), dtype=wp.int32)
            rec.emit_cdf = wp.array(cdf.astype(np.float32), dtype=float)
            em = K.LightRec()
            em.kind = K.EMISSIVE  # emissive geometry: one light record for all emitting triangles
            lights.append(em)
            self.emissive_light = len(lights) - 1
        else:
            rec.emit_tris = wp.zeros(0, dtype=wp.int32)
            rec.emit_cdf = wp.zeros(1, dtype=float)
        rec.emit_prob = wp.array(prob.astype(np.float32), dtype=float)
        self._lights = wp.array(lights, dtype=K.LightRec) if lights else wp.zeros(1, dtype=K.LightRec)
        rec.lights = self._lights
        rec.n_lights = len(lights)
        self._keep = (rec.albedo, rec.emission, rec.two_sided, rec.emit_tris, rec.emit_cdf, rec.emit_prob)
        return rec

    def _light_rec(self, K, l: Light):
        import warp as wp

        r = K.LightRec()
        r.kind = int(l.kind)
        r.position = wp.vec3(*map(float, l.position))
        f = np.asarray(l.frame, float)
        r.ex = wp.vec3(*map(float, f[:, 0]))
        r.ey = wp.vec3(*map(float, f[:, 1]))
        r.ez = wp.vec3(*map(float, f[:, 2]))
        r.emission = wp.vec2(float(l.emission[0]), float(l.emission[1]))
        r.width, r.height, r.radius = float(l.width), float(l.height), float(l.radius)
        # a distant light's cone: 1 − cosθ as 2·sin²(θ/2), without cancellation; 0 = delta
        r.one_minus_cos = 2.0 * math.sin(0.5 * l.half_angle) ** 2 if l.kind == LightKind.DISTANT else 0.0
        r.area = {
            LightKind.RECT: l.width * l.height,
            LightKind.DISK: math.pi * l.radius**2,
            LightKind.SPHERE: 4.0 * math.pi * l.radius**2,
            LightKind.CYLINDER: 2.0 * math.pi * l.radius * l.length,
        }.get(l.kind, 0.0)
        r.length = float(l.length)
        if l.kind == LightKind.DOME and l.texture_map is not None:
            self._upload_dome_map(wp, r, l.texture_map)
        if l.shaping is not None:
            self._upload_shaping(wp, r, l.shaping)
        return r

    def _upload_shaping(self, wp, r, sh) -> None:
        """UsdLuxShapingAPI on the record; an IES table goes in ``map`` (rows θ, columns φ)."""
        r.shaped = 1
        r.shaping = wp.vec4(float(sh.cone_angle_rad), float(sh.cone_softness), float(sh.focus), float(sh.focus_tint))
        if sh.ies is not None:
            _, _, table = sh.ies.regular_table()
            t = np.ascontiguousarray(table.T, np.float32)  # (θ rows, φ columns)
            r.map_h, r.map_w = int(t.shape[0]), int(t.shape[1])
            r.map = wp.array(t.ravel(), dtype=float)
            r.ies_scale = float(sh.ies_scale)
            self._map_arrays.append(r.map)

    def _upload_dome_map(self, wp, r, grey: np.ndarray) -> None:
        """Put a dome's lat-long map and its sampling CDFs on the light record.

        Texels are importance-sampled ∝ value × sinθ (simulator.io.latlong); the
        arrays are kept alive here because the device record holds only
        their pointers. The CDFs are float32: a texel whose share of its row
        (or a row whose share of the map) is below float32 resolution (~6e-8)
        may never be drawn by light sampling; bsdf and mis still see it.
        """
        from simulator.io import latlong

        grey = np.asarray(grey, np.float64)
        h, w = grey.shape
        marg, cond = latlong.build_distribution(latlong.sampling_weights(grey))
        r.has_map, r.map_w, r.map_h = 1, int(w), int(h)
        r.map = wp.array(grey.astype(np.float32).ravel(), dtype=float)
        r.map_marg = wp.array(marg.astype(np.float32), dtype=float)
        r.map_cond = wp.array(cond.astype(np.float32).ravel(), dtype=float)
        self._map_arrays += [r.map, r.map_marg, r.map_cond]

    def _upload_sensors(self, wp, K):
        recs = []
        for s in self.sensors:
            r = K.SensorRec()
            r.kind = int(s.kind)
            r.position = wp.vec3(*map(float, s.position))
            r.normal = wp.vec3(*map(float, s.normal))
            if s.kind == SensorKind.PATCH:
                right = np.cross(s.up, s.normal)
                right /= np.linalg.norm(right)
                r.right = wp.vec3(*map(float, right))
                r.up = wp.vec3(*map(float, s.up))
                r.width, r.height = float(s.size[0]), float(s.size[1])
            r.one_minus_cos = 2.0 * math.sin(0.5 * s.half_angle) ** 2 if s.kind == SensorKind.RADIANCE else 0.0
            recs.append(r)
        return wp.array(recs, dtype=K.SensorRec) if recs else wp.zeros(1, dtype=K.SensorRec)

    # ------------------------------------------------------------ launches

    def _params(self, method: str, seed: int, max_depth: int, component: str):
        K = self._K
        nee, bsdf, mis, bounces = METHOD_FLAGS[method]
        p = K.TraceParams()
        p.nee, p.bsdf, p.mis = nee, bsdf, mis
        p.bounces = max_depth if bounces and component != "direct" else 0
        p.skip_direct = 1 if component == "indirect" else 0
        p.emissive_light = self.emissive_light
        p.seed = int(seed) & 0x7FFFFFFF
        p.count_rays = 0
        p.thread = 0
        p.mask_row = -1
        return p

    def set_light_mask(self, mask: np.ndarray) -> None:
        """Lights to skip per sensor at its first vertex: ``mask`` (S, L) over
        the scene's lights, 0 = wholly behind the sensor (see plan.lights_behind)."""
        wp = _warp()
        n_l = int(self._scene_rec.n_lights)
        full = np.ones((len(self.sensors), n_l), np.int32)
        full[:, : mask.shape[1]] = mask
        if getattr(self, "_light_mask", None) is not None and np.array_equal(self._light_mask, full):
            return  # already on the device: a plan run again (adaptive runs, charts) uploads nothing
        self._light_mask = full
        with wp.ScopedDevice(self.device):
            self._scene_rec.light_mask = wp.array(full.reshape(-1) if full.size else np.ones(1, np.int32), dtype=wp.int32)

    def _launch(self, params, sensor_ids: np.ndarray, first: np.ndarray, count: np.ndarray):
        """Draw count[i] samples of sensor_ids[i], starting at sample first[i].

        Returns (sensors, counts, means, m2s, non_finite) for the batch."""
        wp = _warp()
        K = self._K
        nblk = (count + BLOCK - 1) // BLOCK
        t_sensor = np.repeat(sensor_ids, nblk).astype(np.int32)
        starts = np.repeat(np.cumsum(nblk) - nblk, nblk)
        within = np.arange(len(t_sensor)) - starts
        t_first = (np.repeat(first, nblk) + within * BLOCK).astype(np.int32)
        t_count = np.minimum(BLOCK, np.repeat(first + count, nblk) - t_first).astype(np.int32)
        n = len(t_sensor)
        with wp.ScopedDevice(self.device):
            a_sensor = wp.array(t_sensor, dtype=wp.int32)
            a_first = wp.array(t_first, dtype=wp.int32)
            a_count = wp.array(t_count, dtype=wp.int32)
            if params.count_rays:
                self._scene_rec.ray_counts = wp.zeros(n, dtype=wp.int32)
            shift = wp.empty(n, dtype=wp.vec2d)
            s1 = wp.empty(n, dtype=wp.vec2d)
            s2 = wp.empty(n, dtype=wp.vec2d)
            bad = wp.empty(n, dtype=wp.int32)

            def run(offset: int, dim: int):
                wp.launch(
                    K.estimate_kernel,
                    dim=dim,
                    inputs=[self._scene_rec, self._sensor_arr, params, a_sensor, a_first, a_count, offset],
                    outputs=[shift, s1, s2, bad],
                )

            parts = min(self.threads, n)
            if parts <= 1:
                run(0, n)
            else:
                cuts = np.linspace(0, n, parts + 1).astype(int)
                workers = [
                    threading.Thread(target=run, args=(int(a), int(b - a))) for a, b in zip(cuts[:-1], cuts[1:])
                ]
                for w in workers:
                    w.start()
                for w in workers:
                    w.join()
            wp.synchronize_device()
            out = RunningStats.reduce_blocks(t_sensor, t_count, shift.numpy(), s1.numpy(), s2.numpy())
            if params.count_rays:
                self.rays_traced += int(self._scene_rec.ray_counts.numpy().sum())
            nonfinite = np.add.reduceat(bad.numpy(), np.flatnonzero(np.r_[True, t_sensor[1:] != t_sensor[:-1]]))
        return (*out, nonfinite)

    # ------------------------------------------------------------ runs

    def run_probes(self, probes: list[Sensor], method: str, **kwargs) -> list:
        """Lat-long maps and sphere integrals of PROBE sensors (which
        :meth:`run` does not read) on this engine's scene and device; see
        :func:`simulator.engine.probes.run_probes` for the arguments and the
        estimator. Returns a list of ``ProbeResult``."""
        from simulator.engine.probes import run_probes

        return run_probes(self, probes, method, **kwargs)

    def _run_analytic(self, sensor_ids: np.ndarray) -> EngineResult:
        """Closed-form readings (the caller has checked they apply): exact up
        to float32 rounding, so the standard error is 0 and no samples are drawn."""
        wp = _warp()
        n_s = len(self.sensors)
        t0 = time.perf_counter()
        mean = np.zeros((n_s, 2))
        with wp.ScopedDevice(self.device):
            ids = wp.array(sensor_ids.astype(np.int32), dtype=wp.int32)
            out = wp.empty(len(sensor_ids), dtype=wp.vec2d)
            if len(sensor_ids):
                wp.launch(self._K.analytic_kernel, dim=len(sensor_ids), inputs=[self._scene_rec, self._sensor_arr, ids], outputs=[out])
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
    ) -> EngineResult:
        """Estimate every sensor with ``method`` (light, bsdf, mis or path).

        Fixed budget (``rel_error`` None): ``samples`` per sensor. Adaptive:
        ``samples`` is the first batch; a sensor stops when
        1.96·stderr ≤ max(rel_error·|mean|, abs_error) in both channels, or at
        ``max_samples``; all stop at ``time_limit_s``.

        ``component``: ``total``; ``direct`` (light straight from emitters,
        and for a radiance meter its first surface's reflection of it); or
        ``indirect`` (the rest: light that has been reflected on the way).
        """
        if component not in COMPONENTS:
            raise UserError(f"simulation.component: {component!r} is not one of {', '.join(COMPONENTS)}")
        if component == "indirect" and not METHOD_FLAGS[method][3]:
            raise UserError(f"simulation.component: 'indirect' needs method path, not {method!r}")
        if any(s.kind == SensorKind.PROBE for s in self.sensors):
            raise ValueError("probe sensors are read by Engine.run_probes, not Engine.run")
        ids_all = np.arange(len(self.sensors)) if sensor_ids is None else np.asarray(sensor_ids, np.int64)
        if method == "analytic":
            return self._run_analytic(ids_all)
        if method not in METHOD_FLAGS:
            raise UserError(f"method {method!r} has no Monte Carlo kernel (expected one of {sorted(METHOD_FLAGS)})")
        n_s = len(self.sensors)
        params = self._params(method, seed, max_depth, component)
        params.count_rays = 1 if count_rays else 0
        self.rays_traced = 0  # shadow and path rays, counted when count_rays
        stats = RunningStats(n_s)
        seconds = np.zeros(n_s)
        nonfinite = np.zeros(n_s, np.int64)
        adaptive = rel_error is not None
        z = z_for_confidence(confidence)  # half-width of the confidence interval, in standard errors
        cap = max_samples if adaptive else samples
        active = np.zeros(n_s, bool)
        active[ids_all] = True
        n_run = len(ids_all)
        met = np.zeros(n_s, bool)
        want = np.full(n_s, min(samples, cap), np.int64)  # next batch per sensor
        if not adaptive:
            per = max(BLOCK, SAMPLES_PER_LAUNCH // max(n_run, 1))
            want = np.minimum(want, per)
        t0 = time.perf_counter()
        while active.any():
            ids = np.flatnonzero(active)
            first = stats.count[ids]
            count = np.minimum(want[ids], cap - first)
            tb = time.perf_counter()
            sens, cnt, mean, m2, bad = self._launch(params, ids, first, count)
            dt = time.perf_counter() - tb
            stats.merge(sens, cnt, mean, m2)
            seconds[sens] += dt * cnt / cnt.sum()
            nonfinite[sens] += bad
            done = stats.count >= cap
            if adaptive:
                se = stats.stderr()
                target = np.maximum(rel_error * np.abs(stats.mean), abs_error)
                ok = np.all(z * se <= target, axis=1)
                met |= ok & active
                done |= ok
                # next batch: enough to reach the target if the variance holds,
                # at most doubling, at least one block
                with np.errstate(divide="ignore", invalid="ignore"):
                    ratio = np.max((z * se / np.maximum(target, 1e-300)) ** 2, axis=1)
                need = np.ceil(stats.count * np.nan_to_num(ratio, nan=2.0, posinf=2.0) * 1.1) - stats.count
                want = np.clip(need, BLOCK, np.maximum(stats.count, BLOCK)).astype(np.int64)
            active &= ~done
            elapsed = time.perf_counter() - t0
            if time_limit_s is not None and elapsed >= time_limit_s:
                active[:] = False
            if progress is not None:
                done_n = n_run - int(active.sum())
                frac = stats.count.sum() / max(1, cap * n_run) if not adaptive else done_n / max(n_run, 1)
                eta = elapsed / frac * (1 - frac) if frac > 0 and active.any() else 0.0
                progress(Progress(done_n, n_run, int(stats.count.sum()), elapsed, eta))
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
        )
