"""The triangles that may stand between receivers and emitters: a box hierarchy culled by convex volumes.

For exact direct light (:mod:`.visible`) each (receiver, emitter polygon) pair
needs the triangles that reach into the convex volume between them: the hull
of the receiver point and the emitter polygon, cut by the receiver's horizon.
That volume is the intersection of half-spaces (one plane per emitter edge
through the receiver, the emitter's own plane, the receiver's plane parallel
to it, the horizon), and a triangle wholly outside any one of them cannot
block. Scanning every triangle for every pair costs O(T) a pair; here the
triangles are sorted along a Morton curve of their centroids into leaves of
:data:`LEAF` and levels of :data:`FANOUT` boxes (as
:class:`simulator.plan.bounds.FrontIndex`), and the pairs descend the levels
together, each level one vectorised box-against-planes test over every
(pair, node) still open: a box wholly outside one plane is dropped with all
it holds.

The test is conservative by a margin of 10⁻⁹ of the coordinates' magnitude
(a triangle that touches a plane within rounding is kept): the exact clipping
that follows sets aside what cannot block, so a candidate too many costs
time, never a wrong answer.
"""

from __future__ import annotations

import numpy as np

from simulator.plan.bounds import _morton_order
from simulator.scene.vectors import cross3

__all__ = ["LEAF", "FANOUT", "OccluderIndex", "pyramid_planes", "cluster_planes", "cull_clustered", "outside_none", "reaching_pairs"]

#: triangles per leaf
LEAF = 8
#: children per inner node
FANOUT = 8
#: (pair, node) tests per vectorised step (memory ~ 100 bytes each × planes)
_STEP = 1 << 18
#: relative margin of the plane tests
_MARGIN = 1e-9


