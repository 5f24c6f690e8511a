"""Closed-form readings on the host: a run read wholly in closed form never imports Warp.

The ``analytic`` estimator's formulas (the kernels' :mod:`simulator.kernels.closed_forms` and
each light kind's ``analytic`` hook) in float64 numpy, for irradiance sensors under the light
kinds whose closed form needs nothing but the light's own record: point (unshaped), sphere, rect,
disk (wholly above the horizon, as the planner checks), distant (delta or a cone), uniform dome and
emissive triangles. Where a run has anything else (a shaped light, a textured dome, a patch or a
cylindrical sensor) :func:`host_analytic` returns None and the kernel reads it. Being float64
throughout (the kernels read float32 records), the readings differ from the kernel's by float32
rounding of the inputs (~1e-7 of a reading).

Formulas (docs/REFERENCES.md §Point source, §Uniform sphere, §Lambert's polygon formula,
§Uniform disk and §Uniform environment):

- point: E = I·cosξ/d²;
- sphere of angular radius σ (a distant light of half-angle σ the same at infinity), centre at θ
  from n: wholly above the horizon E/L = π·sin²σ·cosθ; straddling, with x = √(1/sin²σ − 1),
  y = −x·cotθ: E/L = (cosθ·acos y − x·sinθ·√(1 − y²))·sin²σ + atan(sinθ·√(1 − y²)/x);
- a polygon clipped to the receiver's hemisphere: Lambert's contour formula;
- a disk: ½·|n·∮(r × dr)/|r|²| by the periodic trapezoid rule on 256 nodes;
- a uniform dome: π·L (the whole sky, as the kernel's).
"""

from __future__ import annotations

import numpy as np

from simulator.scene.model import LightKind, SensorKind

__all__ = ["HOST_KINDS", "host_analytic"]

#: light kinds read here (shaped lights and textured domes go to the kernel)
HOST_KINDS = frozenset({LightKind.POINT, LightKind.SPHERE, LightKind.RECT, LightKind.DISK, LightKind.DISTANT,
                        LightKind.DOME})  # fmt: skip
#: trapezoid nodes around a disk's rim (the kernel's ``DISK_NODES``)
_DISK_NODES = 256


def _cap(axis: np.ndarray, sin2: np.ndarray, n: np.ndarray) -> np.ndarray:
    """E/L of uniform caps of angular radius σ (sin²σ = ``sin2``) about unit ``axis`` (S, 3) at normals n."""
    cos_t = np.clip(np.einsum("sd,sd->s", axis, n), -1.0, 1.0)
    sin_t = np.sqrt(np.maximum(0.0, 1.0 - cos_t * cos_t))
    cos_s = np.sqrt(np.maximum(0.0, 1.0 - sin2))
    above = (cos_t * cos_t > sin2) & (cos_t > 0.0)
    below = cos_t <= -np.sqrt(sin2)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = cos_s / np.sqrt(sin2)
        y = np.clip(-x * cos_t / np.where(sin_t > 0.0, sin_t, 1.0), -1.0, 1.0)
        sy = np.sqrt(np.maximum(0.0, 1.0 - y * y))
        straddle = (cos_t * np.arccos(y) - x * sin_t * sy) * sin2 + np.arctan(sin_t * sy / x)
    return np.where(below, 0.0, np.where(above | (sin_t <= 0.0), np.pi * sin2 * cos_t, straddle))


def _polygons(V: np.ndarray, P: np.ndarray, N: np.ndarray) -> np.ndarray:
    """E/L of convex polygons V (S, K, 3) at receivers (P, N), each clipped to its receiver's hemisphere."""
    from simulator.engine.visible import clip_halfplane, lambert_pieces

    d = V - P[:, None]
    W, cnt = clip_halfplane(d, np.full(len(P), V.shape[1]), np.einsum("skd,sd->sk", d, N))
    f, _ = lambert_pieces(W, N)
    return np.where(cnt >= 3, f, 0.0)


