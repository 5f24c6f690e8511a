"""Float64 geometry the reference cases need: patch corners, cone rims,
ray–triangle intersection and point-in-polygon tests.

These are independent of the engine (no Warp, no BVH): the reference values
and the tests that check the engine's ray queries use them as ground truth.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

__all__ = ["patch_vertices", "cone_rim", "ray_triangles", "ray_hits_triangles", "points_in_polygon_2d", "cone_lands_inside"]


def patch_vertices(position: np.ndarray, normal: np.ndarray, up: np.ndarray, size: tuple[float, float]) -> np.ndarray:
    """Corners of a rectangular patch, counter-clockwise about its normal.

    Parameters
    ----------
    position, normal, up : ndarray, shape (3,)
        Centre (metres), unit normal and unit up direction (in the patch's plane).
    size : (float, float)
        Width (along up × normal) and height (along up), metres.

    Returns
    -------
    ndarray, shape (4, 3), metres
    """
    right = np.cross(up, normal)
    right /= np.linalg.norm(right)
    hw, hh = 0.5 * size[0], 0.5 * size[1]
    c = position
    return np.array([c - hw * right - hh * up, c + hw * right - hh * up, c + hw * right + hh * up, c - hw * right + hh * up])


def cone_rim(direction: np.ndarray, half_angle: float, n: int = 64) -> np.ndarray:
    """Unit directions on the rim of a cone (and its axis), shape (n + 1, 3).

    Parameters
    ----------
    direction : ndarray, shape (3,)
        The cone's axis.
    half_angle : float
        Radians.
    """
    d = direction / np.linalg.norm(direction)
    helper = np.array([1.0, 0.0, 0.0]) if abs(d[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    a = np.cross(d, helper)
    a /= np.linalg.norm(a)
    b = np.cross(d, a)
    phi = 2 * np.pi * np.arange(n) / n
    rim = np.cos(half_angle) * d + np.sin(half_angle) * (np.cos(phi)[:, None] * a + np.sin(phi)[:, None] * b)
    return np.vstack([d, rim])


def ray_triangles(o: np.ndarray, d: np.ndarray, tri: np.ndarray, det_min: float = 1e-300):
    """Möller–Trumbore intersection of rays with triangles, float64, both faces.

    Parameters
    ----------
    o, d : ndarray, shape (..., 3)
        Ray origins (metres) and directions, broadcast against ``tri``'s
        leading axes (for R rays against T triangles pass (R, 1, 3)).
    tri : ndarray, shape (..., 3, 3)
        Triangle vertices, metres.
    det_min : float
        Rays more nearly parallel to a triangle's plane (|det| ≤ det_min) miss it.

    Returns
    -------
    t : ndarray
        Distance along d to the plane crossing (meaningful where ``ok``).
    u, v : ndarray
        Barycentric coordinates of the crossing (inside: u, v ≥ 0, u + v ≤ 1).
    ok : ndarray, bool
        |det| > det_min.

    Notes
    -----
    With e1 = p1 − p0, e2 = p2 − p0, P = d × e2, det = e1·P, T = o − p0,
    Q = T × e1: u = T·P/det, v = d·Q/det, t = e2·Q/det.

    References
    ----------
    T. Möller and B. Trumbore, "Fast, minimum storage ray-triangle
    intersection", Journal of Graphics Tools 2(1), 21–28, 1997.
    """
    p0 = tri[..., 0, :]
    e1 = tri[..., 1, :] - p0
    e2 = tri[..., 2, :] - p0
    pv = np.cross(d, e2)
    det = np.sum(e1 * pv, axis=-1)
    ok = np.abs(det) > det_min
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    tv = o - p0
    u = np.sum(tv * pv, axis=-1) * inv
    qv = np.cross(tv, e1)
    v = np.sum(qv * d, axis=-1) * inv
    t = np.sum(e2 * qv, axis=-1) * inv
    return t, u, v, ok


def ray_hits_triangles(o: np.ndarray, d: np.ndarray, tri: np.ndarray, t_max: float = math.inf) -> bool:
    """Whether the ray o + t·d, 0 < t < t_max, hits any of the triangles ``tri`` (T, 3, 3)
    (:func:`ray_triangles`)."""
    if len(tri) == 0:
        return False
    t, u, v, ok = ray_triangles(o, d, tri)
    return bool(np.any(ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < t_max)))


def points_in_polygon_2d(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Even–odd rule for points (N, 2) in a simple polygon (V, 2); returns (N,) bool."""
    x, y = pts[:, 0:1], pts[:, 1:2]
    x0, y0 = poly[:, 0], poly[:, 1]
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    crosses = ((y0 <= y) != (y1 <= y)) & (x < x0 + (y - y0) * (x1 - x0) / np.where(y1 != y0, y1 - y0, 1.0))
    return np.count_nonzero(crosses, axis=1) % 2 == 1


def cone_lands_inside(position: np.ndarray, axis: np.ndarray, half_angle: float, plane_point, plane_normal,
                      inside: Callable[[np.ndarray], np.ndarray]) -> bool:  # fmt: skip
    """Whether every ray of a cone (its rim and axis, :func:`cone_rim`) from
    ``position`` meets the plane in front of it at a point for which ``inside`` holds."""
    dirs = cone_rim(axis, half_angle)
    denom = dirs @ plane_normal
    if np.any(np.abs(denom) < 1e-12):
        return False
    t = ((np.asarray(plane_point) - position) @ plane_normal) / denom
    if np.any(t <= 0):
        return False
    return bool(np.all(inside(position + t[:, None] * dirs)))
