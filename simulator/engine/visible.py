"""The visible part of planar emitters past occluders, by convex subtraction in the emitter's plane.

Measured quantity: for a receiver at ``p`` with unit normal ``n`` and a
planar convex emitter polygon ``A`` of uniform radiance, the geometric factor

    F = ∫_{Ω_vis} cos θ dω   (sr),

Ω_vis the solid angle of the part of ``A`` above the receiver's horizon that
no occluder hides; the irradiance is E = L·F.

How (all receivers at once, float64 numpy):

1. each occluder triangle that may stand between ``p`` and ``A`` (the
   caller's cull, :mod:`.occluders`) is clipped to the open slab between the
   emitter's plane and the receiver's parallel plane (what lies beyond the
   emitter or behind the receiver hides nothing) and projected centrally from
   ``p`` onto the emitter's plane: a convex polygon, its shadow;
2. in the plane's 2-D frame the emitter is clipped to the receiver's horizon
   (the half-plane n·(x − p) ≥ 0, a line in the emitter's plane) and each
   shadow to that convex polygon (shadows that miss it are dropped; one that
   covers it leaves nothing);
3. the visible region starts as that one convex piece, and each shadow, the
   largest first, is subtracted from every piece it overlaps: a convex
   piece C minus a convex shadow S with edges e_1..e_k is the disjoint
   union of C ∩ H_1ᶜ, C ∩ H_1 ∩ H_2ᶜ, … (H_i the inner half-plane of e_i),
   each convex, found by Sutherland–Hodgman clipping of all pieces at once;
4. F = Σ over the pieces of Lambert's contour integral (Arvo 1995; docs/REFERENCES.md
   §Visible part of an emitter):
   |Σ_i γ_i n·û_i| / 2, u_i the unit vectors from ``p`` to the piece's
   vertices, γ_i = ∠(u_i, u_{i+1}), û_i = normalize(u_i × u_{i+1}). The
   pieces are disjoint and above the horizon, so their integrals add.

No 2-D Boolean library is used: the pieces are convex at every step, so
clipping by half-planes is all the arithmetic there is. The work per
receiver grows with its shadows (one round per shadow, each a few
vectorised clips over every receiver's pieces), not with the scene.

Float error bound (:func:`visible_factors`, second output): the contour sum
of a piece with m edges is a sum of m terms each computed to a few units in
the last place; the pieces' vertices come from a few clips and a projection,
each within a few ulps of the coordinates' magnitude R; slivers thinner than
rounding are dropped (their area counted). With ε the float64 unit roundoff,
the bound is

    B = 64·ε·Σ|γ_i n·û_i|/2 + (A_dropped + 64·ε·R·perimeter) / h²,

h the receiver's height over the emitter's plane (the factor's density per
unit area of the plane, cos θ_r·cos θ_l/d², is at most 1/h²). It is far
below any sampled error (10⁻¹³ of F on the bundled rooms).

References
----------
.. [1] J. Arvo, "Applications of irradiance tensors to the simulation of
       non-Lambertian phenomena", SIGGRAPH 1995 (Lambert's formula for
       polygons).
.. [2] J. Stewart, S. Ghali, "Fast computation of shadow boundaries using
       spatial coherence and backprojections", SIGGRAPH 1994 (shadows of
       polygonal lights by projection from the receiver).
.. [3] I. E. Sutherland, G. W. Hodgman, "Reentrant polygon clipping",
       CACM 17(1), 1974.
"""

from __future__ import annotations

import numpy as np

from simulator.scene.vectors import cross3

__all__ = ["PLANE_SLACK", "clip_halfplane", "signed_area", "lambert_pieces", "visible_factors", "polygon_frame"]

#: relative slack, × the scene's coordinate magnitude, within which a surface
#: counts as lying *in* the emitter's plane or the receiver's (and so hides
#: nothing): stage points are float32 (``point3f``), each coordinate rounded
#: by up to 2⁻²⁴ of its magnitude, so two surfaces authored in one plane may
#: differ by 2⁻²³ of it. A ceiling around a flush luminaire, or a sofa top a
#: sensor lies on, is then in plane; a shade 0.1 mm below a lamp 300 m from
#: the origin (slack 36 µm there) still blocks it.
PLANE_SLACK = 2.0**-23