def _disk(light, P: np.ndarray, N: np.ndarray) -> np.ndarray:
    """E/L of a disk wholly above each receiver's horizon: ½·|n·∮(r × dr)/|r|²| (trapezoid rule)."""
    h = 2.0 * np.pi / _DISK_NODES
    phi = np.arange(_DISK_NODES) * h
    ex, ey = light.frame[:, 0], light.frame[:, 1]
    rim = light.radius * (np.cos(phi)[:, None] * ex + np.sin(phi)[:, None] * ey)  # (k, 3)
    drim = light.radius * (-np.sin(phi)[:, None] * ex + np.cos(phi)[:, None] * ey)
    r = (light.position - P)[:, None] + rim[None]  # (S, k, 3)
    c = np.cross(r, drim[None])
    acc = np.einsum("skd,sd->sk", c, N) / np.einsum("skd,skd->sk", r, r)
    return 0.5 * np.abs(acc.sum(axis=1) * h)


def host_analytic(scene, sensors, ids: np.ndarray, light_mask: np.ndarray | None = None) -> np.ndarray | None:
    """Closed-form readings of sensors ``ids``, (S, 2) ``(W/m², lx)`` (rows not read: 0), or None where
    some sensor or light needs the kernel (module docstring). ``light_mask`` (S, L): 0 where a light
    is culled for a sensor (wholly behind it: it adds nothing)."""
    ids = np.asarray(ids, np.int64)
    if any(sensors[i].kind != SensorKind.IRRADIANCE or getattr(sensors[i], "optics", None) is not None for i in ids):
        return None
    for l in scene.lights:
        if l.kind not in HOST_KINDS or l.shaping is not None or (l.kind == LightKind.DOME and l.texture):
            return None
    out = np.zeros((len(sensors), 2))
    if not len(ids):
        return out
    P = np.array([sensors[i].position for i in ids], float)
    N = np.array([sensors[i].normal for i in ids], float)
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    E = np.zeros((len(ids), 2))
    for j, l in enumerate(scene.lights):
        on = np.ones(len(ids), bool) if light_mask is None or j >= light_mask.shape[1] else light_mask[ids, j] != 0
        em = np.asarray(l.emission, float)
        if l.kind == LightKind.POINT:
            d = l.position - P
            d2 = np.einsum("sd,sd->s", d, d)
            c = np.einsum("sd,sd->s", d, N)
            with np.errstate(divide="ignore", invalid="ignore"):
                f = np.where((c > 0.0) & (d2 > 0.0), c / (d2 * np.sqrt(d2)), 0.0)
        elif l.kind == LightKind.SPHERE:
            d = l.position - P
            d2 = np.einsum("sd,sd->s", d, d)
            inside = d2 <= l.radius**2
            axis = d / np.sqrt(np.where(inside, 1.0, d2))[:, None]
            f = np.where(inside, 0.0, _cap(axis, l.radius**2 / np.where(inside, 1.0, d2), N))
        elif l.kind == LightKind.RECT:
            from simulator.engine.exact import rect_vertices

            back = (P - l.position) @ l.frame[:, 2] >= 0.0  # behind a one-sided emitter
            V = np.broadcast_to(rect_vertices(l), (len(P), 4, 3))
            f = np.where(back, 0.0, _polygons(V, P, N))
        elif l.kind == LightKind.DISK:
            back = (P - l.position) @ l.frame[:, 2] >= 0.0
            f = np.where(back, 0.0, _disk(l, P, N))
        elif l.kind == LightKind.DISTANT:
            ez = np.broadcast_to(l.frame[:, 2], P.shape)
            if l.half_angle <= 0.0:
                f = np.maximum(0.0, N @ l.frame[:, 2])
            else:
                omc = 2.0 * np.sin(0.5 * l.half_angle) ** 2
                f = _cap(ez, np.full(len(P), omc * (2.0 - omc)), N)
        else:  # a uniform dome: the whole sky
            f = np.full(len(P), np.pi)
        E += np.where(on, f, 0.0)[:, None] * em[None]
    g = scene.geometry
    if g.n_triangles and np.any(g.emission > 0):
        tris = np.flatnonzero(np.any(g.emission > 0, axis=1))
        for t in tris:
            a, b, c = g.points[g.triangles[t]]
            facing = (P - a) @ np.cross(b - a, c - a)  # > 0: in front
            lit = (facing > 0.0) | bool(g.two_sided[t])
            f = _polygons(np.broadcast_to(np.array([a, b, c]), (len(P), 3, 3)), P, N)
            E += np.where(lit, f, 0.0)[:, None] * g.emission[t][None]
    out[ids] = E
    return out
