"""Exact direct irradiance from a uniform polygonal light seen past a few occluders.

Measured quantity: irradiance E (W/m², or lx in photometric units) at a
receiver ``p`` with normal ``n`` from a planar polygon of uniform radiance L,
counting only the part of the polygon that is visible from ``p``:

    E = L · ∫_{Ω_vis} cos θ dω,

with Ω_vis the solid angle of the light not hidden by any occluder. There is
no sampling, so there is no variance: penumbrae are exact.

How: every occluder triangle is clipped to the slab strictly between the
light's plane and the receiver (the part beyond the light or behind the
receiver hides nothing), then projected centrally from ``p`` onto the
light's plane. The union of those shadows, intersected with the light, is
the hidden part H. Lambert's contour formula is additive over regions, so
the visible part V = light − H (a set of polygons with holes) reads

    E = Σ_rings ± L·∫_ring cos θ dω

(exterior rings count +, holes −), each ring clipped to the receiver's
hemisphere first. The code shares nothing with
:mod:`simulator.reference.closed_forms`, which the tests check it against.
Computing V itself, rather than E(light) − E(H), keeps deep penumbrae free of
cancellation and makes a wholly hidden lamp read exactly 0.
The 2-D union and intersection are computed with Shapely (GEOS) in float64.

Cost grows with the number of occluders that reach the light's pyramid, so
the planner uses this only where that number is small; elsewhere shadow
rays sample the visibility.

References
----------
.. [1] J. Arvo, "Applications of irradiance tensors to the simulation of
       non-Lambertian phenomena", SIGGRAPH 1995 (Lambert's formula for
       polygons).
.. [2] J. Stewart, S. Ghali, "Fast computation of shadow boundaries using
       spatial coherence and backprojections", SIGGRAPH 1994 (shadows of
       polygonal lights by projection from the receiver).
"""

from __future__ import annotations

import numpy as np


__all__ = ["visible_polygon_irradiance", "lambert_rings", "clip_polygons", "exact_direct", "exact_refusal", "rect_vertices"]

#: relative slack, × the scene's coordinate magnitude, within which a surface
#: counts as lying *in* the light's plane or the receiver's (and so hides
#: nothing): stage points are float32 (``point3f``), each coordinate rounded
#: by up to 2⁻²⁴ of its magnitude, so two surfaces authored in one plane may
#: differ by 2⁻²³ of it. A ceiling around a flush luminaire, or a sofa top a
#: sensor lies on, is then in plane; a shade 0.1 mm below a lamp 300 m from
#: the origin (slack 36 µm there) still blocks it.
PLANE_SLACK = 2.0**-23


def _plane_frame(light: np.ndarray):
    c = light.mean(axis=0)
    m = np.cross(light[1] - light[0], light[2] - light[0])
    for i in range(3, len(light)):  # a longer cross product if the first is short
        mi = np.cross(light[i - 1] - light[0], light[i] - light[0])
        if np.linalg.norm(mi) > np.linalg.norm(m):
            m = mi
    m = m / np.linalg.norm(m)
    e1 = light[1] - light[0]
    e1 = e1 - (e1 @ m) * m
    e1 = e1 / np.linalg.norm(e1)
    e2 = np.cross(m, e1)
    return c, m, e1, e2


