"""Polygons and triangles in plain numpy: the implicit gprims as polygons, triangulation.

Nothing here reads USD: the shapes come as ``(points, faceVertexCounts,
faceVertexIndices)`` in the prim's local frame, as a ``UsdGeom.Mesh`` states
them, and triangles keep each face's winding.
"""

from __future__ import annotations

import numpy as np

from simulator.scene.usd.transforms import _unit
from simulator.scene.vectors import cross3


def _cube_polygons(size: float):
    """UsdGeom.Cube: an axis-aligned cube of edge ``size`` centred at the origin, faces outward."""
    h = 0.5 * size
    # vertex i + 2j + 4k sits at (+-h, +-h, +-h) with bit set -> +h
    points = np.array([[(-h, h)[i], (-h, h)[j], (-h, h)[k]] for k in (0, 1) for j in (0, 1) for i in (0, 1)])
    quads = [(1, 3, 7, 5), (0, 4, 6, 2), (2, 6, 7, 3), (0, 1, 5, 4), (4, 5, 7, 6), (0, 2, 3, 1)]  # +X -X +Y -Y +Z -Z
    return points, np.full(6, 4, np.int64), np.array(quads, np.int64).ravel()


def _ring_faces(n_ring: int, n_lon: int):
    """Faces of a closed pole-to-pole surface: triangle fans at the poles, quads between rings, outward.

    Parameters
    ----------
    n_ring : int
        Rings of ``n_lon`` vertices between the poles (>= 1).
    n_lon : int
        Vertices per ring (>= 3).

    Returns
    -------
    counts, indices : ndarray of int64
        ``faceVertexCounts`` and ``faceVertexIndices`` for points laid out as
        the north pole (index 0), then ring ``k`` column ``j`` at index
        ``1 + k * n_lon + j``, then the south pole (the last index), with rings
        ordered north to south and columns counter-clockwise seen from the
        north pole.
    """
    north, south = 0, 1 + n_ring * n_lon
    j = np.arange(n_lon)
    jn = (j + 1) % n_lon
    v = lambda k, jj: 1 + k * n_lon + jj  # noqa: E731  vertex of ring k (0-based), column jj
    faces = [np.stack([np.full(n_lon, north), v(0, j), v(0, jn)], 1).ravel()]
    for k in range(n_ring - 1):
        faces.append(np.stack([v(k, j), v(k + 1, j), v(k + 1, jn), v(k, jn)], 1).ravel())
    faces.append(np.stack([v(n_ring - 1, j), np.full(n_lon, south), v(n_ring - 1, jn)], 1).ravel())
    counts = np.array([3] * n_lon + [4] * (n_lon * (n_ring - 1)) + [3] * n_lon, np.int64)
    return counts, np.concatenate(faces)


def _sphere_polygons(radius: float, n_lon: int, n_lat: int):
    """UsdGeom.Sphere as a UV sphere: pole caps of triangles, quads between rings, faces outward."""
    theta = np.pi * np.arange(1, n_lat) / n_lat  # ring polar angles, north to south
    phi = 2 * np.pi * np.arange(n_lon) / n_lon
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    ring = np.stack([st * np.cos(phi), st * np.sin(phi), np.broadcast_to(ct, (n_lat - 1, n_lon))], axis=-1)
    points = radius * np.concatenate([[[0.0, 0.0, 1.0]], ring.reshape(-1, 3), [[0.0, 0.0, -1.0]]])
    counts, indices = _ring_faces(n_lat - 1, n_lon)
    return points, counts, indices


#: a proper rotation taking local +Z to each UsdGeom ``axis`` (cyclic permutations: det +1)
_AXIS_ROTATIONS = {
    "Z": np.eye(3),
    "X": np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),  # (a, b, c) -> (c, a, b)
    "Y": np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]),  # (a, b, c) -> (b, c, a)
}


