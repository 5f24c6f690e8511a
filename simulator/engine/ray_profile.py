"""Ray queries alone on an engine's scene, timed (``benchmarks/profile_office.py``).

The host draws the rays; :func:`cast` sends them through
:mod:`simulator.kernels.ray_replay` in one launch on one worker and returns
where they stop, so a profile can follow paths bounce by bounce, and
:func:`time_queries` the CPU seconds a batch of rays takes.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from .device import warp

__all__ = ["Hits", "cast", "time_queries", "time_light_samples"]


@dataclass
class Hits:
    """Where each ray of a batch stopped (arrays of length n)."""

    t_m: np.ndarray  # distance to the first surface (RAY_INF: none)
    face: np.ndarray  # its triangle, −1: none
    ng: np.ndarray  # (n, 3) its unit geometric normal


def _arrays(wp, device, origin, direction, t_max):
    o = wp.array(np.ascontiguousarray(origin, np.float32), dtype=wp.vec3, device=device)
    d = wp.array(np.ascontiguousarray(direction, np.float32), dtype=wp.vec3, device=device)
    t = wp.array(np.ascontiguousarray(t_max, np.float32), dtype=float, device=device)
    return o, d, t


def cast(engine, origin: np.ndarray, direction: np.ndarray, t_max: np.ndarray) -> Hits:
    """The first surface each ray (origin (n, 3) m, unit direction (n, 3)) meets before ``t_max`` (n,) m,
    by the estimator's own query (:func:`simulator.kernels.rays.first_hit`)."""
    wp = warp()
    from simulator.kernels import ray_replay as R

    rec = engine.scene_rec
    n = len(origin)
    with wp.ScopedDevice(engine.device):
        o, d, t = _arrays(wp, engine.device, origin, direction, t_max)
        out_t = wp.empty(n, dtype=float)
        out_f = wp.empty(n, dtype=wp.int32)
        out_n = wp.empty(n, dtype=wp.vec3)
        wp.launch(R.closest_hit_kernel, dim=n, inputs=[rec, o, d, t], outputs=[out_t, out_f, out_n])
        wp.synchronize_device()
        return Hits(out_t.numpy(), out_f.numpy(), out_n.numpy())


def time_queries(engine, origin: np.ndarray, direction: np.ndarray, t_max: np.ndarray,
                 repeats: int = 3) -> tuple[float, float]:  # fmt: skip
    """``(first_hit_s, bvh_s)``: the least CPU seconds (``time.process_time``, one worker) of ``repeats``
    launches casting every ray by :func:`~simulator.kernels.rays.first_hit`, and by Warp's BVH query
    alone. The kernels are loaded before the first timing."""
    wp = warp()
    from simulator.kernels import ray_replay as R

    rec = engine.scene_rec
    n = len(origin)
    wp.load_module(R, device=engine.device)
    with wp.ScopedDevice(engine.device):
        o, d, t = _arrays(wp, engine.device, origin, direction, t_max)
        out_t = wp.empty(n, dtype=float)
        out_f = wp.empty(n, dtype=wp.int32)
        out_n = wp.empty(n, dtype=wp.vec3)
        best = [np.inf, np.inf]
        for _ in range(repeats):
            c0 = time.process_time()
            wp.launch(R.closest_hit_kernel, dim=n, inputs=[rec, o, d, t], outputs=[out_t, out_f, out_n])
            wp.synchronize_device()
            best[0] = min(best[0], time.process_time() - c0)
            c0 = time.process_time()
            wp.launch(R.bvh_only_kernel, dim=n, inputs=[rec, o, d, t], outputs=[out_f])
            wp.synchronize_device()
            best[1] = min(best[1], time.process_time() - c0)
    return best[0], best[1]


def time_light_samples(engine, point: np.ndarray, normal: np.ndarray, repeats: int = 3) -> list[float]:
    """Per light record, the least CPU seconds of ``repeats`` launches drawing one sample of it
    (:func:`~simulator.kernels.lights.sample_light`, no shadow ray) at each receiver (point (n, 3) m,
    unit normal (n, 3))."""
    wp = warp()
    from simulator.kernels import ray_replay as R

    rec = engine.scene_rec
    n = len(point)
    wp.load_module(R, device=engine.device)
    out = []
    with wp.ScopedDevice(engine.device):
        p = wp.array(np.ascontiguousarray(point, np.float32), dtype=wp.vec3)
        nn = wp.array(np.ascontiguousarray(normal, np.float32), dtype=wp.vec3)
        val = wp.empty(n, dtype=wp.vec2)
        for li in range(int(rec.n_lights)):
            best = np.inf
            for k in range(repeats):
                c0 = time.process_time()
                wp.launch(R.light_sample_kernel, dim=n, inputs=[rec, p, nn, li, k], outputs=[val])
                wp.synchronize_device()
                best = min(best, time.process_time() - c0)
            out.append(best)
    return out
