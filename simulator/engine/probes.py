"""Light probes on the engine's device: lat-long maps and sphere integrals.

A probe estimates the radiance arriving at a point from every direction
(see :mod:`simulator.kernels.probe` for the estimator) and reports

- a lat-long map of incident radiance: each pixel the mean radiance over its
  solid angle, with its standard error;
- integrals over the sphere, each with its standard error: scalar irradiance
  (fluence rate) ∫L dω, the irradiance on the six axis-aligned faces
  ∫L·max(0, ±ω·axis) dω, the vector irradiance ∫L·ω dω and its direction,
  and the nine real spherical-harmonic coefficients ∫L·Y_lm dω (l ≤ 2).

Estimator. Every *pass* draws one direction in each pixel, uniform in
solid angle within it, so a pass gives every integral as the stratified sum
I_q = Σ_pixels Ω_p·f_q(ω_p)·L(ω_p). With n passes, pixel p's mean μ_pq of
f_q·L and its sample variance s²_pq, the estimate and its standard error are

    I_q = Σ_p Ω_p·μ_pq + D_q,     se(I_q) = √(Σ_p Ω_p²·s²_pq / n),

where D_q is the exact contribution of delta lights (point lights and
angle-0 distant lights: no direction sample can see them), added by
next-event estimation with a shadow ray when the method samples lights
(light, mis, path; method bsdf is blind to them, as for every sensor). The
map never shows a delta light: it holds what direction sampling sees.

Frame. Directions in the map follow the OpenEXR lat-long convention
(:mod:`simulator.io.latlong`) in the frame an *untransformed* DomeLight of the
same stage has: the world frame for a Z-up stage, the Y-up stage's axes for
a Y-up one. So the map can be given straight back to that stage as a
DomeLight's ``texture:file``. The integrals are in the world frame (Z up).

Only this module, :mod:`simulator.engine.driver` and ``simulator.kernels`` import
``warp``.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from simulator.errors import UserError
from simulator.scene.model import Sensor, SensorKind
from simulator.engine.stats import RunningStats, z_for_confidence

__all__ = [
    "FACE_NAMES",
    "SH_NAMES",
    "MIN_PASSES",
    "MAX_PROBE_PIXELS",
    "ProbeResult",
    "latlong_layout",
    "pixel_solid_angles",
    "probe_frame",
    "run_probes",
]

#: the six faces of the "cube" sensor, in integrand order
FACE_NAMES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")
#: real SH coefficients (l, m) in integrand order
SH_NAMES = ("0,0", "1,-1", "1,0", "1,1", "2,-2", "2,-1", "2,0", "2,1", "2,2")
#: fewest passes (directions per pixel) a probe draws: its per-pixel standard
#: errors come from the spread between passes
MIN_PASSES = 8
#: passes one kernel thread draws for one pixel
PASS_BLOCK = 16
#: kernel threads per launch: bounds the float64 sums held at once (~900 B each)
THREADS_PER_LAUNCH = 1 << 16
#: most pixels in a probe map (keep equal to simulator.config.loader.MAX_PROBE_PIXELS)
MAX_PROBE_PIXELS = 1 << 19

_Q = 22  # integrands per sample, see simulator.kernels.probe (19 reported + 3 for covariances)
_C = 2  # channels: radiometric, photometric


# --------------------------------------------------------------------------- layout (numpy)


def probe_frame(up_axis: str) -> np.ndarray:
    """World axes (columns) of the map frame: an untransformed DomeLight's frame.

    Parameters
    ----------
    up_axis : str
        The stage's ``upAxis``, ``"Z"`` or ``"Y"``.

    Returns
    -------
    ndarray, shape (3, 3)
        Identity for a Z-up stage; for a Y-up stage the stage's axes in the
        world frame, ``(x, y, z)_Yup -> (x, -z, y)``.
    """
    if str(up_axis).upper() == "Y":
        return np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    return np.eye(3)


def _lonlat(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """OpenEXR longitude and latitude of map-frame directions (x, y, z):
    d = (sin lon·cos lat, sin lat, cos lon·cos lat)."""
    return np.arctan2(d[..., 0], d[..., 2]), np.arcsin(np.clip(d[..., 1], -1.0, 1.0))


def latlong_layout(width: int, height: int) -> tuple[float, float, float, float]:
    """Longitude and latitude of pixel edges in the shared lat-long convention.

    Reads the convention off :func:`simulator.io.latlong.latlong_uv_to_direction`
    (u across the width, v down the height, both in [0, 1]) so that the
    probe's pixels are exactly the pixels a textured DomeLight reads.

    Returns
    -------
    lon0, dlon, lat0, dlat : float
        Pixel (i, j) spans longitudes ``[lon0 + i·dlon, lon0 + (i+1)·dlon]``
        and latitudes ``[lat0 + j·dlat, lat0 + (j+1)·dlat]``, radians.
    """
    from simulator.io.latlong import latlong_uv_to_direction

    def lonlat(u, v):
        return _lonlat(np.asarray(latlong_uv_to_direction(np.array([u, v], float)), float))

    # slopes from interior points (lon is continuous on (0, 1); its ±π seam is at the edges)
    (l25, _), (l75, _) = lonlat(0.25, 0.5), lonlat(0.75, 0.5)
    slope_lon = (l75 - l25) / 0.5
    lon0 = float(l25 - 0.25 * slope_lon)
    (_, b25), (_, b75) = lonlat(0.5, 0.25), lonlat(0.5, 0.75)
    slope_lat = (b75 - b25) / 0.5
    lat0 = float(b25 - 0.25 * slope_lat)
    if not (abs(abs(slope_lon) - 2 * math.pi) < 1e-9 and abs(abs(slope_lat) - math.pi) < 1e-9):
        raise AssertionError("simulator.io.latlong is not an equirectangular map over the whole sphere")
    return lon0, float(slope_lon) / width, lat0, float(slope_lat) / height


def pixel_solid_angles(width: int, height: int) -> np.ndarray:
    """Solid angle of every lat-long pixel, sr, shape (height, width).

    Ω = |Δlon|·|sin lat_b − sin lat_a| (:func:`simulator.io.latlong.texel_solid_angles`);
    the pixels tile the sphere (Σ = 4π).
    """
    from simulator.io.latlong import texel_solid_angles

    return np.repeat(texel_solid_angles(width, height)[:, None], width, axis=1)


# --------------------------------------------------------------------------- results


@dataclass
class ProbeResult:
    """One probe's estimates.

    Attributes
    ----------
    sensor : Sensor
    frame : ndarray, shape (3, 3)
        World axes (columns) of the map frame, see :func:`probe_frame`.
    radiance, radiance_stderr : ndarray, shape (H, W, 2)
        Mean radiance per pixel and its standard error: channel 0 W m⁻² sr⁻¹,
        channel 1 cd/m². Row 0 is the top of the map.
    solid_angle_sr : ndarray, shape (H, W)
    integrals, integrals_stderr : ndarray, shape (19, 2)
        The sphere integrals in integrand order (fluence, six faces, vector
        x/y/z, nine SH), W/m² (channel 0) and lx (channel 1).
    vector_cov : ndarray, shape (2, 3, 3)
        Covariance matrix of the vector irradiance estimate per channel,
        (W/m²)² and lx².
    delta : ndarray, shape (19, 2)
        The part of ``integrals`` that delta lights gave (exact).
    passes : int
        Directions drawn per pixel.
    samples : int
        Directions drawn in all (passes × pixels).
    seconds : float
    non_finite : int
        Samples that came out NaN or Inf (counted as 0).
    target_met : bool or None
        Adaptive runs: whether scalar irradiance reached the error target.
    """

    sensor: Sensor
    frame: np.ndarray
    radiance: np.ndarray
    radiance_stderr: np.ndarray
    solid_angle_sr: np.ndarray
    integrals: np.ndarray
    integrals_stderr: np.ndarray
    vector_cov: np.ndarray
    delta: np.ndarray
    passes: int
    samples: int
    seconds: float
    non_finite: int = 0
    target_met: bool | None = None
    warnings: list[str] = field(default_factory=list)

    @property
    def scalar_irradiance(self) -> tuple[np.ndarray, np.ndarray]:
        """(value, stderr), each shape (2,): W/m² and lx."""
        return self.integrals[0], self.integrals_stderr[0]

    @property
    def faces(self) -> tuple[np.ndarray, np.ndarray]:
        """(value, stderr), each shape (6, 2), faces in :data:`FACE_NAMES` order."""
        return self.integrals[1:7], self.integrals_stderr[1:7]

    @property
    def vector(self) -> tuple[np.ndarray, np.ndarray]:
        """Vector irradiance ∫L·ω dω: (value, stderr), each shape (3, 2)."""
        return self.integrals[7:10], self.integrals_stderr[7:10]

    @property
    def sh(self) -> tuple[np.ndarray, np.ndarray]:
        """SH coefficients: (value, stderr), each shape (9, 2), :data:`SH_NAMES` order."""
        return self.integrals[10:19], self.integrals_stderr[10:19]

    def mean_direction(self, channel: int = 0) -> tuple[np.ndarray, float]:
        """Unit mean direction of arrival and its angular standard error, degrees.

        The direction is m = v/|v| for the vector irradiance v. Its error is
        the delta-method RMS angle √(tr(P·Σ·P))/|v|, with Σ the covariance
        of v (:attr:`vector_cov`) and P = I − m·mᵀ the projection across m:
        the spread of v perpendicular to its direction. NaN where v = 0.
        """
        v = self.integrals[7:10, channel]
        norm = float(np.linalg.norm(v))
        if not norm > 0.0:
            return np.full(3, np.nan), math.nan
        m = v / norm
        p = np.eye(3) - np.outer(m, m)
        ang = math.sqrt(max(0.0, float(np.trace(p @ self.vector_cov[channel] @ p)))) / norm
        return m, math.degrees(ang)


# --------------------------------------------------------------------------- device runs


def _probe_rec(wp, K, sensor: Sensor, frame: np.ndarray, key: int):
    w, h = sensor.resolution
    lon0, dlon, lat0, dlat = latlong_layout(w, h)
    r = K.ProbeRec()
    r.position = wp.vec3(*map(float, sensor.position))
    r.ex = wp.vec3(*map(float, frame[:, 0]))
    r.ey = wp.vec3(*map(float, frame[:, 1]))
    r.ez = wp.vec3(*map(float, frame[:, 2]))
    r.width, r.height = int(w), int(h)
    r.lon0, r.dlon, r.lat0, r.dlat = lon0, dlon, lat0, dlat
    r.key = int(key)
    return r


def _stream_key(seed: int, sensor_index: int) -> int:
    """``sensor_stream_key`` of simulator.kernels.sampling, in numpy (same bits)."""

    def h(x: int) -> int:
        x &= 0xFFFFFFFF
        state = (x * 747796405 + 2891336453) & 0xFFFFFFFF
        word = (((state >> ((state >> 28) + 4)) ^ state) * 277803737) & 0xFFFFFFFF
        return ((word >> 22) ^ word) & 0xFFFFFFFF

    return h((seed & 0xFFFFFFFF) ^ h(sensor_index + 0x9E3779B9)) >> 1


def _launch_passes(engine, K, rec, params, n_pix: int, first_pass: int, n_passes: int):
    """Draw passes [first_pass, first_pass + n_passes) of every pixel.

    Returns per-pixel (counts, means, m2s) of shape (P,), (P, 38), (P, 38)
    and the number of non-finite samples."""
    from simulator.engine.driver import _warp

    wp = _warp()
    blocks = (n_passes + PASS_BLOCK - 1) // PASS_BLOCK
    counts_blk = np.minimum(PASS_BLOCK, n_passes - PASS_BLOCK * np.arange(blocks))
    pix_per_launch = max(1, THREADS_PER_LAUNCH // blocks)
    counts = np.full(n_pix, n_passes, np.int64)
    means = np.empty((n_pix, _Q * _C))
    m2s = np.empty((n_pix, _Q * _C))
    bad_total = 0
    with wp.ScopedDevice(engine.device):
        for p0 in range(0, n_pix, pix_per_launch):
            p1 = min(n_pix, p0 + pix_per_launch)
            n = (p1 - p0) * blocks
            shift = wp.empty((n, _Q * _C), dtype=wp.float64)
            s1 = wp.empty((n, _Q * _C), dtype=wp.float64)
            s2 = wp.empty((n, _Q * _C), dtype=wp.float64)
            bad = wp.empty(n, dtype=wp.int32)

            def run(offset: int, dim: int):
                wp.launch(
                    K.probe_kernel,
                    dim=dim,
                    inputs=[engine._scene_rec, rec, params, 0, first_pass, n_passes, PASS_BLOCK, blocks, p0, offset],
                    outputs=[shift, s1, s2, bad],
                )

            _split(engine.threads, run, n)
            wp.synchronize_device()
            block_pix = np.repeat(np.arange(p0, p1), blocks)
            block_cnt = np.tile(counts_blk, p1 - p0)
            _, _, m, v = RunningStats.reduce_blocks(block_pix, block_cnt, shift.numpy(), s1.numpy(), s2.numpy())
            means[p0:p1] = m
            m2s[p0:p1] = v
            bad_total += int(bad.numpy().sum())
    return counts, means, m2s, bad_total


def _split(threads: int, run, n: int) -> None:
    """Run ``run(offset, dim)`` over n kernel threads, split over ``threads``
    CPU workers (Warp's CPU launches release the GIL; 1 on a GPU)."""
    parts = min(threads, n)
    if parts <= 1:
        run(0, n)
        return
    cuts = np.linspace(0, n, parts + 1).astype(int)
    workers = [threading.Thread(target=run, args=(int(a), int(b - a))) for a, b in zip(cuts[:-1], cuts[1:])]
    for w in workers:
        w.start()
    for w in workers:
        w.join()


def run_probes(
    engine,
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
) -> list[ProbeResult]:
    """Estimate every probe with ``method`` (light, bsdf, mis or path).

    Parameters
    ----------
    engine : simulator.engine.driver.Engine
        The scene, resident on its device.
    probes : list of Sensor
        Sensors of kind PROBE.
    samples : int
        Directions per probe, rounded up to whole passes (one direction per
        pixel each), at least :data:`MIN_PASSES` passes. In adaptive mode
        the first batch.
    seed : int
        Run seed.
    stream_ids : list of int, optional
        Random-stream index of each probe (its index among all the run's
        sensors); default ``range(len(probes))``.
    rel_error, abs_error, max_samples, time_limit_s
        Adaptive stopping as for :meth:`simulator.engine.driver.Engine.run`, applied
        to the probe's scalar irradiance (both channels); ``max_samples``
        caps the directions per probe. ``time_limit_s`` counts from the start
        of this call; a probe past it still finishes its current batch (at
        least :data:`MIN_PASSES` passes).
    max_depth, component
        As for :meth:`simulator.engine.driver.Engine.run`.
    progress : callable, optional
        Receives :class:`simulator.engine.driver.Progress` after each batch.

    Returns
    -------
    list of ProbeResult
    """
    from simulator.engine.driver import METHOD_FLAGS, Progress

    if method not in METHOD_FLAGS:
        raise UserError(f"method {method!r} cannot read probes (use light, bsdf, mis, path or auto)")
    from simulator.engine.driver import _warp
    from simulator.kernels import probe as K

    wp = _warp()
    wp.load_module(K, device=engine.device)
    params = engine._params(method, seed, max_depth, component)
    stream_ids = list(range(len(probes))) if stream_ids is None else list(stream_ids)
    frame = probe_frame(engine.scene.up_axis)
    adaptive = rel_error is not None
    z = z_for_confidence(confidence)  # half-width of the confidence interval, in standard errors
    out: list[ProbeResult] = []
    t_start = time.perf_counter()
    total_samples = 0
    for k, s in enumerate(probes):
        if s.kind != SensorKind.PROBE:
            raise ValueError(f"{s.name}: not a probe")
        w, h = s.resolution
        n_pix = int(w) * int(h)
        if n_pix < 1 or n_pix > MAX_PROBE_PIXELS:
            raise UserError(f"{s.source}: probe {s.name!r}: resolution {w} x {h} must have 1 to {MAX_PROBE_PIXELS} pixels")
        t0 = time.perf_counter()
        rec = _probe_rec(wp, K, s, frame, _stream_key(seed, stream_ids[k]))
        omega = pixel_solid_angles(w, h).reshape(-1)
        # delta lights: exact, once
        with wp.ScopedDevice(engine.device):
            d_shift = wp.zeros((1, _Q * _C), dtype=wp.float64)
            d_sum = wp.zeros((1, _Q * _C), dtype=wp.float64)
            d_sq = wp.zeros((1, _Q * _C), dtype=wp.float64)
            d_bad = wp.zeros(1, dtype=wp.int32)
            wp.launch(K.probe_kernel, dim=1, inputs=[engine._scene_rec, rec, params, 1, 0, 0, 1, 1, 0, 0],
                      outputs=[d_shift, d_sum, d_sq, d_bad])  # fmt: skip
            delta = d_sum.numpy()[0].reshape(_Q, _C)
        stats = RunningStats(n_pix, _Q * _C)
        first_batch = max(MIN_PASSES, -(-samples // n_pix))
        cap = max(MIN_PASSES, -(-max_samples // n_pix)) if adaptive else first_batch
        want = min(first_batch, cap)
        bad = 0
        met = False
        while True:
            count = min(want, cap - int(stats.count[0]))
            counts, means, m2s, b = _launch_passes(engine, K, rec, params, n_pix, int(stats.count[0]), count)
            stats.merge(np.arange(n_pix), counts, means, m2s)
            bad += b
            done = int(stats.count[0]) >= cap
            if adaptive:
                val, se = _integrals(stats, omega, delta)
                target = np.maximum(rel_error * np.abs(val[0]), abs_error)
                met = bool(np.all(z * se[0] <= target))
                done |= met
                if not done:
                    with np.errstate(divide="ignore", invalid="ignore"):
                        ratio = float(np.max((z * se[0] / np.maximum(target, 1e-300)) ** 2))
                    n = int(stats.count[0])
                    need = math.ceil(n * (ratio if math.isfinite(ratio) else 2.0) * 1.1) - n
                    want = int(np.clip(need, PASS_BLOCK, max(n, PASS_BLOCK)))
            elapsed = time.perf_counter() - t_start
            if time_limit_s is not None and elapsed >= time_limit_s:
                done = True
            if progress is not None:
                progress(Progress(k + int(done), len(probes), total_samples + int(stats.count.sum()), elapsed, None))
            if done:
                break
        passes = int(stats.count[0])
        total_samples += passes * n_pix
        val, se = _integrals(stats, omega, delta)
        # Cov(v_i, v_j) = (Var(v_i + v_j) − Var v_i − Var v_j)/2 from the pair sums
        var = se**2
        cov = np.zeros((_C, 3, 3))
        for a in range(3):
            cov[:, a, a] = var[7 + a]
        for q, (a, b) in zip((19, 20, 21), ((0, 1), (0, 2), (1, 2))):
            cov[:, a, b] = cov[:, b, a] = 0.5 * (var[q] - var[7 + a] - var[7 + b])
        mean = stats.mean.reshape(n_pix, _Q, _C)[:, 0, :]
        pse = stats.stderr().reshape(n_pix, _Q, _C)[:, 0, :]
        warnings = []
        if bad:
            warnings.append(f"probe {s.name}: {bad} non-finite samples were counted as 0")
        out.append(
            ProbeResult(
                sensor=s,
                frame=frame,
                radiance=mean.reshape(h, w, _C).copy(),
                radiance_stderr=pse.reshape(h, w, _C).copy(),
                solid_angle_sr=omega.reshape(h, w),
                integrals=val[:19],
                integrals_stderr=se[:19],
                vector_cov=cov,
                delta=delta[:19],
                passes=passes,
                samples=passes * n_pix,
                seconds=time.perf_counter() - t0,
                non_finite=bad,
                target_met=met if adaptive else None,
                warnings=warnings,
            )
        )
    return out


def _integrals(stats: RunningStats, omega: np.ndarray, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Stratified sphere integrals and their standard errors, each (22, 2)."""
    n = stats.count.astype(np.float64)[:, None]
    mean = stats.mean
    with np.errstate(invalid="ignore", divide="ignore"):
        var_mean = np.where(n > 1, stats.m2 / (n * (n - 1.0)), np.inf)
    val = (omega[:, None] * mean).sum(axis=0).reshape(_Q, _C) + delta
    se = np.sqrt((omega[:, None] ** 2 * var_mean).sum(axis=0)).reshape(_Q, _C)
    return val, se
