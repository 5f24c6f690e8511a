"""The sun's direct light at each sensor, every hour, exactly: one shadow ray per (hour, sensor) on the host.

The sun of a climate-based study is a delta distant light: from normal
illuminance E_n along unit direction s, a sensor at x reads

- irradiance (normal n): E = E_n · max(0, n·s) · V(x, s); a modelled head (a sensor model's
  angular response r, docs/sensors.md): E_n · r(θ, φ) · V(x, s), θ the sun's angle from n;
- cone meter (axis n, half-angle α, mean radiance over the cone): a delta
  inside the cone adds E_n / Ω to the mean, Ω = 2π(1 − cos α); outside, 0
  (a meter whose axis is within α of the sun reads E_n·V/Ω),

with V(x, s) = 1 when the ray from x along s meets no triangle of the
stage (Möller–Trumbore's test in float64 over all triangles, vectorised
over sensors). On a stage with panes, translucent layers or coverage
(a glazed window, a screen) V is the share the faces on the ray pass, as
the kernels' shadow rays take it (:mod:`simulator.study.annual.rays`); a
matte face passes nothing. No sampling: this part of every hourly reading
has no variance, and the sun's direct light (the part IES LM-83 ASE
counts) is exact.

References
----------
Möller, T. and Trumbore, B. (1997). Fast, minimum storage ray-triangle
intersection. Journal of Graphics Tools 2(1), 21–28.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.scene.model import SensorKind
from simulator.study.annual.rays import cast, has_surfaces, ray_scene

__all__ = ["visible", "direct_sun", "head_response"]

#: a hit nearer than this (metres) along the ray is the sensor's own surface, not an occluder
_T_MIN_M = 1e-6


def visible(origins: np.ndarray, direction: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """True where the ray from each origin along ``direction`` hits no triangle.

    Parameters
    ----------
    origins : ndarray, shape (S, 3)
    direction : ndarray, shape (3,), unit
    tris : ndarray, shape (T, 3, 3)
        Triangle vertices.
    """
    if len(tris) == 0 or len(origins) == 0:
        return np.ones(len(origins), bool)
    v0 = tris[:, 0]
    e1, e2 = tris[:, 1] - v0, tris[:, 2] - v0
    pvec = np.cross(direction, e2)  # (T, 3)
    det = np.einsum("tk,tk->t", e1, pvec)
    ok = np.abs(det) > 1e-14
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    tvec = origins[:, None, :] - v0[None]  # (S, T, 3)
    u = np.einsum("stk,tk->st", tvec, pvec) * inv
    qvec = np.cross(tvec, e1[None])
    v = np.einsum("k,stk->st", direction, qvec) * inv
    t = np.einsum("stk,tk->st", qvec, e2) * inv
    hit = ok & (u >= 0.0) & (v >= 0.0) & (u + v <= 1.0) & (t > _T_MIN_M)
    return ~hit.any(axis=1)


def _frame_x(n: np.ndarray) -> np.ndarray:
    """The first tangent the kernels take around unit ``n`` (kernels.sampling.frame_x, Duff et al. 2017)."""
    s = 1.0 if n[2] >= 0.0 else -1.0
    a = -1.0 / (s + n[2])
    b = n[0] * n[1] * a
    return np.array([1.0 + s * n[0] * n[0] * a, s * b, -s * n[0]])


def head_response(sensors, ids, nrm: np.ndarray, s: np.ndarray) -> np.ndarray:
    """r(θ, φ) of the modelled heads ``ids`` (their ``optics``) toward unit direction ``s``, in the frame the
    kernels read them in (azimuth 0 along ``azimuth_ref``, else the tangent of :func:`_frame_x`)."""
    out = np.zeros(len(ids))
    for k, i in enumerate(ids):
        sen, n = sensors[i], nrm[i]
        c = float(n @ s)
        if c <= 0.0:
            continue
        theta = math.degrees(math.atan2(float(np.linalg.norm(s - c * n)), c))
        phi = 0.0
        if not sen.optics.symmetric:
            x = sen.azimuth_ref if sen.azimuth_ref is not None else _frame_x(n)
            x = x - float(x @ n) * n
            x = x / np.linalg.norm(x)
            phi = math.degrees(math.atan2(float(s @ np.cross(n, x)), float(s @ x)))
        out[k] = float(sen.optics.response(theta, phi))
    return out


def direct_sun(sensors, scene, sun_dir: np.ndarray, sun_lx: np.ndarray) -> np.ndarray:
    """Direct sun reading of every sensor every hour, shape (H, S) (lux for irradiance, cd/m² for a cone meter;
    a modelled head, ``optics`` set, reads E_n·r(θ, φ)·V through its angular response).

    ``sun_dir`` (H, 3) unit directions toward the sun; ``sun_lx`` (H,)
    normal illuminance (0: no sun that hour)."""
    g = scene.geometry
    tris = np.asarray(g.points, np.float64)[np.asarray(g.triangles)]
    pos = np.array([s.position for s in sensors], np.float64)
    nrm = np.array([s.normal for s in sensors], np.float64)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    cone = np.array([s.kind == SensorKind.RADIANCE for s in sensors])
    half = np.array([s.half_angle for s in sensors], np.float64)
    omega = 2 * math.pi * 2.0 * np.sin(0.5 * half) ** 2  # 2π(1 − cos α) without cancellation
    heads = [i for i, x in enumerate(sensors) if getattr(x, "optics", None) is not None]
    out = np.zeros((len(sun_dir), len(sensors)))
    rs = None
    if has_surfaces(scene):  # panes or layers pass a share of the sun: the rays' product of shares
        rs = ray_scene(scene)
    for h in np.nonzero(np.asarray(sun_lx) > 0)[0]:
        s = sun_dir[h]
        c = nrm @ s
        w = np.where(cone, np.where((c >= np.cos(half)) & (omega > 0), 1.0 / np.where(omega > 0, omega, 1.0), 0.0), np.maximum(c, 0.0))
        if heads:
            w[list(heads)] = head_response(sensors, heads, nrm, s)
        ids = np.nonzero(w > 0)[0]
        if len(ids):
            v = visible(pos[ids], s, tris) if rs is None else cast(rs, pos[ids], s).through
            out[h, ids] = sun_lx[h] * w[ids] * v
    return out