def _revolution_polygons(radii: np.ndarray, heights: np.ndarray, n_lon: int, axis: str = "Z"):
    """A closed surface of revolution about ``axis`` from a profile, faces outward.

    Parameters
    ----------
    radii, heights : ndarray, shape (K,)
        The profile from the top pole to the bottom pole: ``(radii[k],
        heights[k])`` is a ring of radius ``radii[k]`` at height ``heights[k]``
        along the axis; the first and the last entries are the poles (their
        radius is ignored: one vertex each). Heights must not increase.
    n_lon : int
        Segments around the axis (>= 3).
    axis : {"X", "Y", "Z"}
        The axis of revolution (UsdGeom ``axis``).

    Returns
    -------
    points, counts, indices
        ``(P, 3)`` points and ``faceVertexCounts``/``faceVertexIndices`` as a
        Mesh states them: triangle fans at the poles, quads between rings.

    Notes
    -----
    Vertices lie on the surface, so each ring is an inscribed regular
    polygon: a side area short by a factor ``sin(2 pi/n)/(2 pi/n)`` (0.16% at
    n = 64). Rings of radius 0 (a cone's apex) give zero-area faces, which
    :func:`_drop_zero_area` removes after triangulation.
    """
    phi = 2 * np.pi * np.arange(n_lon) / n_lon
    r, z = np.asarray(radii[1:-1], float)[:, None], np.asarray(heights[1:-1], float)[:, None]
    n_ring = len(r)
    ring = np.stack([r * np.cos(phi), r * np.sin(phi), np.broadcast_to(z, (n_ring, n_lon))], axis=-1)
    points = np.concatenate([[[0.0, 0.0, heights[0]]], ring.reshape(-1, 3), [[0.0, 0.0, heights[-1]]]])
    counts, indices = _ring_faces(n_ring, n_lon)
    return points @ _AXIS_ROTATIONS[axis].T, counts, indices


def _cylinder_polygons(radius_top: float, radius_bottom: float, height: float, n_lon: int, axis: str = "Z"):
    """UsdGeom.Cylinder (and Cylinder_1's two radii): capped, centred, ``height`` along ``axis``."""
    h = 0.5 * height
    return _revolution_polygons(np.array([0.0, radius_top, radius_bottom, 0.0]), np.array([h, h, -h, -h]),
                                n_lon, axis)


def _cone_polygons(radius: float, height: float, n_lon: int, axis: str = "Z"):
    """UsdGeom.Cone: apex at ``+height/2`` along ``axis``, a capped base of ``radius`` at ``-height/2``."""
    h = 0.5 * height
    return _revolution_polygons(np.array([0.0, radius, 0.0]), np.array([h, -h, -h]), n_lon, axis)


