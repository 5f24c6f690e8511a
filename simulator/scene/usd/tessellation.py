"""Polygons and triangles in plain numpy: Cube and UV-sphere polygons, triangulation.

Nothing here reads USD: the shapes come as ``(points, faceVertexCounts,
faceVertexIndices)`` in the prim's local frame, as a ``UsdGeom.Mesh`` states
them, and triangles keep each face's winding.
"""

from __future__ import annotations

import numpy as np

from simulator.scene.usd.transforms import _unit


def _cube_polygons(size: float):
    """UsdGeom.Cube: an axis-aligned cube of edge ``size`` centred at the origin, faces outward."""
    h = 0.5 * size
    # vertex i + 2j + 4k sits at (+-h, +-h, +-h) with bit set -> +h
    points = np.array([[(-h, h)[i], (-h, h)[j], (-h, h)[k]] for k in (0, 1) for j in (0, 1) for i in (0, 1)])
    quads = [(1, 3, 7, 5), (0, 4, 6, 2), (2, 6, 7, 3), (0, 1, 5, 4), (4, 5, 7, 6), (0, 2, 3, 1)]  # +X -X +Y -Y +Z -Z
    return points, np.full(6, 4, np.int64), np.array(quads, np.int64).ravel()


def _sphere_polygons(radius: float, n_lon: int, n_lat: int):
    """UsdGeom.Sphere as a UV sphere: pole caps of triangles, quads between rings, faces outward."""
    theta = np.pi * np.arange(1, n_lat) / n_lat  # ring polar angles, north to south
    phi = 2 * np.pi * np.arange(n_lon) / n_lon
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    ring = np.stack([st * np.cos(phi), st * np.sin(phi), np.broadcast_to(ct, (n_lat - 1, n_lon))], axis=-1)
    points = radius * np.concatenate([[[0.0, 0.0, 1.0]], ring.reshape(-1, 3), [[0.0, 0.0, -1.0]]])
    north, south = 0, len(points) - 1
    j = np.arange(n_lon)
    jn = (j + 1) % n_lon
    v = lambda k, jj: 1 + k * n_lon + jj  # noqa: E731  vertex of ring k (0-based), column jj
    faces = [np.stack([np.full(n_lon, north), v(0, j), v(0, jn)], 1).ravel()]
    for k in range(n_lat - 2):
        faces.append(np.stack([v(k, j), v(k + 1, j), v(k + 1, jn), v(k, jn)], 1).ravel())
    faces.append(np.stack([v(n_lat - 2, j), np.full(n_lon, south), v(n_lat - 2, jn)], 1).ravel())
    counts = np.array([3] * n_lon + [4] * (n_lon * (n_lat - 2)) + [3] * n_lon, np.int64)
    return points, counts, np.concatenate(faces)


def _triangulate(points: np.ndarray, counts: np.ndarray, indices: np.ndarray) -> tuple[np.ndarray, int]:
    """Split polygons into triangles that keep each face's winding.

    Faces are grouped by vertex count and handled in bulk: triangles as they
    are, convex polygons by a fan from their first vertex, and concave ones by
    ear clipping in the face's plane. Faces with fewer than 3 vertices are
    skipped.

    Returns
    -------
    tris : ndarray, shape (T, 3), int64
        Vertex indices of the triangles.
    fanned : int
        Faces that could not be ear-clipped (self-intersecting or
        non-planar) and were fan-triangulated instead.
    """
    starts = np.cumsum(counts) - counts
    out = [np.zeros((0, 3), np.int64)]
    concave_fallback = 0
    for n in np.unique(counts):
        n = int(n)
        if n < 3:
            continue
        idx = indices[starts[counts == n][:, None] + np.arange(n)]  # (F, n)
        if n == 3:
            out.append(idx)
            continue
        convex = _convex_faces(points[idx])
        hub = idx[convex]  # fan (v0, vk, vk+1), k = 1 .. n-2
        k = np.arange(1, n - 1)
        fan = np.stack([np.broadcast_to(hub[:, :1], (len(hub), n - 2)), hub[:, k], hub[:, k + 1]], -1)
        out.append(fan.reshape(-1, 3))
        for face in idx[~convex]:
            local, ok = _ear_clip(points[face])
            concave_fallback += not ok
            out.append(face[local])
    return np.concatenate(out), concave_fallback


def _newell_normal(poly: np.ndarray) -> np.ndarray:
    """Newell's area vector of polygons (..., n, 3): robust for non-planar faces, points along the winding."""
    return 0.5 * np.cross(poly, np.roll(poly, -1, axis=-2)).sum(axis=-2)


def _convex_faces(poly: np.ndarray) -> np.ndarray:
    """True where a polygon (F, n, 3) turns the same way as its area normal at every vertex."""
    normal = _newell_normal(poly)
    edge = np.roll(poly, -1, axis=1) - poly  # e_i = p_{i+1} - p_i
    turn = np.cross(np.roll(edge, 1, axis=1), edge)  # at vertex i: e_{i-1} x e_i
    dots = np.einsum("fni,fi->fn", turn, normal)
    tol = 1e-12 * np.linalg.norm(turn, axis=-1) * np.linalg.norm(normal, axis=-1)[:, None]
    return np.all(dots >= -tol, axis=1)


def _ear_clip(poly: np.ndarray) -> tuple[np.ndarray, bool]:
    """Ear-clip one simple polygon (n, 3); returns local vertex triples and whether it succeeded.

    The polygon is projected on the plane of its Newell normal with a basis
    (u, v, normal) that is right-handed, so its winding is counter-clockwise
    in 2D and each ear (prev, i, next) keeps the face's orientation.
    """
    n_vec = _unit(_newell_normal(poly))
    n = len(poly)
    if n_vec is None:
        return np.array([[0, k, k + 1] for k in range(1, n - 1)]), False
    helper = np.array([1.0, 0.0, 0.0]) if abs(n_vec[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = _unit(np.cross(helper, n_vec))
    v = np.cross(n_vec, u)
    q = np.column_stack([poly @ u, poly @ v])

    def cross2(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    remaining = list(range(n))
    tris = []
    while len(remaining) > 3:
        m = len(remaining)
        for k in range(m):
            i0, i1, i2 = remaining[k - 1], remaining[k], remaining[(k + 1) % m]
            if cross2(q[i0], q[i1], q[i2]) <= 0:  # reflex or collinear: not an ear
                continue
            if any(
                cross2(q[i0], q[i1], q[j]) >= 0 and cross2(q[i1], q[i2], q[j]) >= 0 and cross2(q[i2], q[i0], q[j]) >= 0
                for j in remaining if j not in (i0, i1, i2)
            ):
                continue
            tris.append((i0, i1, i2))
            remaining.pop(k)
            break
        else:  # no ear: not a simple polygon; fan the rest so nothing is lost
            tris += [(remaining[0], remaining[k], remaining[k + 1]) for k in range(1, len(remaining) - 1)]
            return np.array(tris), False
    tris.append(tuple(remaining))
    return np.array(tris), True


def _parallelogram_areas(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """``|(p1 - p0) x (p2 - p0)|`` per triangle (T,): twice each triangle's area."""
    p = points[tris]
    return np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def _drop_zero_area(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Remove triangles of exactly zero area (collinear fan slivers): nothing can hit them."""
    if len(tris) == 0:
        return tris
    return tris[_parallelogram_areas(points, tris) > 0]
