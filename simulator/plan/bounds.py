"""Bounding-box hierarchy over a scene's triangles for the planner's half-space tests.

The planner asks, per sensor, whether any triangle has a vertex strictly in
front of the sensor's plane, and which is the first (lowest index) such
triangle among a few subsets (all, non-emissive, reflecting, ...). A scan
of every triangle costs O(T) per sensor; this index answers in roughly
O(√T) for a plane that cuts a surface and O(log T) for one that does not.

Build (once per scene): triangles sorted along a Morton curve of their
centroids, leaves of ``LEAF`` consecutive triangles, and levels of
``FANOUT`` consecutive nodes, each node holding the axis-aligned box of its
vertices and, per subset, the lowest original index it contains.

Query: descend from the top level; a node whose box lies wholly behind the
plane (by more than a rounding margin) is dropped, one wholly in front
contributes its stored lowest indices, one the plane cuts is opened; at the
leaves the triangles of cut nodes get the exact per-vertex test,
:func:`front_of_plane`, the same arithmetic as a scan of every triangle,
so the answers are the scan's.

Notes
-----
Box bound: for a vertex v in the box [lo, hi], each term (v_k − o_k)·n_k of
the signed height h = (v − o)·n lies between the corner terms
min/max((lo_k − o_k)·n_k, (hi_k − o_k)·n_k) (floating-point subtraction and
multiplication are monotone). Summing three terms in another order or with a
fused multiply-add moves h by a few units in the last place of
|v| + |o|; the margin, 1e-12·(1 + max|v| + max|o|), is far above that, so a
box is called behind or in front only where every vertex in it is, to the
scan's own float64 arithmetic.

References
----------
G. M. Morton, "A computer oriented geodetic data base and a new technique in
file sequencing", IBM technical report, 1966 (the space-filling order).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["LEAF", "FANOUT", "SCAN_MAX_TRIANGLES", "SCAN_PAIRS", "front_of_plane", "FrontIndex"]

#: triangles per leaf
LEAF = 16
#: children per inner node
FANOUT = 8
#: triangles up to which :meth:`FrontIndex.first_in_front_many` scans every triangle for every plane
SCAN_MAX_TRIANGLES = 512
#: planes × triangles scanned at once (memory: ~200 bytes each)
SCAN_PAIRS = 1 << 16
#: no triangle: the sentinel of a node's lowest index
_NONE = np.iinfo(np.int64).max


def front_of_plane(points: np.ndarray, origin: np.ndarray, normal: np.ndarray, tol: float) -> np.ndarray:
    """Per triangle: does any vertex lie strictly in front of the plane?

    Parameters
    ----------
    points : ndarray, shape (T, 3, 3)
        Triangle vertices, metres.
    origin, normal : ndarray, shape (3,)
        A point of the plane (metres) and its unit normal.
    tol : float
        Heights (v − origin)·normal up to ``tol`` metres count as behind.

    Returns
    -------
    ndarray, shape (T,), bool
    """
    h = (points - origin) @ normal  # (T, 3)
    return np.any(h > tol, axis=1)


def _spread_bits(x: np.ndarray) -> np.ndarray:
    """10-bit integers with two zero bits inserted after each bit (for Morton codes)."""
    x = x.astype(np.uint32) & np.uint32(0x3FF)
    for shift, mask in ((16, 0x030000FF), (8, 0x0300F00F), (4, 0x030C30C3), (2, 0x09249249)):
        x = (x | (x << np.uint32(shift))) & np.uint32(mask)
    return x


def _morton_order(points: np.ndarray) -> np.ndarray:
    """Indices that sort ``points`` (N, 3) along a Morton curve on a 1024³ grid over their box."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.where(hi > lo, hi - lo, 1.0)
    q = np.clip((points - lo) * (1023.0 / span), 0, 1023).astype(np.uint32)
    code = _spread_bits(q[:, 0]) | (_spread_bits(q[:, 1]) << np.uint32(1)) | (_spread_bits(q[:, 2]) << np.uint32(2))
    return np.argsort(code)


def _vertex_min(p: np.ndarray) -> np.ndarray:
    return np.minimum(np.minimum(p[:, 0], p[:, 1]), p[:, 2])


def _vertex_max(p: np.ndarray) -> np.ndarray:
    return np.maximum(np.maximum(p[:, 0], p[:, 1]), p[:, 2])


@dataclass
class _Level:
    lo: np.ndarray  # (N, 3) box corners, metres
    hi: np.ndarray
    first: np.ndarray  # (N, K) lowest original triangle index per subset (_NONE: none)