def _capsule_polygons(radius: float, height: float, n_lon: int, n_lat: int, axis: str = "Z"):
    """UsdGeom.Capsule: a cylinder of ``height`` along ``axis`` with hemispherical caps of ``radius``.

    The capsule's full length is ``height + 2 radius``. Each cap has
    ``ceil(n_lat / 2)`` latitude bands (``n_lat`` is the whole sphere's, as
    for a Sphere's tessellation).
    """
    n_half = max(1, (n_lat + 1) // 2)
    theta = 0.5 * np.pi * np.arange(n_half + 1) / n_half  # pole (0) to equator (pi/2)
    h = 0.5 * height
    r_top, z_top = radius * np.sin(theta), h + radius * np.cos(theta)
    radii = np.concatenate([r_top, r_top[::-1]])
    heights = np.concatenate([z_top, -z_top[::-1]])
    return _revolution_polygons(radii, heights, n_lon, axis)


def _plane_polygons(width: float, length: float, axis: str = "Z"):
    """UsdGeom.Plane: one ``width`` x ``length`` quad centred at the origin, front face along +``axis``.

    Width lies along X (axis Z or Y) or Z (axis X); length along Y (axis Z
    or X) or Z (axis Y), as the schema states.
    """
    u_axis = {"Z": 0, "Y": 0, "X": 2}[axis]
    v_axis = {"Z": 1, "Y": 2, "X": 1}[axis]
    normal = np.eye(3)["XYZ".index(axis)]
    u, v = 0.5 * width * np.eye(3)[u_axis], 0.5 * length * np.eye(3)[v_axis]
    points = np.array([-u - v, u - v, u + v, -u + v])
    quad = [0, 1, 2, 3] if np.dot(np.cross(u, v), normal) > 0 else [0, 3, 2, 1]
    return points, np.array([4], np.int64), np.array(quad, np.int64)


def _triangulate(points: np.ndarray, counts: np.ndarray, indices: np.ndarray) -> tuple[np.ndarray, int]:
    """Split polygons into triangles that keep each face's winding (see :func:`_triangulate_faces`)."""
    tris, fanned, _ = _triangulate_faces(points, counts, indices)
    return tris, fanned


def _triangulate_faces(points: np.ndarray, counts: np.ndarray, indices: np.ndarray,
                       convex: bool = False) -> tuple[np.ndarray, int, np.ndarray]:
    """Split polygons into triangles that keep each face's winding.

    Faces are grouped by vertex count and handled in bulk: triangles as they
    are, convex polygons by a fan from their first vertex, and concave ones by
    ear clipping in the face's plane. Faces with fewer than 3 vertices are
    skipped. ``convex``: every face is known to be convex (the implicit
    gprims' own polygons, planar by construction), so each is fanned without
    the test, which on a finely tessellated Sphere costs more than all the
    rest of its reading.

    Returns
    -------
    tris : ndarray, shape (T, 3), int64
        Vertex indices of the triangles.
    fanned : int
        Faces that could not be ear-clipped (self-intersecting or
        non-planar) and were fan-triangulated instead.
    face_of : ndarray, shape (T,), int64
        The face (index into ``counts``) each triangle came from.
    """
    starts = np.cumsum(counts) - counts
    out = [np.zeros((0, 3), np.int64)]
    face_out = [np.zeros(0, np.int64)]
    concave_fallback = 0
    for n in np.unique(counts):
        n = int(n)
        if n < 3:
            continue
        faces = np.flatnonzero(counts == n)
        idx = indices[starts[faces][:, None] + np.arange(n)]  # (F, n)
        if n == 3:
            out.append(idx)
            face_out.append(faces)
            continue
        fans = np.ones(len(faces), bool) if convex else _convex_faces(points[idx])
        hub = idx[fans]  # fan (v0, vk, vk+1), k = 1 .. n-2
        k = np.arange(1, n - 1)
        fan = np.stack([np.broadcast_to(hub[:, :1], (len(hub), n - 2)), hub[:, k], hub[:, k + 1]], -1)
        out.append(fan.reshape(-1, 3))
        face_out.append(np.repeat(faces[fans], n - 2))
        for f, face in zip(faces[~fans], idx[~fans]):
            local, ok = _ear_clip(points[face])
            concave_fallback += not ok
            out.append(face[local])
            face_out.append(np.full(len(local), f))
    return np.concatenate(out), concave_fallback, np.concatenate(face_out)


def _newell_normal(poly: np.ndarray) -> np.ndarray:
    """Newell's area vector of polygons (..., n, 3): robust for non-planar faces, points along the winding."""
    return 0.5 * cross3(poly, np.roll(poly, -1, axis=-2)).sum(axis=-2)


def _convex_faces(poly: np.ndarray) -> np.ndarray:
    """True where a polygon (F, n, 3) turns the same way as its area normal at every vertex."""
    normal = _newell_normal(poly)
    edge = np.roll(poly, -1, axis=1) - poly  # e_i = p_{i+1} - p_i
    turn = cross3(np.roll(edge, 1, axis=1), edge)  # at vertex i: e_{i-1} x e_i
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
    # each corner gathered on its own, (T, 3) contiguous: the same values as points[tris], in half the time
    p0, p1, p2 = (np.take(points, tris[:, k], axis=0) for k in range(3))
    return np.linalg.norm(cross3(p1 - p0, p2 - p0), axis=1)


def _drop_zero_area(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Remove triangles of exactly zero area (collinear fan slivers): nothing can hit them."""
    if len(tris) == 0:
        return tris
    return tris[_nonzero_area(points, tris)]


def _nonzero_area(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """True (T,) for triangles of non-zero area."""
    return _parallelogram_areas(points, tris) > 0