_EPS = float(np.finfo(np.float64).eps)
#: the error bound's factor on the unit roundoff (module docstring)
_ULPS = 64.0


def clip_halfplane(V: np.ndarray, cnt: np.ndarray, s: np.ndarray, lab: np.ndarray | None = None, new: int = -1):
    """Sutherland–Hodgman on many convex polygons at once: keep where ``s > 0``.

    Parameters
    ----------
    V : ndarray, shape (M, K, D)
        Vertices (any dimension D); row ``i`` uses its first ``cnt[i]``,
        padded with copies of its last.
    cnt : ndarray of int, shape (M,)
    s : ndarray, shape (M, K)
        A value linear in the point (a signed distance to a line or plane) at each vertex.
    lab : ndarray of int, shape (M, K), optional
        A label of the edge that starts at each vertex (the line it lies on); the clipped
        polygons' edges keep theirs and the new edge along the cut takes ``new``.

    Returns
    -------
    (W, cnt_out) or (W, cnt_out, lab_out) : ndarray (M, K + 1, D), ndarray (M,), ndarray (M, K + 1)
        The clipped polygons, padded with copies of their last vertex (zeros where empty).
    """
    M, K, D = V.shape
    idx = np.arange(K)
    valid = idx[None, :] < cnt[:, None]
    prev = (idx[None, :] - 1) % np.maximum(cnt[:, None], 1)  # wraps within each row's own count
    a = np.take_along_axis(V, prev[:, :, None], axis=1)
    sa = np.take_along_axis(s, prev, axis=1)
    ina, inb = sa > 0.0, s > 0.0
    cross = valid & (ina != inb)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(cross, sa / (sa - s), 0.0)
    q = a + (V - a) * t[:, :, None]
    # a vertex on the line is its own crossing, exactly (not within rounding of itself: an edge between
    # two copies of a point is then of length 0, no line, rather than a line of any direction)
    q = np.where((s == 0.0)[:, :, None], V, np.where((sa == 0.0)[:, :, None], a, q))
    pts = np.stack([q, V], axis=2).reshape(M, 2 * K, D)  # per edge: its crossing, then its end if inside
    keep = np.stack([cross, valid & inb], axis=2).reshape(M, 2 * K)
    pos = np.cumsum(keep, axis=1) - 1
    keep &= pos <= K  # a convex polygon cut by a line keeps at most K + 1 (rounding may find more)
    n_out = keep.sum(axis=1)
    W = np.zeros((M, K + 1, D))
    r, c = np.nonzero(keep)
    W[r, pos[r, c]] = pts[r, c]
    last_i = np.maximum(n_out - 1, 0)[:, None]
    pad = np.arange(K + 1)[None, :] >= n_out[:, None]
    W = np.where(pad[:, :, None], np.take_along_axis(W, last_i[:, :, None].repeat(D, axis=2), axis=1), W)
    if lab is None:
        return W, np.minimum(n_out, K + 1)
    # an entering crossing starts a stretch of the edge it lies on; a leaving one, the cut
    lq = np.where(inb, np.take_along_axis(lab, prev, axis=1), new)
    lp = np.stack([lq, lab], axis=2).reshape(M, 2 * K)
    L = np.full((M, K + 1), new, lab.dtype)
    L[r, pos[r, c]] = lp[r, c]
    return W, np.minimum(n_out, K + 1), L


def signed_area(V: np.ndarray) -> np.ndarray:
    """Shoelace area of padded 2-D polygons ``V`` (M, K, 2), positive counter-clockwise."""
    x, y = V[..., 0], V[..., 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)


def _perimeter(V: np.ndarray) -> np.ndarray:
    return np.sum(np.linalg.norm(np.roll(V, -1, axis=1) - V, axis=2), axis=1)


def _trim(V: np.ndarray, cnt: np.ndarray) -> np.ndarray:
    """Drop padding columns no row uses."""
    k = max(int(cnt.max()) if len(cnt) else 1, 1)
    return V[:, :k]