class OccluderIndex:
    """Triangles grouped for convex-volume culls.

    Parameters
    ----------
    tris : ndarray, shape (T, 3, 3)
        Triangle vertices, metres.
    """

    def __init__(self, tris: np.ndarray):
        tris = np.asarray(tris, np.float64).reshape(-1, 3, 3)
        self.n = len(tris)
        self.scale = max(1.0, float(np.abs(tris).max())) if self.n else 1.0
        if not self.n:
            self.levels = []
            return
        order = _morton_order(tris.mean(axis=1))
        self.tris = np.ascontiguousarray(tris[order])
        self.original = order.astype(np.int64)
        starts = np.arange(0, self.n, LEAF)
        lo = np.minimum.reduceat(self.tris.min(axis=1), starts)
        hi = np.maximum.reduceat(self.tris.max(axis=1), starts)
        count = np.diff(np.r_[starts, self.n])
        self.levels = [(lo, hi, count)]  # leaves first; reversed below
        while len(lo) > FANOUT:
            s = np.arange(0, len(lo), FANOUT)
            lo, hi, count = np.minimum.reduceat(lo, s), np.maximum.reduceat(hi, s), np.add.reduceat(count, s)
            self.levels.append((lo, hi, count))
        self.levels.reverse()

    def tris_by_original(self) -> np.ndarray:
        """The triangles in their original order, (T, 3, 3) (kept after the first call)."""
        if getattr(self, "_by_original", None) is None:
            out = np.empty_like(self.tris)
            out[self.original] = self.tris
            self._by_original = out
        return self._by_original

    def cull(self, planes: np.ndarray, count_only: bool = False):
        """The triangles not wholly outside any plane of each volume.

        Parameters
        ----------
        planes : ndarray, shape (J, k, 4)
            Per volume, k planes (w, o): a point x is inside where w·x ≥ o (w need not be unit;
            a row of zeros is no plane).
        count_only : bool
            Return only how many triangles each volume may hold (boxes wholly inside every plane
            counted whole, not opened): an upper bound on the candidates, for the planner.

        Returns
        -------
        (job, tri) : ndarray (Q,), ndarray (Q,) of int
            Candidate pairs: volume index and original triangle index, sorted by volume.
        or counts : ndarray (J,) of int, with ``count_only``.
        """
        planes = np.asarray(planes, np.float64)
        J = len(planes)
        if count_only:
            counts = np.zeros(J, np.int64)
        if not self.n or not J:
            return counts if count_only else (np.zeros(0, np.int64), np.zeros(0, np.int64))
        wx, wy, wz, o = (np.ascontiguousarray(planes[..., i]) for i in range(4))  # (J, k) each
        ax, ay, az = np.abs(wx), np.abs(wy), np.abs(wz)
        tol = _MARGIN * self.scale * (1.0 + np.sqrt(wx * wx + wy * wy + wz * wz))  # (J, k)
        lim = o - tol  # a point is outside a plane where w·x < o − tol
        jobs = np.repeat(np.arange(J), len(self.levels[0][0]))
        nodes = np.tile(np.arange(len(self.levels[0][0])), J)
        for depth, (lo, hi, cnt) in enumerate(self.levels):
            cx, cy, cz = (0.5 * (lo[:, i] + hi[:, i]) for i in range(3))
            ex, ey, ez = (0.5 * (hi[:, i] - lo[:, i]) for i in range(3))
            keep_j, keep_n = [], []
            for a in range(0, len(jobs), _STEP):
                j, nd = jobs[a : a + _STEP], nodes[a : a + _STEP]
                centre = wx[j] * cx[nd, None] + wy[j] * cy[nd, None] + wz[j] * cz[nd, None]
                reach = ax[j] * ex[nd, None] + ay[j] * ey[nd, None] + az[j] * ez[nd, None]
                out = np.any(centre + reach < lim[j], axis=1)
                if count_only:
                    inside = np.all(centre - reach > o[j] + tol[j], axis=1) & ~out
                    np.add.at(counts, j[inside], cnt[nd[inside]])
                    out |= inside
                keep_j.append(j[~out])
                keep_n.append(nd[~out])
            jobs, nodes = np.concatenate(keep_j), np.concatenate(keep_n)
            if depth + 1 < len(self.levels):
                n_next = len(self.levels[depth + 1][0])
                nodes = (nodes[:, None] * FANOUT + np.arange(FANOUT)).ravel()
                jobs = np.repeat(jobs, FANOUT)
                ok = nodes < n_next
                jobs, nodes = jobs[ok], nodes[ok]
            if not len(jobs):
                break
        if not len(jobs):
            return counts if count_only else (np.zeros(0, np.int64), np.zeros(0, np.int64))
        # leaves: each triangle against the planes (all three vertices outside one plane: culled)
        tj = np.repeat(jobs, LEAF)
        tt = (nodes[:, None] * LEAF + np.arange(LEAF)).ravel()
        ok = tt < self.n
        tj, tt = tj[ok], tt[ok]
        keep_j, keep_t = [], []
        V = self.tris
        for a in range(0, len(tj), _STEP):
            j, t = tj[a : a + _STEP], tt[a : a + _STEP]
            wxj, wyj, wzj, lj = wx[j], wy[j], wz[j], lim[j]
            out = np.ones(wxj.shape, bool)
            for v in range(3):
                out &= wxj * V[t, v, 0, None] + wyj * V[t, v, 1, None] + wzj * V[t, v, 2, None] < lj
            out = np.any(out, axis=1)
            keep_j.append(j[~out])
            keep_t.append(t[~out])
        tj, tt = np.concatenate(keep_j), np.concatenate(keep_t)
        if count_only:
            np.add.at(counts, tj, 1)
            return counts
        order = np.argsort(tj, kind="stable")
        return tj[order], self.original[tt[order]]