class FrontIndex:
    """Triangles grouped for "first triangle in front of a plane" queries.

    Parameters
    ----------
    points : ndarray, shape (T, 3, 3)
        Triangle vertices, metres (T ≥ 1).
    subsets : dict of str to ndarray, shape (T,), bool
        Named subsets the queries answer for.
    tol : float
        The height tolerance of :func:`front_of_plane`, metres.
    """

    def __init__(self, points: np.ndarray, subsets: dict[str, np.ndarray], tol: float):
        self.names = tuple(subsets)
        self.tol = float(tol)
        self.n = len(points)
        order = _morton_order(points[:, 0])  # any order gives the same answers; a compact one, small boxes
        self.points = np.ascontiguousarray(points[order])
        self.original = order.astype(np.int64)
        self.member = np.column_stack([np.asarray(subsets[k], bool)[order] for k in self.names])  # (T, K)
        self.scale = max(float(self.points.max()), -float(self.points.min()))
        starts = np.arange(0, self.n, LEAF)
        first = np.where(self.member, self.original[:, None], _NONE)
        level = _Level(np.minimum.reduceat(_vertex_min(self.points), starts), np.maximum.reduceat(_vertex_max(self.points), starts),
                       np.minimum.reduceat(first, starts))  # fmt: skip
        self.levels = [level]  # leaves first; reversed below
        while len(level.lo) > FANOUT:
            s = np.arange(0, len(level.lo), FANOUT)
            level = _Level(np.minimum.reduceat(level.lo, s), np.maximum.reduceat(level.hi, s), np.minimum.reduceat(level.first, s))
            self.levels.append(level)
        self.levels.reverse()

    def first_in_front(self, origin: np.ndarray, normal: np.ndarray) -> dict[str, int]:
        """Per subset, the lowest original index of a triangle with a vertex in
        front of the plane (``front_of_plane``), or −1 where there is none."""
        o = np.asarray(origin, float)
        n = np.asarray(normal, float)
        margin = 1e-12 * (1.0 + self.scale + float(np.abs(o).max()))
        best = np.full(len(self.names), _NONE, np.int64)
        nodes = np.arange(len(self.levels[0].lo))
        for depth, level in enumerate(self.levels):
            nodes = nodes[np.any(level.first[nodes] < best, axis=1)]  # nothing lower to find in the others
            if len(nodes) == 0:
                break
            a = (level.lo[nodes] - o) * n
            b = (level.hi[nodes] - o) * n
            top = np.maximum(a, b).sum(axis=1)
            bottom = np.minimum(a, b).sum(axis=1)
            ahead = bottom > self.tol + margin
            if ahead.any():
                best = np.minimum(best, level.first[nodes[ahead]].min(axis=0))
            cut = nodes[~ahead & (top > self.tol - margin)]
            if depth + 1 < len(self.levels):
                nodes = (cut[:, None] * FANOUT + np.arange(FANOUT)).ravel()
                nodes = nodes[nodes < len(self.levels[depth + 1].lo)]
            else:
                best = np.minimum(best, self._exact(cut, o, n))
        return {k: (int(b) if b != _NONE else -1) for k, b in zip(self.names, best)}

    def first_in_front_many(self, origins: np.ndarray, normals: np.ndarray) -> np.ndarray | None:
        """:meth:`first_in_front` of many planes at once, or None where the scene is too big for a
        scan of every triangle per plane (more than :data:`SCAN_MAX_TRIANGLES`: the hierarchy
        per plane is cheaper there).

        Parameters
        ----------
        origins, normals : ndarray, shape (S, 3)
            A point (metres) and the unit normal of each plane.

        Returns
        -------
        ndarray of int, shape (S, K), or None
            Per plane and subset (in ``names`` order), the lowest original
            index of a triangle in front (:func:`front_of_plane`), −1 for none.

        Notes
        -----
        Heights ``(v − o)·n`` are computed by the same matrix product as
        :func:`front_of_plane`'s, stacked over the planes (numpy's ``matmul``
        gives the same bits per plane), so the answers are the scan's.
        """
        if self.n > SCAN_MAX_TRIANGLES:
            return None
        o = np.asarray(origins, float).reshape(-1, 3)
        nrm = np.asarray(normals, float).reshape(-1, 3)
        out = np.full((len(o), len(self.names)), _NONE, np.int64)
        first = np.where(self.member, self.original[:, None], _NONE)  # (T, K)
        step = max(1, SCAN_PAIRS // max(self.n, 1))
        for a in range(0, len(o), step):
            d = self.points[None] - o[a : a + step, None, None, :]  # (s, T, 3, 3)
            h = (d @ nrm[a : a + step, None, :, None])[..., 0]  # (s, T, 3): stacked matmul, the scan's own arithmetic
            front = np.any(h > self.tol, axis=2)  # (s, T)
            out[a : a + step] = np.where(front[:, :, None], first[None], _NONE).min(axis=1)
        return np.where(out == _NONE, -1, out)

    def _exact(self, leaves: np.ndarray, o: np.ndarray, n: np.ndarray) -> np.ndarray:
        """Lowest original index per subset among the leaves' triangles in front."""
        out = np.full(len(self.names), _NONE, np.int64)
        if len(leaves) == 0:
            return out
        tri = (leaves[:, None] * LEAF + np.arange(LEAF)).ravel()
        tri = tri[tri < self.n]
        front = front_of_plane(self.points[tri], o, n, self.tol)
        if front.any():
            hit = tri[front]
            first = np.where(self.member[hit], self.original[hit][:, None], _NONE)
            out = first.min(axis=0)
        return out