def polygon_frame(V: np.ndarray, cnt: np.ndarray):
    """Per polygon: centre, unit normal (Newell's, along the vertex order's right-hand turn), and an
    in-plane orthonormal pair (e1 along the first edge, e2 = m × e1).

    Parameters
    ----------
    V : ndarray, shape (J, K, 3)
        Planar polygons, padded with copies of the last vertex.
    cnt : ndarray, shape (J,)

    Returns
    -------
    c, m, e1, e2 : ndarray, shape (J, 3) each
    """
    valid = np.arange(V.shape[1])[None, :] < cnt[:, None]
    c = np.sum(np.where(valid[:, :, None], V, 0.0), axis=1) / cnt[:, None]
    m = np.sum(cross3(V - c[:, None], np.roll(V, -1, axis=1) - c[:, None]), axis=1)  # padding adds 0
    m /= np.linalg.norm(m, axis=1, keepdims=True)
    e1 = V[:, 1] - V[:, 0]
    e1 = e1 - np.sum(e1 * m, axis=1, keepdims=True) * m
    e1 /= np.linalg.norm(e1, axis=1, keepdims=True)
    return c, m, e1, cross3(m, e1)


def lambert_pieces(d: np.ndarray, N: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lambert's contour integral of convex polygons above their receivers' horizons.

    Parameters
    ----------
    d : ndarray, shape (M, K, 3)
        Each polygon's vertices relative to its receiver (metres), padded with copies of the last.
    N : ndarray, shape (M, 3)
        Each receiver's unit normal.

    Returns
    -------
    (F, A) : ndarray (M,), ndarray (M,)
        ∫ cos θ dω over each polygon (sr, ≥ 0), and Σ|γ_i n·û_i|/2, the scale of its rounding.
    """
    r = np.linalg.norm(d, axis=2)
    u = d / np.where(r > 0.0, r, 1.0)[:, :, None]
    w = np.roll(u, -1, axis=1)
    c = cross3(u, w)
    sin_g = np.linalg.norm(c, axis=2)
    gamma = np.arctan2(sin_g, np.sum(u * w, axis=2))
    proj = np.einsum("mkj,mj->mk", c, N) / np.where(sin_g > 0.0, sin_g, 1.0)
    term = np.where((sin_g > 0.0) & (r > 0.0) & (np.roll(r, -1, axis=1) > 0.0), gamma * proj, 0.0)
    return 0.5 * np.abs(term.sum(axis=1)), 0.5 * np.abs(term).sum(axis=1)


def _side(V: np.ndarray, g: np.ndarray) -> np.ndarray:
    """g·(v, 1) per vertex of ``V`` (M, K, 2), for one line g = (α, β, γ) per row (M, 3): the signed
    distance to the line αu + βv + γ = 0 where (α, β) is a unit vector, > 0 on the inner side."""
    return g[:, None, 0] * V[..., 0] + g[:, None, 1] * V[..., 1] + g[:, None, 2]


def _polygon_lines(V: np.ndarray, cnt: np.ndarray) -> np.ndarray:
    """The edge lines of convex counter-clockwise polygons ``V`` (M, K, 2) from their vertices,
    implicit and normalised, inner side positive: (M, K, 3); zeros (no line) past the count and for an
    edge shorter than 10⁻⁹ of its polygon's size, whose direction rounding may have turned any way
    (leaving a line out only enlarges the polygon its lines bound, by a sliver: what these lines
    serve, telling a shadow that misses the emitter and sizing it, stays on the safe side)."""
    K = V.shape[1]
    nxt = (np.arange(K)[None, :] + 1) % np.maximum(cnt[:, None], 1)
    d = np.take_along_axis(V, nxt[:, :, None].repeat(2, axis=2), axis=1) - V
    n = np.linalg.norm(d, axis=2)
    size = np.abs(V).max(axis=(1, 2))[:, None]
    ok = (np.arange(K)[None, :] < cnt[:, None]) & (n > 1e-9 * size)
    a = np.stack([-d[..., 1], d[..., 0]], axis=2) / np.where(n > 0.0, n, 1.0)[:, :, None]  # left normal
    g = np.concatenate([a, -np.sum(a * V, axis=2, keepdims=True)], axis=2)
    return np.where(ok[:, :, None], g, 0.0)


def _subtract(Pv, pc, pj, G, a_min):
    """Each convex piece (``Pv``, ``pc``; ``pj`` its job) minus a convex shadow given by its edge
    lines (``G`` (M, k, 3), implicit, the shadow on each line's positive side; a row of zeros is no
    line). C − S is the disjoint union of C ∩ H₁ᶜ, C ∩ H₁ ∩ H₂ᶜ, …

    Returns the pieces kept (lists of vertices, counts, jobs) and the slivers dropped (jobs, areas)."""
    keep_v, keep_c, keep_j, dropped = [], [], [], []
    rest_v, rest_c, rest_j = Pv, pc, pj
    for i in range(G.shape[1]):
        if not len(rest_c):
            break
        g = G[:, i]
        line = np.any(g[:, :2] != 0.0, axis=1)
        s = _side(rest_v, g)
        valid = np.arange(rest_v.shape[1])[None, :] < rest_c[:, None]
        lo = np.where(valid, s, np.inf).min(axis=1)
        hi = np.where(valid, s, -np.inf).max(axis=1)
        outside = line & (hi <= 0.0)  # wholly outside this edge: all of the rest stays visible
        cut = line & ~outside & (lo < 0.0)
        if outside.any():
            keep_v.append(_trim(rest_v[outside], rest_c[outside]))
            keep_c.append(rest_c[outside])
            keep_j.append(rest_j[outside])
        go = ~outside
        if cut.any():
            v, c, sj = rest_v[cut], rest_c[cut], s[cut]
            out_v, out_c = clip_halfplane(v, c, -sj)
            in_v, in_c = clip_halfplane(v, c, sj)
            area_out, area_in = signed_area(out_v), signed_area(in_v)
            big = (out_c >= 3) & (area_out > a_min)
            if big.any():
                keep_v.append(_trim(out_v[big], out_c[big]))
                keep_c.append(out_c[big])
                keep_j.append(rest_j[cut][big])
            small = (out_c >= 3) & ~big
            if small.any():
                dropped.append((rest_j[cut][small], np.abs(area_out[small])))
            ok_in = (in_c >= 3) & (area_in > a_min)
            small_in = (in_c >= 3) & ~ok_in
            if small_in.any():  # a sliver of the rest: dropped, whatever the later edges would do with it
                dropped.append((rest_j[cut][small_in], np.abs(area_in[small_in])))
            K = max(rest_v.shape[1], in_v.shape[1])
            new_v = np.concatenate([rest_v, np.repeat(rest_v[:, -1:], K - rest_v.shape[1], axis=1)], axis=1)
            rows = np.flatnonzero(cut)
            new_v[rows] = np.concatenate([in_v, np.repeat(in_v[:, -1:], K - in_v.shape[1], axis=1)], axis=1)
            rest_c = rest_c.copy()
            rest_c[rows] = in_c
            rest_v = new_v
            go[rows[~ok_in]] = False
        rest_v, rest_c, rest_j, G = rest_v[go], rest_c[go], rest_j[go], G[go]
        if len(rest_c):
            rest_v = _trim(rest_v, rest_c)
    # what is left after every edge lies inside the shadow: hidden
    return keep_v, keep_c, keep_j, dropped


def _concat(vs: list[np.ndarray], cs: list[np.ndarray], js: list[np.ndarray]):
    vs = [v for v in vs if len(v)]
    if not vs:
        return np.zeros((0, 3, 2)), np.zeros(0, np.int64), np.zeros(0, np.int64)
    k = max(v.shape[1] for v in vs)
    out = np.concatenate([np.concatenate([v, np.repeat(v[:, -1:], k - v.shape[1], axis=1)], axis=1) for v in vs])
    return out, np.concatenate([c for c in cs if len(c)]), np.concatenate([j for j in js if len(j)])


def _unit2(x: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(x, axis=-1, keepdims=True)
    return np.where(n > 0.0, x / np.where(n > 0.0, n, 1.0), 0.0)


def _shadow_lines(T, P, c, ms, e1, e2, h, slack) -> np.ndarray:
    """The five lines a shadow's edges may lie on, implicit in the emitter plane's (u, v) and
    normalised (unit (α, β)), unoriented: (Q, 5, 3). Labels 0–2: the images of the triangle's
    edges T_k T_k+1, the light plane's intersection with the plane through the receiver and the
    edge, whose normal is n = (T_k − p) × (T_k+1 − p): n·(c + u e1 + v e2 − p) = 0. Label 3: the
    triangle cut at the emitter's plane, n_T·(c + u e1 + v e2 − T_0) = 0 (a point of the plane is
    its own image). Label 4: the triangle cut at the receiver's side of the slab, height h − s:
    its image, through the plane of the pencil of the triangle's plane and that one that holds p,
    n_T·(c + u e1 + v e2 − T_0) + n_T·(p − T_0)·(h − s)/s = 0."""
    Q = len(T)
    out = np.empty((Q, 5, 3))
    for k in range(3):
        n = cross3(T[:, k] - P, T[:, (k + 1) % 3] - P)
        out[:, k] = np.stack([np.einsum("qd,qd->q", n, e1), np.einsum("qd,qd->q", n, e2),
                              np.einsum("qd,qd->q", n, c - P)], axis=1)  # fmt: skip
    nt = cross3(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    base = np.stack([np.einsum("qd,qd->q", nt, e1), np.einsum("qd,qd->q", nt, e2),
                     np.einsum("qd,qd->q", nt, c - T[:, 0])], axis=1)  # fmt: skip
    out[:, 3] = base
    out[:, 4] = base
    out[:, 4, 2] += np.einsum("qd,qd->q", nt, P - T[:, 0]) * (h - slack) / slack
    norm = np.linalg.norm(out[..., :2], axis=2, keepdims=True)
    return np.where(norm > 0.0, out / np.where(norm > 0.0, norm, 1.0), 0.0)


def visible_factors(light: np.ndarray, light_cnt: np.ndarray, P: np.ndarray, N: np.ndarray, occ_job: np.ndarray,
                    occ_tri: np.ndarray, one_sided: np.ndarray | None = None, slack: float = 0.0):  # fmt: skip
    """∫_{Ω_vis} cos θ dω of each job's emitter polygon at its receiver, and the float error bound.

    Parameters
    ----------
    light : ndarray, shape (J, K, 3)
        Each job's emitter: a convex planar polygon (metres), padded with copies of its last vertex.
    light_cnt : ndarray of int, shape (J,)
    P, N : ndarray, shape (J, 3)
        Each job's receiver position (metres) and unit normal.
    occ_job : ndarray of int, shape (Q,)
        The job each candidate occluder belongs to.
    occ_tri : ndarray, shape (Q, 3, 3)
        Candidate occluder triangles (metres): any that may stand between a receiver and its
        emitter; those that cannot are set aside exactly (a superset is fine).
    one_sided : ndarray of bool, shape (J,), optional
        The emitter emits only toward the side its vertex order's normal (right-hand turn)
        points to; default both sides.
    slack : float
        Metres within which a surface counts as in the emitter's plane or the receiver's
        (:data:`PLANE_SLACK` × the scene's coordinate magnitude).

    Returns
    -------
    (F, B) : ndarray (J,), ndarray (J,)
        The visible part's cosine-weighted solid angle (sr) and a bound on its float error (sr).

    Notes
    -----
    A shadow's edges are cut along lines found from the 3-D geometry, not from its clipped 2-D
    vertices (two of which may lie within rounding of each other, leaving the line between them
    with no direction to speak of): the image of an occluder edge AB is the light plane's
    intersection with the plane through the receiver and AB, direction ((A − p) × (B − p)) × m;
    an edge cut by a slab plane lies along (triangle normal) × m.
    """
    J = len(P)
    F = np.zeros(J)
    B = np.zeros(J)
    if J == 0:
        return F, B
    light = np.asarray(light, float)
    light_cnt = np.asarray(light_cnt, np.int64)
    P = np.asarray(P, float)
    N = np.asarray(N, float)
    c, m, e1, e2 = polygon_frame(light, light_cnt)
    h = np.einsum("jk,jk->j", P - c, m)
    front = np.abs(h) > slack
    if one_sided is not None:
        front &= ~np.asarray(one_sided, bool) | (h > 0.0)
    ms = np.where(h < 0.0, -1.0, 1.0)[:, None] * m  # from the emitter's plane toward the receiver
    h = np.abs(h)
    # 1. the emitter in 2-D (counter-clockwise in e1, e2), clipped to the receiver's horizon
    rel = light - c[:, None]
    uv = np.stack([np.einsum("jkd,jd->jk", rel, e1), np.einsum("jkd,jd->jk", rel, e2)], axis=2)
    hz = (np.einsum("jd,jd->j", c - P, N)[:, None] + uv[..., 0] * np.einsum("jd,jd->j", e1, N)[:, None]
          + uv[..., 1] * np.einsum("jd,jd->j", e2, N)[:, None])  # fmt: skip
    L2, Lc = clip_halfplane(uv, light_cnt, hz)
    front &= Lc >= 3
    if not front.any():
        return F, B
    L2 = _trim(L2, np.where(front, Lc, 1))
    size = float(np.abs(uv).max())  # the 2-D coordinates' magnitude
    scale = max(float(np.abs(light).max()), float(np.abs(P).max()), 1.0)  # the 3-D coordinates'
    slack = max(float(slack), PLANE_SLACK * scale)  # projections stay finite
    a_min = _ULPS * _EPS * size * size  # pieces thinner than rounding: dropped, their area in the bound
    # 2. shadows: clip to the open slab, project from the receiver
    occ_job = np.asarray(occ_job, np.int64).reshape(-1)
    occ_tri = np.asarray(occ_tri, float).reshape(-1, 3, 3)
    sel = front[occ_job] if len(occ_job) else np.zeros(0, bool)
    qj, qt = occ_job[sel], occ_tri[sel]
    if len(qj):
        z = np.einsum("qkd,qd->qk", qt - c[qj][:, None], ms[qj])
        keep = ~(np.all(z <= slack, axis=1) | np.all(z >= h[qj][:, None] - slack, axis=1))
        qj, qt, z = qj[keep], qt[keep], z[keep]
    if len(qj):
        lab0 = np.tile(np.arange(3), (len(qj), 1))
        q, qc, lab = clip_halfplane(qt, np.full(len(qj), 3), z, lab0, 3)  # exactly at the emitter's plane
        zq = np.einsum("qkd,qd->qk", q - c[qj][:, None], ms[qj])
        q, qc, lab = clip_halfplane(q, qc, (h[qj][:, None] - slack) - zq, lab, 4)  # the slack short of the receiver's
        ok = qc >= 3
        q, qc, lab, qj, qt = q[ok], qc[ok], lab[ok], qj[ok], qt[ok]
    if len(qj):
        p = P[qj]
        depth = h[qj][:, None] - np.einsum("qkd,qd->qk", q - c[qj][:, None], ms[qj])  # in (0, h)
        x = p[:, None] + (q - p[:, None]) * (h[qj][:, None] / depth)[:, :, None]
        rel = x - c[qj][:, None]
        S = np.stack([np.einsum("qkd,qd->qk", rel, e1[qj]), np.einsum("qkd,qd->qk", rel, e2[qj])], axis=2)
        # each edge's line, implicit in (u, v), from the 3-D geometry (Notes)
        G = _shadow_lines(qt, P[qj], c[qj], ms[qj], e1[qj], e2[qj], h[qj], slack)  # (Q, 5, 3) by label
        G = np.take_along_axis(G, lab[:, :, None].repeat(3, axis=2), axis=1)  # (Q, K, 3) per edge
        valid = np.arange(S.shape[1])[None, :] < qc[:, None]
        G = np.where(valid[:, :, None], G, 0.0)
        # orient: a convex polygon's vertices all lie on each edge line's inner side, so the sign of
        # their sum of values is that side (dominated by the vertex farthest from the line)
        tot = np.einsum("qkc,qlc->qk", G[..., :2], np.where(valid[:, :, None], S, 0.0)) + G[..., 2] * qc[:, None]
        G = np.where((tot < 0.0)[:, :, None], -G, G)
        # shadows that miss the emitter's piece: wholly outside one of its edges, or it wholly
        # outside one of theirs (the subtraction would keep every piece whole: dropped here for speed)
        LG = _polygon_lines(L2[qj], Lc[qj])  # (Q, KL, 3)
        tolm = _ULPS * _EPS * size
        s_of_S = np.einsum("qlc,qkc->qlk", LG[..., :2], S) + LG[..., 2][:, :, None]  # (Q, KL, K)
        s_of_S = np.where(valid[:, None, :], s_of_S, -np.inf)
        miss = np.any(np.any(LG[..., :2] != 0.0, axis=2) & (s_of_S.max(axis=2) < -tolm), axis=1)
        vL = np.arange(L2.shape[1])[None, :] < Lc[qj][:, None]
        s_of_L = np.einsum("qkc,qlc->qkl", G[..., :2], L2[qj]) + G[..., 2][:, :, None]  # (Q, K, KL)
        s_of_L = np.where(vL[:, None, :], s_of_L, -np.inf)
        miss |= np.any(np.any(G[..., :2] != 0.0, axis=2) & (s_of_L.max(axis=2) < -tolm), axis=1)
        # the order: the largest first, by the overlap of the shadow's box with the piece's (only
        # the order depends on it: big shadows first leave few pieces for the rest)
        big = 1e300
        s_lo = np.where(valid[:, :, None], S, big).min(axis=1)
        s_hi = np.where(valid[:, :, None], S, -big).max(axis=1)
        l_lo = np.where(vL[:, :, None], L2[qj], big).min(axis=1)
        l_hi = np.where(vL[:, :, None], L2[qj], -big).max(axis=1)
        ext = np.clip(np.minimum(s_hi, l_hi) - np.maximum(s_lo, l_lo), 0.0, None)
        area = ext[:, 0] * ext[:, 1]
        keep = ~miss & (qc >= 3)
        order = np.lexsort((-area[keep], qj[keep]))  # per job, the largest first
        SG, sj = G[keep][order], qj[keep][order]
        # each shadow's box within its piece's (a piece outside it is left whole without a clip)
        SB = np.concatenate([np.maximum(s_lo, l_lo), np.minimum(s_hi, l_hi)], axis=1)[keep][order]
    else:
        sj = np.zeros(0, np.int64)
    # 3. subtract the shadows, one per job per round, from every piece of that job
    jobs = np.flatnonzero(front)
    Pv, pc, pj = L2[jobs], Lc[jobs], jobs
    dropped_area = np.zeros(J)
    if len(sj):
        first = np.searchsorted(sj, np.arange(J))
        n_sh = np.bincount(sj, minlength=J)
        done_v, done_c, done_j = [], [], []  # pieces of jobs whose shadows are all subtracted
        for k in range(int(n_sh.max())):
            finished = n_sh[pj] <= k
            if finished.any():
                done_v.append(Pv[finished])
                done_c.append(pc[finished])
                done_j.append(pj[finished])
                Pv, pc, pj = Pv[~finished], pc[~finished], pj[~finished]
            if not len(pj):
                break
            idx = first[pj] + k
            # pieces whose box misses the shadow's keep whole, unclipped
            valid = np.arange(Pv.shape[1])[None, :] < pc[:, None]
            p_lo = np.where(valid[:, :, None], Pv, np.inf).min(axis=1)
            p_hi = np.where(valid[:, :, None], Pv, -np.inf).max(axis=1)
            box = SB[idx]
            on = np.all(p_lo < box[:, 2:], axis=1) & np.all(p_hi > box[:, :2], axis=1)
            if not on.any():
                continue
            kv, kc, kj, dr = _subtract(Pv[on], pc[on], pj[on], SG[idx[on]], a_min)
            for jj, aa in dr:
                np.add.at(dropped_area, jj, aa)
            Pv, pc, pj = _concat([Pv[~on]] + kv, [pc[~on]] + kc, [pj[~on]] + kj)
        Pv, pc, pj = _concat([Pv] + done_v, [pc] + done_c, [pj] + done_j)
    # 4. Lambert's formula on each piece, summed per job
    if len(pj):
        d = (c[pj] - P[pj])[:, None, :] + Pv[..., :1] * e1[pj][:, None, :] + Pv[..., 1:] * e2[pj][:, None, :]
        f, a_abs = lambert_pieces(d, N[pj])
        np.add.at(F, pj, f)
        np.add.at(B, pj, _ULPS * _EPS * (a_abs + scale * _perimeter(Pv) / h[pj] ** 2))
    B += dropped_area / np.where(h > 0.0, h, 1.0) ** 2
    F[~front] = 0.0
    return F, B