def _clip_convex_or_not(v: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Sutherland–Hodgman of one polygon ``v`` (any simple polygon) to ``s ≥ 0``.

    For a non-convex polygon the result may carry zero-width bridges along
    the cut; they add nothing to a contour integral."""
    out = []
    for i in range(len(v)):
        a, b, sa, sb = v[i - 1], v[i], s[i - 1], s[i]
        if (sa >= 0.0) != (sb >= 0.0):
            out.append(a + (b - a) * (sa / (sa - sb)))
        if sb >= 0.0:
            out.append(b)
    return np.asarray(out).reshape(-1, 3)


def _lambert_one(v: np.ndarray, n: np.ndarray) -> float:
    """∫ cos θ dω of one polygon ``v`` (receiver at the origin, above its horizon)."""
    if len(v) < 3:
        return 0.0
    r = np.linalg.norm(v, axis=1)
    v = v[r > 0.0]
    if len(v) < 3:
        return 0.0
    u = v / np.linalg.norm(v, axis=1)[:, None]
    w = np.roll(u, -1, axis=0)
    c = np.cross(u, w)
    sin_g = np.linalg.norm(c, axis=1)
    gamma = np.arctan2(sin_g, np.sum(u * w, axis=1))
    proj = np.where(sin_g > 0.0, (c @ n) / np.where(sin_g > 0.0, sin_g, 1.0), 0.0)
    return 0.5 * abs(float(np.sum(gamma * proj)))


def clip_polygons(V: np.ndarray, count: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Sutherland–Hodgman on many convex polygons at once: keep where ``s > 0``.

    Parameters
    ----------
    V : ndarray, shape (M, K, 3)
        Vertices; row ``i`` uses its first ``count[i]`` entries.
    count : ndarray of int, shape (M,)
    s : ndarray, shape (M, K)
        A signed value, linear in the point (a plane's signed distance), at each vertex.

    Returns
    -------
    (W, count_out) : ndarray (M, K + 1, 3), ndarray (M,)
        The clipped polygons (a convex K-gon cut by a plane has at most K + 1
        vertices), padded with their last vertex.
    """
    M, K = V.shape[:2]
    idx = np.arange(K)
    valid = idx[None, :] < count[:, None]
    prev = (idx[None, :] - 1) % np.maximum(count[:, None], 1)  # wraps within each row's own count
    a = np.take_along_axis(V, prev[:, :, None], axis=1)
    sa = np.take_along_axis(s, prev, axis=1)
    sb = s
    inside_a, inside_b = sa > 0.0, sb > 0.0
    cross = valid & (inside_a != inside_b)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(cross, sa / (sa - sb), 0.0)
    q = a + (V - a) * t[:, :, None]
    # per edge: [intersection if it crosses, the end vertex if inside], in order
    pts = np.stack([q, V], axis=2).reshape(M, 2 * K, 3)
    keep = np.stack([cross, valid & inside_b], axis=2).reshape(M, 2 * K)
    order = np.argsort(~keep, axis=1, kind="stable")
    pts = np.take_along_axis(pts, order[:, :, None], axis=1)[:, : K + 1]
    n_out = keep.sum(axis=1)
    last = np.take_along_axis(pts, np.maximum(n_out - 1, 0)[:, None, None].repeat(3, axis=2), axis=1)
    pad = np.arange(K + 1)[None, :] >= n_out[:, None]
    pts = np.where(pad[:, :, None], last, pts)
    return pts, np.minimum(n_out, K + 1)


def _rings_of(geoms: np.ndarray, owners: np.ndarray):
    """Flatten polygons to rings: ``(xy, counts, owner, sign)``, the rings' vertices one after another
    (each ring's closing point dropped; rings of fewer than 3 left out), shape (M, 2), the vertex
    count, owner and sign (+1 exterior, −1 hole) of each ring."""
    import shapely

    parts, part_idx = shapely.get_parts(geoms, return_index=True)
    parts_owner = owners[part_idx]
    poly = shapely.get_type_id(parts) == 3
    parts, parts_owner = parts[poly], parts_owner[poly]
    n_int = shapely.get_num_interior_rings(parts)
    rings = [shapely.get_exterior_ring(parts)]
    owner = [parts_owner]
    sign = [np.ones(len(parts))]
    for j in range(int(n_int.max()) if len(parts) else 0):
        has = n_int > j
        rings.append(shapely.get_interior_ring(parts[has], j))
        owner.append(parts_owner[has])
        sign.append(-np.ones(int(has.sum())))
    rings = np.concatenate(rings)
    owner = np.concatenate(owner)
    sign = np.concatenate(sign)
    xy, ring_id = shapely.get_coordinates(rings, return_index=True)
    if not len(xy):
        return np.zeros((0, 2)), np.zeros(0, np.int64), owner[:0], sign[:0]
    present, counts = np.unique(ring_id, return_counts=True)  # ring_id is sorted: rings in order
    counts = counts - 1  # the closing point
    closing = np.cumsum(counts + 1) - 1
    keep_pt = np.ones(len(xy), bool)
    keep_pt[closing] = False
    ok = counts >= 3
    keep_pt &= np.repeat(ok, counts + 1)
    return xy[keep_pt], counts[ok], owner[present][ok], sign[present][ok]


def lambert_rings(rings: list[np.ndarray], receivers: np.ndarray, P: np.ndarray, N: np.ndarray) -> np.ndarray:
    """Cosine-weighted solid angle ∫ cos θ dω of each ring (a simple planar polygon).

    Vectorised Lambert contour sums; rings that dip below a receiver's horizon
    are clipped to its hemisphere, all together (:func:`_lambert_clipped`,
    the bits of :func:`_clip_convex_or_not` and :func:`_lambert_one` one ring
    at a time).

    Parameters
    ----------
    rings : list of ndarray, shape (k_i, 3)
        Polygon vertices, metres.
    receivers : ndarray of int, shape (R,)
        Receiver index of each ring into ``P``, ``N``.
    P, N : ndarray, shape (S, 3)
        Receiver positions (metres) and unit normals.

    Returns
    -------
    ndarray, shape (R,)
        ∫ cos θ dω over each ring's spherical image, sr (≥ 0).

    Notes
    -----
    With u_i the unit vectors from the receiver to the vertices,
    γ_i = ∠(u_i, u_{i+1}) and û_i = normalize(u_i × u_{i+1}), the integral is
    |Σ_i γ_i · n·û_i| / 2 (Lambert; Arvo 1995).
    """
    if len(rings) == 0:
        return np.zeros(0)
    return _lambert_flat(np.concatenate(rings), np.array([len(r) for r in rings]), receivers, P, N)


def _lambert_flat(V: np.ndarray, counts: np.ndarray, receivers: np.ndarray, P: np.ndarray, N: np.ndarray) -> np.ndarray:
    """:func:`lambert_rings` of rings given one after another: ``V`` (M, 3), ``counts`` (R,) vertices each."""
    R = len(counts)
    out = np.zeros(R)
    if R == 0:
        return out
    ring_of = np.repeat(np.arange(R), counts)
    start = np.concatenate([[0], np.cumsum(counts)[:-1]])
    nxt = np.arange(len(V)) + 1
    last = start + counts - 1
    nxt[last] = start
    rec = receivers[ring_of]
    d = V - P[rec]
    below = np.einsum("ij,ij->i", d, N[rec]) < 0.0
    bad = np.zeros(R, bool)
    np.logical_or.at(bad, ring_of, below)
    r = np.linalg.norm(d, axis=1)
    u = d / np.where(r > 0.0, r, 1.0)[:, None]
    w = u[nxt]
    c = np.cross(u, w)
    sin_g = np.linalg.norm(c, axis=1)
    gamma = np.arctan2(sin_g, np.einsum("ij,ij->i", u, w))
    proj = np.einsum("ij,ij->i", c, N[rec]) / np.where(sin_g > 0.0, sin_g, 1.0)
    term = np.where((sin_g > 0.0) & (r > 0.0) & (r[nxt] > 0.0), gamma * proj, 0.0)
    out = 0.5 * np.abs(np.add.reduceat(term, start))
    crossing = np.flatnonzero(bad)  # crosses the horizon: clip to the hemisphere (rare for ceiling lights)
    if len(crossing):
        out[crossing] = _lambert_clipped(V, start, counts, receivers, crossing, P, N)
    return out


def _lambert_clipped(V, start, counts, receivers, which, P, N) -> np.ndarray:
    """:func:`_lambert_one` of :func:`_clip_convex_or_not` of each ring in ``which`` (relative to its
    receiver, clipped to its hemisphere), for all of them at once: the same operations on each ring,
    stacked (row-wise norms, cross products and dot products, one stacked ``matmul`` per ring for
    ``c @ n`` and each ring's sum by ``np.add.reduceat``), checked bit for bit against the loop."""
    k = counts[which]
    idx = np.repeat(start[which], k) + (np.arange(int(k.sum())) - np.repeat(np.cumsum(k) - k, k))
    rec = np.repeat(receivers[which], k)
    v = V[idx] - P[rec]
    ring = np.repeat(np.arange(len(which)), k)
    first = np.cumsum(k) - k
    sv = _ring_dot(v, ring, first, k, N[receivers[which]])  # v @ n, as the loop's matrix-vector product
    prev = np.arange(len(v)) - 1
    prev[first] = first + k - 1
    # Sutherland–Hodgman, keeping s ≥ 0: per edge (prev → this), its crossing, then its end if kept
    a, sa, b, sb = v[prev], sv[prev], v, sv
    cross = (sa >= 0.0) != (sb >= 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = a + (b - a) * np.where(cross, sa / (sa - sb), 0.0)[:, None]
    pts = np.stack([q, b], axis=1).reshape(-1, 3)
    keep = np.stack([cross, sb >= 0.0], axis=1).reshape(-1)
    owner = np.repeat(ring, 2)[keep]
    c_pts = pts[keep]
    # _lambert_one: drop vertices at the receiver, then rings of fewer than 3
    c_pts, owner = c_pts[np.linalg.norm(c_pts, axis=1) > 0.0], owner[np.linalg.norm(c_pts, axis=1) > 0.0]
    n_of = np.bincount(owner, minlength=len(which))
    live = n_of[owner] >= 3
    c_pts, owner = c_pts[live], owner[live]
    out = np.zeros(len(which))
    if not len(c_pts):
        return out
    present, n_k = np.unique(owner, return_counts=True)
    s0 = np.cumsum(n_k) - n_k
    nxt = np.arange(len(c_pts)) + 1
    nxt[s0 + n_k - 1] = s0
    u = c_pts / np.linalg.norm(c_pts, axis=1)[:, None]
    w = u[nxt]
    c = np.cross(u, w)
    sin_g = np.linalg.norm(c, axis=1)
    gamma = np.arctan2(sin_g, np.sum(u * w, axis=1))
    cn = _ring_dot(c, np.repeat(np.arange(len(present)), n_k), s0, n_k, N[receivers[which][present]])
    proj = np.where(sin_g > 0.0, cn / np.where(sin_g > 0.0, sin_g, 1.0), 0.0)
    out[present] = 0.5 * np.abs(_ring_sum(gamma * proj, s0, n_k))
    return out


def _ring_dot(x: np.ndarray, ring: np.ndarray, first: np.ndarray, k: np.ndarray, n: np.ndarray) -> np.ndarray:
    """``x[ring r] @ n[r]`` for every ring at once, through a stacked ``matmul`` over rings padded
    with zeros: per ring the bits of its own matrix-vector product (a product per row does not
    always give them)."""
    pad = np.zeros((len(k), int(k.max()), 3))
    pos = np.arange(len(x)) - first[ring]
    pad[ring, pos] = x
    return (pad @ n[:, :, None])[ring, pos, 0]


def _ring_sum(x: np.ndarray, first: np.ndarray, k: np.ndarray) -> np.ndarray:
    """``np.sum`` of each ring's run of ``x``, rings of one length together (numpy sums a row of n
    pairwise, as it does an array of n; ``np.add.reduceat`` sums in order, other bits)."""
    out = np.zeros(len(k))
    for n in np.unique(k):  # a few lengths, not one call per ring
        rows = np.flatnonzero(k == n)
        out[rows] = x[first[rows][:, None] + np.arange(n)].sum(axis=1)
    return out


def visible_polygon_irradiance(radiance, light, tris, P, N, one_sided_normal=None, length_scale_m=1.0):
    """Irradiance from the visible part of a uniform polygonal light.

    Parameters
    ----------
    radiance : float
        Radiance of the light, W m⁻² sr⁻¹ (or cd/m²).
    light : array_like, shape (V, 3)
        The light's vertices (a convex planar polygon), metres.
    tris : array_like, shape (T, 3, 3)
        Occluder triangles, metres: any that may block. Those that cannot
        (outside the pyramid from a receiver to the light, or not strictly
        between them) are set aside exactly.
    P, N : array_like, shape (S, 3) or (3,)
        Receiver positions (metres) and normals.
    one_sided_normal : array_like, shape (3,), optional
        The light emits only into the half-space this normal points into.
    length_scale_m : float
        The scene's size, metres (for :data:`PLANE_SLACK`).

    Returns
    -------
    ndarray, shape (S,) (or float for one receiver)
        Irradiance, W/m² (or lx).
    """
    import shapely

    light = np.asarray(light, float)
    tris = np.asarray(tris, float).reshape(-1, 3, 3)
    single = np.ndim(P) == 1
    P = np.atleast_2d(np.asarray(P, float))
    N = np.atleast_2d(np.asarray(N, float))
    N = N / np.linalg.norm(N, axis=1, keepdims=True)
    S = len(P)
    c, m, e1, e2 = _plane_frame(light)
    h = (P - c) @ m  # signed height of each receiver over the light's plane
    front = np.abs(h) > 0.0
    if one_sided_normal is not None:
        front &= h * (np.asarray(one_sided_normal, float) @ m) > 0.0
    sgn = np.where(h < 0.0, -1.0, 1.0)
    h = np.abs(h)
    ids = np.nonzero(front)[0]
    e = np.zeros(S)
    e[ids] = lambert_rings([light] * len(ids), ids, P, N)
    scale = max(length_scale_m, float(np.abs(c).max()), float(np.abs(P).max()) if S else 0.0)
    slack = PLANE_SLACK * scale
    ids = ids[(h[ids] > slack) & (e[ids] > 0.0)]
    if not (len(tris) and len(ids)):
        return _finish(e, radiance, single)
    Pi, ms, hi = P[ids], sgn[ids, None] * m, h[ids]
    # 1. candidates: heights of the occluder vertices over the light's plane, toward each
    #    receiver, (S', T, 3); keep triangles reaching into the open slab between them ...
    z = np.einsum("tkj,sj->stk", tris - c, ms)
    cand = ~(np.all(z <= slack, axis=2) | np.all(z >= hi[:, None, None] - slack, axis=2))
    # ... and not wholly outside one side plane of the pyramid from the receiver to the light
    centroid = light.mean(axis=0)
    for i in range(len(light)):
        w = np.cross(light[i - 1] - Pi, light[i] - Pi)  # (S', 3)
        w = np.where((np.einsum("sj,sj->s", w, centroid - Pi) >= 0.0)[:, None], w, -w)
        d = np.einsum("stkj,sj->stk", tris[None] - Pi[:, None, None, :], w)
        cand &= ~np.all(d < 0.0, axis=2)
    si, ti = np.nonzero(cand)
    if not len(si):
        return _finish(e, radiance, single)
    # 2. clip each to the open slab: exactly at the light's plane (a point on it
    #    projects onto itself), and ``slack`` short of the receiver's parallel plane,
    #    where the projection runs off to infinity (such far points never reach the
    #    light unless the occluder touches the receiver)
    zz = z[si, ti]
    q, cnt = clip_polygons(tris[ti], np.full(len(si), 3), zz)
    zq = np.einsum("mkj,mj->mk", q - c, ms[si])
    q, cnt = clip_polygons(q, cnt, (hi[si, None] - slack) - zq)
    ok = cnt >= 3
    q, cnt, si = q[ok], cnt[ok], si[ok]
    # 3. project centrally from the receiver onto the light's plane (2-D frame e1, e2)
    p = Pi[si][:, None, :]
    depth = hi[si, None] - np.einsum("mkj,mj->mk", q - c, ms[si])  # in (0, h): off the receiver's plane
    x = p + (q - p) * (hi[si, None] / depth)[:, :, None]
    uv = np.stack([(x - c) @ e1, (x - c) @ e2], axis=2)
    polys = shapely.polygons(uv)  # convex (padding repeats a vertex), so valid
    luv = shapely.Polygon(np.stack([(light - c) @ e1, (light - c) @ e2], axis=1))
    hit = shapely.intersection(polys, luv)
    keep = shapely.area(hit) > 0.0
    hit, si = hit[keep], si[keep]
    if not len(si):
        return _finish(e, radiance, single)
    # 4. per receiver: the visible part = light − union of its shadows
    order = np.argsort(si, kind="stable")
    hit, si = hit[order], si[order]
    cuts = np.flatnonzero(np.diff(si)) + 1
    owners = si[np.r_[0, cuts]]
    hidden = _union_per_receiver(hit, np.r_[0, cuts])
    visible = shapely.difference(luv, hidden)
    xy, counts, ring_owner, ring_sign = _rings_of(visible, owners)
    rec = ids[owners]
    e[rec] = 0.0  # recomputed from the visible part: a wholly hidden lamp reads exactly 0
    if len(counts):
        r3 = c + xy[:, :1] * e1 + xy[:, 1:] * e2  # back to 3-D, on the light's plane
        vis = _lambert_flat(r3, counts, ids[ring_owner], P, N) * ring_sign
        np.add.at(e, ids[ring_owner], vis)
    return _finish(e, radiance, single)


def _union_per_receiver(shadows: np.ndarray, starts: np.ndarray) -> np.ndarray:
    """The union of each receiver's shadows (``shadows[starts[k]:starts[k + 1]]``), one geometry per
    receiver: a lone shadow as it is, several by one GEOS unary union per receiver, all in one call
    (``union_all`` along the rows of a table padded with None, which it leaves out: the same
    collection, hence the same union, as a call per receiver)."""
    import shapely

    sizes = np.diff(np.r_[starts, len(shadows)])
    out = shadows[starts].copy()
    many = np.flatnonzero(sizes > 1)
    if len(many):
        table = np.full((len(many), int(sizes[many].max())), None, dtype=object)
        row = np.repeat(np.arange(len(many)), sizes[many])
        col = np.arange(len(row)) - np.repeat(np.cumsum(sizes[many]) - sizes[many], sizes[many])
        table[row, col] = shadows[np.repeat(sizes > 1, sizes)]
        out[many] = shapely.union_all(table, axis=1)
    return out


def _finish(e: np.ndarray, radiance, single: bool):
    e = np.maximum(e, 0.0) * float(radiance)
    return float(e[0]) if single else e


#: receivers × occluder triangles evaluated at once (memory: ~40 bytes each, per side plane)
_CHUNK_PAIRS = 1 << 21


def rect_vertices(light) -> np.ndarray:
    """Corners of a RectLight, shape (4, 3), metres, wound counter-clockwise about +Z."""
    ex, ey = light.frame[:, 0], light.frame[:, 1]
    hx, hy = 0.5 * light.width * ex, 0.5 * light.height * ey
    c = np.asarray(light.position, float)
    return np.array([c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy])


def exact_refusal(light) -> str | None:
    """Why this light's direct light cannot be read exactly, or None."""
    if light.kind.name != "RECT":
        return f"{light.name} is not a RectLight"
    if light.shaping is not None:
        return f"{light.name} is shaped (UsdLuxShapingAPI)"
    return None


def exact_direct(scene, sensors, sensor_ids: np.ndarray, light_mask: np.ndarray | None = None) -> np.ndarray:
    """Direct irradiance of irradiance sensors from every RectLight, exactly.

    Parameters
    ----------
    scene : simulator.scene.model.Scene
        Its lights must all be unshaped RectLights where ``light_mask`` is 1
        (the planner checks, :func:`exact_refusal`); emissive triangles are
        not counted.
    sensors : list of Sensor
    sensor_ids : ndarray of int
        The sensors to read.
    light_mask : ndarray, shape (S, L), optional
        1 where light l can reach sensor s (0: culled, wholly behind it).

    Returns
    -------
    ndarray, shape (S, 2)
        ``(radiometric, photometric)`` irradiance (W/m², lx); rows outside
        ``sensor_ids`` are 0.
    """
    out = np.zeros((len(sensors), 2))
    ids = np.asarray(sensor_ids, np.int64)
    if not len(ids):
        return out
    P = np.array([sensors[i].position for i in ids], float)
    N = np.array([sensors[i].normal for i in ids], float)
    from simulator.engine import exact_memo

    g = scene.geometry
    tris_all = g.points[g.triangles] if g.n_triangles else np.zeros((0, 3, 3))
    scale = max(1.0, float(np.abs(tris_all).max()) if len(tris_all) else 1.0)
    scene_key = exact_memo.digest(tris_all, [scale, PLANE_SLACK])  # the factors below depend on the lights, receivers and this
    for j, light in enumerate(scene.lights):
        on = np.ones(len(ids), bool) if light_mask is None else light_mask[ids, j] != 0
        if not on.any():
            continue
        why = exact_refusal(light)
        if why is not None:
            raise ValueError(f"exact direct light: {why}")
        V = rect_vertices(light)
        ez = light.frame[:, 2]
        # only what reaches in front of the emitting side (−ez) can stand between it and a receiver
        tris = tris_all[np.any((tris_all - light.position) @ -ez > 0.0, axis=1)] if len(tris_all) else tris_all
        k = np.flatnonzero(on)
        step = max(1, _CHUNK_PAIRS // max(len(tris), 1))
        for a in range(0, len(k), step):
            sel = k[a : a + step]
            key = scene_key + exact_memo.digest(V, ez, light.position, P[sel], N[sel])
            e = exact_memo.factor(key, lambda: visible_polygon_irradiance(1.0, V, tris, P[sel], N[sel], one_sided_normal=-ez,
                                                                          length_scale_m=scale))  # fmt: skip
            out[ids[sel]] += e[:, None] * np.asarray(light.emission, float)[None, :]
    return out
