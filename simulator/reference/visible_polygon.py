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
hemisphere first (:func:`simulator.reference.closed_forms.polygon_irradiance`).
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

from simulator.reference.closed_forms import polygon_irradiance

__all__ = ["visible_polygon_irradiance", "lambert_rings"]

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


def _clip_halfspace(poly: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Sutherland–Hodgman: the part of ``poly`` where the signed value ``s`` > 0."""
    out = []
    k = len(poly)
    for i in range(k):
        a, b, sa, sb = poly[i - 1], poly[i], s[i - 1], s[i]
        if (sa > 0.0) != (sb > 0.0):
            out.append(a + (b - a) * (sa / (sa - sb)))
        if sb > 0.0:
            out.append(b)
    return np.asarray(out).reshape(-1, 3)


def lambert_rings(rings: list[np.ndarray], receivers: np.ndarray, P: np.ndarray, N: np.ndarray) -> np.ndarray:
    """Cosine-weighted solid angle ∫ cos θ dω of each ring (a simple planar polygon).

    Vectorised Lambert contour sums; rings that dip below a receiver's horizon
    are clipped to its hemisphere one by one (the closed form's own path).

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
    R = len(rings)
    out = np.zeros(R)
    if R == 0:
        return out
    counts = np.array([len(r) for r in rings])
    V = np.concatenate(rings)
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
    for i in np.nonzero(bad)[0]:  # crosses the horizon: clip (rare for ceiling lights)
        k = receivers[i]
        out[i] = float(polygon_irradiance(1.0, rings[i], P[k], N[k]))
    return out


def _clip_pair(tri: np.ndarray, s: np.ndarray, top: np.ndarray) -> np.ndarray:
    """Clip ``tri`` to ``s > 0`` (off the light's plane), then to ``top(q) > 0``
    (in front of the receiver's parallel plane)."""
    q = _clip_halfspace(tri, s)
    if len(q) < 3:
        return q
    return _clip_halfspace(q, top(q))


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
    if len(tris) and len(ids):
        Pi, ms, hi = P[ids], sgn[ids, None] * m, h[ids]
        # heights of the occluder vertices over the light's plane, toward each receiver: (S', T, 3)
        z = np.einsum("tkj,sj->stk", tris - c, ms)
        in_slab = ~(np.all(z <= slack, axis=2) | np.all(z >= hi[:, None, None] - slack, axis=2))
        # pyramid from each receiver to the light: drop triangles wholly outside one side plane
        centroid = light.mean(axis=0)
        for i in range(len(light)):
            a, b = light[i - 1], light[i]
            w = np.cross(a - Pi, b - Pi)  # (S', 3)
            inside = np.einsum("sj,sj->s", w, centroid - Pi) >= 0.0
            w = np.where(inside[:, None], w, -w)
            d = np.einsum("stkj,sj->stk", tris[None] - Pi[:, None, None, :], w)
            in_slab &= ~np.all(d < 0.0, axis=2)
        si, ti = np.nonzero(in_slab)
        if len(si):
            zz = z[si, ti]  # (M, 3)
            whole = np.all((zz > slack) & (zz < hi[si, None] - slack), axis=1)
            uv_list, owner = [], []
            # wholly inside the slab: project the three vertices at once
            if np.any(whole):
                q = tris[ti[whole]]  # (M', 3, 3)
                p = Pi[si[whole]][:, None, :]
                depth = hi[si[whole], None] - zz[whole]  # distance from the receiver's parallel plane
                x = p + (q - p) * (hi[si[whole], None] / depth)[:, :, None]
                uv = np.stack([(x - c) @ e1, (x - c) @ e2], axis=2)
                uv_list.extend(shapely.polygons(uv))
                owner.extend(si[whole])
            for k in np.nonzero(~whole)[0]:  # straddles a plane: clip it first
                s_ = si[k]
                tri = tris[ti[k]]
                top = lambda q, s_=s_: (hi[s_] - slack) - (q - c) @ ms[s_]
                q = _clip_pair(tri, zz[k] - slack, top)
                if len(q) < 3:
                    continue
                depth = hi[s_] - (q - c) @ ms[s_]
                x = Pi[s_] + (q - Pi[s_]) * (hi[s_] / depth)[:, None]
                uv_list.append(shapely.Polygon(np.stack([(x - c) @ e1, (x - c) @ e2], axis=1)))
                owner.append(s_)
            polys = np.array(uv_list, dtype=object)
            owner = np.array(owner, dtype=np.int64)
            polys = shapely.make_valid(polys)
            luv = shapely.Polygon(np.stack([(light - c) @ e1, (light - c) @ e2], axis=1))
            hit = shapely.intersection(polys, luv)
            keep = ~shapely.is_empty(hit) & (shapely.area(hit) > 0.0)
            hit, owner = hit[keep], owner[keep]
            rings, ring_rec, ring_sign = [], [], []
            order = np.argsort(owner, kind="stable")
            hit, owner = hit[order], owner[order]
            bounds = np.nonzero(np.diff(owner))[0] + 1
            shaded = []
            for group, o in zip(np.split(hit, bounds), np.split(owner, bounds)):
                if len(group) == 0:
                    continue
                k = ids[o[0]]
                shaded.append(k)
                # the visible part itself (not light − hidden): a fully hidden lamp reads exactly 0
                hidden = group[0] if len(group) == 1 else shapely.union_all(group)
                visible = shapely.difference(luv, hidden)
                for poly in getattr(visible, "geoms", [visible]):
                    if poly.geom_type != "Polygon" or poly.is_empty:
                        continue
                    for sign, ring in [(1.0, poly.exterior)] + [(-1.0, r) for r in poly.interiors]:
                        uv = np.asarray(ring.coords)[:-1]
                        if len(uv) >= 3:
                            rings.append(c + uv[:, :1] * e1 + uv[:, 1:] * e2)
                            ring_rec.append(k)
                            ring_sign.append(sign)
            shaded = np.array(shaded, dtype=np.int64)
            e[shaded] = 0.0
            if rings:
                vis = lambert_rings(rings, np.array(ring_rec), P, N) * np.array(ring_sign)
                np.add.at(e, np.array(ring_rec), vis)
    e = np.maximum(e, 0.0) * float(radiance)
    return float(e[0]) if single else e