def outside_none(planes: np.ndarray, job: np.ndarray, tri: np.ndarray, tris: np.ndarray, scale: float) -> np.ndarray:
    """Per (job, triangle) pair: whether the triangle is not wholly outside one of the job's planes
    (by :meth:`OccluderIndex.cull`'s margin), shape (Q,)."""
    keep = np.zeros(len(job), bool)
    wx, wy, wz = (np.ascontiguousarray(planes[..., i]) for i in range(3))
    lim_all = planes[..., 3] - _MARGIN * scale * (1.0 + np.sqrt(wx * wx + wy * wy + wz * wz))  # per job, once
    for a in range(0, len(job), _STEP):
        j, t = job[a : a + _STEP], tri[a : a + _STEP]
        x, y, z = wx[j], wy[j], wz[j]
        lim = lim_all[j]
        out = np.ones(lim.shape, bool)
        for v in range(3):
            out &= x * tris[t, v, 0, None] + y * tris[t, v, 1, None] + z * tris[t, v, 2, None] < lim
        keep[a : a + _STEP] = ~np.any(out, axis=1)
    return keep


def reaching_pairs(planes: np.ndarray, job: np.ndarray, tri: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Per (job, triangle) pair: whether some of the triangle lies inside every one of the job's
    planes (it reaches into the job's hull), shape (Q,): the triangle clipped by each plane in turn
    (Sutherland–Hodgman) keeps at least three vertices. A triangle wholly outside the hull by more
    than rounding is out whichever planes culled it first, so this answer is the same after a
    per-receiver or a clustered cull."""
    from simulator.engine.visible import clip_halfplane

    keep = np.zeros(len(job), bool)
    for a in range(0, len(job), _STEP):
        j, t = job[a : a + _STEP], tri[a : a + _STEP]
        pl = planes[j]
        V = tris[t]
        # first the cheap test: wholly outside one plane (by more than rounding) is out
        out = np.zeros(len(t), bool)
        for k in range(pl.shape[1]):
            h = np.einsum("qvd,qd->qv", V, pl[:, k, :3]) - pl[:, k, 3:4]
            out |= np.all(h < -_MARGIN * np.abs(pl[:, k, 3:4]) - 1e-300, axis=1)
        pl, V, cnt, rows = pl[~out], V[~out], np.full(int((~out).sum()), 3), np.flatnonzero(~out)
        for k in range(pl.shape[1]):
            w, o = pl[:, k, :3], pl[:, k, 3]
            has = np.any(w != 0.0, axis=1)
            s = np.einsum("qvd,qd->qv", V, w) - o[:, None]
            V, cnt = clip_halfplane(V, cnt, np.where(has[:, None], s, 1.0))
            live = cnt >= 3
            if not live.all():  # clipped away: out
                pl, V, cnt, rows = pl[live], V[live], cnt[live], rows[live]
            V = V[:, : max(int(cnt.max()) if len(cnt) else 1, 1)]
        keep[a + rows] = cnt >= 3
    return keep


def cluster_planes(P: np.ndarray, N: np.ndarray, poly: np.ndarray, cnt: int, side: np.ndarray, starts: np.ndarray,
                   ends: np.ndarray) -> np.ndarray:  # fmt: skip
    """Half-spaces holding the hulls of every receiver in a cluster with one emitter polygon.

    Parameters
    ----------
    P, N : ndarray, shape (n, 3)
        Receivers and their unit normals, in cluster order; cluster c is ``starts[c]:ends[c]``, all
        its receivers on one side of the polygon's plane.
    poly : ndarray, shape (K, 3)
        The convex emitter polygon (first ``cnt`` vertices).
    side : ndarray, shape (C,)
        +1 or −1 per cluster: its receivers' side of the polygon's plane along its right-hand normal.

    Returns
    -------
    ndarray, shape (C, cnt + 3, 4)
        Planes (w, o), inside where w·x ≥ o (rows of zeros: no plane): the polygon's plane; the
        plane parallel to it through the farthest receiver; per edge, the plane through the edge
        that has every receiver on the polygon's side (through the corner of the receivers' box
        that turns it farthest out; none where the edge's line passes through the box); the
        horizon, where the receivers share a normal. Each receiver's own hull
        (:func:`pyramid_planes`) lies inside every one of them, so what a cluster's planes cull no
        receiver of it can need.
    """
    V = poly[:cnt]
    C = len(starts)
    centre = V.mean(axis=0)
    m0 = np.cross(V[1] - V[0], V[2] - V[0])
    m0 = m0 / np.linalg.norm(m0)
    m = side[:, None] * m0  # (C, 3) toward the receivers
    lo, hi = np.minimum.reduceat(P, starts), np.maximum.reduceat(P, starts)  # (C, 3)
    pick = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)])  # (8, 3)
    corners = np.where(pick[None] == 0, lo[:, None], hi[:, None])  # (C, 8, 3)
    out = np.zeros((C, cnt + 3, 4))
    out[:, 0, :3] = m
    out[:, 0, 3] = m @ centre
    out[:, 1, :3] = -m
    out[:, 1, 3] = -np.maximum.reduceat(np.einsum("pd,pd->p", P, np.repeat(m, ends - starts, axis=0)), starts)
    mag = 1.0 + float(np.abs(corners).max())
    for i in range(cnt):
        a, b = V[i], V[(i + 1) % cnt]
        w = np.cross(corners - a, b - a)  # (C, 8, 3): the planes through the edge and each corner
        w = np.where(((w @ (centre - a)) >= 0.0)[..., None], w, -w)
        tol = _MARGIN * np.linalg.norm(w, axis=2) * mag  # (C, 8)
        val = np.einsum("cvd,cud->cvu", w, corners - a)  # plane v at corner u
        ok = np.all(val >= -tol[:, :, None], axis=2)  # (C, 8)
        has = ok.any(axis=1)
        k = np.argmax(ok, axis=1)
        wk = w[np.arange(C), k]
        out[has, 2 + i, :3] = wk[has]
        out[has, 2 + i, 3] = wk[has] @ a
    same = np.all(np.abs(N - np.repeat(N[starts], ends - starts, axis=0)) <= 1e-12, axis=1)
    same_c = np.logical_and.reduceat(same, starts)
    n0 = N[starts]
    low = np.minimum.reduceat(np.einsum("pd,pd->p", P, np.repeat(n0, ends - starts, axis=0)), starts)
    out[same_c, -1, :3] = n0[same_c]
    out[same_c, -1, 3] = low[same_c]
    return out


#: the largest side of a cluster's cell, metres: receivers farther apart share little of their hulls
CLUSTER_CELL_M = 1.0


def cull_clustered(index: OccluderIndex, P: np.ndarray, N: np.ndarray, poly: np.ndarray, cnt: int,
                   cluster: int = 32) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """:meth:`OccluderIndex.cull` for many receivers (P, N) and one shared emitter polygon: receivers
    grouped by cells of :data:`CLUSTER_CELL_M` into clusters of at most ``cluster`` (in a cell, along a
    Morton curve), the hierarchy culled once per cluster
    by :func:`cluster_planes`, then each of the cluster's candidates tested against each receiver's
    own planes (:func:`outside_none`). Returns (receiver index, original triangle index) pairs sorted
    by receiver: every triangle that reaches into its hull (:func:`reaching_pairs`), and of the others
    at most those :meth:`OccluderIndex.cull` keeps for it (a cluster's planes may set aside a few more
    of those: which depends on the receivers it is grouped with, the readings only in rounding)."""
    from simulator.plan.bounds import _morton_order

    if not index.n or not len(P):
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    V = poly[:cnt]
    m = np.cross(V[1] - V[0], V[2] - V[0])
    side = np.where((P - V[0]) @ m >= 0.0, 1.0, -1.0)
    cell = np.floor((P - P.min(axis=0)) / CLUSTER_CELL_M).astype(np.int64)
    morton = np.empty(len(P), np.int64)
    morton[_morton_order(P)] = np.arange(len(P))
    order = np.lexsort((morton, cell[:, 2], cell[:, 1], cell[:, 0], side))  # by side, cell, then along the curve
    key = np.stack([side[order], *cell[order].T], axis=1)
    new = np.r_[True, np.any(key[1:] != key[:-1], axis=1)]
    group_start = np.maximum.accumulate(np.where(new, np.arange(len(P)), 0))
    new |= (np.arange(len(P)) - group_start) % cluster == 0  # at most ``cluster`` a cluster
    starts = np.flatnonzero(new)
    ends = np.r_[starts[1:], len(P)]
    cp = cluster_planes(P[order], N[order], poly, cnt, side[order[starts]], starts, ends)
    cj, ct = index.cull(cp)  # (cluster, original triangle)
    if not len(cj):
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    # every receiver of a cluster against the cluster's candidates, by its own planes
    size = ends - starts
    per = np.bincount(cj, minlength=len(starts))
    first = np.r_[0, np.cumsum(per)[:-1]]
    rec_rows = np.repeat(np.arange(len(starts)), size)  # cluster of each ordered receiver
    n_pairs = per[rec_rows]
    job = np.repeat(order, n_pairs)
    within = np.arange(int(n_pairs.sum())) - np.repeat(np.cumsum(n_pairs) - n_pairs, n_pairs)
    tri = ct[np.repeat(first[rec_rows], n_pairs) + within]
    planes = pyramid_planes(P, N, np.broadcast_to(poly, (len(P), *poly.shape)), np.full(len(P), cnt))
    keep = outside_none(planes, job, tri, index.tris_by_original(), index.scale)
    job, tri = job[keep], tri[keep]
    o = np.argsort(job, kind="stable")
    return job[o], tri[o]


def pyramid_planes(P: np.ndarray, N: np.ndarray | None, poly: np.ndarray, cnt: np.ndarray) -> np.ndarray:
    """The half-spaces bounding the hull of each receiver and its emitter polygon (and its horizon).

    Parameters
    ----------
    P : ndarray, shape (J, 3)
        Receivers, metres.
    N : ndarray, shape (J, 3), or None
        Their unit normals (the horizon plane), or None for no horizon plane.
    poly : ndarray, shape (J, K, 3)
        Convex planar emitter polygons, padded with copies of their last vertex.
    cnt : ndarray of int, shape (J,)

    Returns
    -------
    ndarray, shape (J, K + 2 (+ 1), 4)
        Planes (w, o), inside where w·x ≥ o: one through the receiver and each edge, the
        emitter's plane and the receiver's plane parallel to it (the slab between), the horizon.
    """
    J, K = poly.shape[:2]
    valid = np.arange(K)[None, :] < cnt[:, None]
    centre = np.sum(np.where(valid[:, :, None], poly, 0.0), axis=1) / cnt[:, None]
    nxt = np.take_along_axis(poly, ((np.arange(K)[None, :] + 1) % cnt[:, None])[:, :, None].repeat(3, axis=2), axis=1)
    w = cross3(poly - P[:, None], nxt - P[:, None])  # (J, K, 3): the plane through p, a_i, a_{i+1}
    inside = np.einsum("jkd,jd->jk", w, centre - P) >= 0.0
    w = np.where(inside[:, :, None], w, -w)
    w = np.where(valid[:, :, None], w, 0.0)
    o = np.einsum("jkd,jd->jk", w, P)
    m = np.sum(cross3(poly - centre[:, None], nxt - centre[:, None]), axis=1)
    m = np.where((np.einsum("jd,jd->j", m, P - centre) >= 0.0)[:, None], m, -m)  # toward the receiver
    planes = [np.concatenate([w, o[:, :, None]], axis=2),
              np.concatenate([m, np.einsum("jd,jd->j", m, centre)[:, None]], axis=1)[:, None],
              np.concatenate([-m, -np.einsum("jd,jd->j", m, P)[:, None]], axis=1)[:, None]]  # fmt: skip
    if N is not None:
        planes.append(np.concatenate([N, np.einsum("jd,jd->j", N, P)[:, None]], axis=1)[:, None])
    return np.concatenate(planes, axis=1)
