"""Exact direct irradiance from planar Lambertian emitters past occluders.

Measured quantity: the irradiance a receiver at ``p`` with normal ``n``
gets straight from an emitter of uniform radiance L (no reflection on the
way), counting only the part of the emitter it sees:

    E = L · ∫_{Ω_vis} cos θ dω,

computed without sampling (:mod:`.visible`: each candidate occluder's shadow
projected from the receiver onto the emitter's plane and subtracted from the
emitter, Lambert's contour formula on what is left), so penumbrae carry no
noise. The candidates come from a box hierarchy culled by the hull of the
receiver and the emitter (:mod:`.occluders`); there is no cap on them or on
the stage's triangles. Emitters read this way (:func:`exact_refusal`):

- RectLights (one polygon, emitting toward −Z);
- DiskLights, bounded: the visible parts of the inscribed and the
  circumscribed regular :data:`DISK_SIDES`-gons enclose the disk's own
  (E_in ≤ E ≤ E_out, the integrand being ≥ 0), so the reading is their mean
  and half their difference joins its error bound (π²/(2n²) = 7.5·10⁻⁵ of the disk's
  light at 256 sides);
- emissive triangles (a mesh light or ``emissiveColor``), edge-sharing
  coplanar pairs of equal radiance merged into convex quads, each one-sided
  unless ``doubleSided``;
- a uniform DomeLight: the sky is the faces of a half cube about the
  receiver (the top square and the upper halves of the four sides) far beyond
  the stage, whose visible parts are read the same way: the sky seen through
  openings, exactly.

Shaped lights (UsdLuxShapingAPI), point, sphere, cylinder and distant lights
and textured domes are not (their direct light stays sampled), nor is an
emitter a pane or a cut-out may stand before (``transmitting``: the kernels'
shadow rays pass those at their transmittance).

Surfaces within 2⁻²³ of the coordinates' magnitude of the emitter's plane or
the receiver's count as in that plane (:data:`simulator.engine.visible.PLANE_SLACK`):
a flush ceiling hides nothing, a sofa top a sensor lies on hides nothing, a
shade 0.1 mm below a lamp 300 m out still shadows it. The code shares nothing
with :mod:`simulator.reference.closed_forms`, which the tests check it against.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from simulator.engine.visible import PLANE_SLACK, visible_factors
from simulator.scene.model import LightKind

__all__ = ["PLANE_SLACK", "DISK_SIDES", "ExactDirect", "visible_polygon_irradiance", "exact_direct", "exact_refusal",
           "emissive_refusal", "transmitting", "rect_vertices", "record_polygons", "occluder_index", "covered_records"]

#: sides of the polygons that bound a DiskLight's visible part (the bound is ~π²/(2n²) of its light: 7.5e-5)
DISK_SIDES = 256

#: receivers × emitter polygons handled in one call of the visible-part code (memory: a few kB each)
_JOBS = 1 << 14


def rect_vertices(light) -> np.ndarray:
    """Corners of a RectLight, shape (4, 3), metres, wound counter-clockwise about +Z."""
    ex, ey = light.frame[:, 0], light.frame[:, 1]
    hx, hy = 0.5 * light.width * ex, 0.5 * light.height * ey
    c = np.asarray(light.position, float)
    return np.array([c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy])


def exact_refusal(light) -> str | None:
    """Why this light's direct light cannot be computed exactly, or None."""
    if light.kind not in (LightKind.RECT, LightKind.DISK, LightKind.DOME):
        return f"{light.name} is a {light.kind.name.lower()} light (only rect, disk and uniform dome lights are computed)"
    if light.shaping is not None:
        return f"{light.name} is shaped (UsdLuxShapingAPI)"
    if light.kind == LightKind.DOME and light.texture:
        return f"{light.name} is a textured DomeLight"
    return None


def emissive_refusal(geometry) -> str | None:
    """Why the emissive triangles' direct light cannot be computed exactly, or None (also None
    where nothing emits)."""
    g = geometry
    if not g.n_triangles:
        return None
    emits = np.any(g.emission > 0, axis=1)
    if emits.any() and g.surface_id is not None and np.any(g.surface_id[emits] >= 0):
        return "an emissive face has a modelled surface (a pane, a cut-out or a glossy lobe)"
    return None


def transmitting(geometry) -> np.ndarray:
    """Per triangle: whether it passes part of the light that meets it (a pane or a cut-out, a
    coverage texture), shape (T,): direct light past such a face stays sampled."""
    g = geometry
    out = np.zeros(g.n_triangles, bool)
    if g.has_surfaces:
        for k, s in enumerate(g.surfaces):
            if s.pane or s.coverage < 1.0:
                out |= g.surface_id == k
    if g.texture_id is not None:
        out |= g.texture_id >= 0
    return out


@dataclass
class ExactDirect:
    """Exact direct light of some sensors.

    Attributes
    ----------
    mean : ndarray, shape (S, 2)
        ``(W/m², lx)`` straight from the emitters computed (rows not read: 0).
    bound : ndarray, shape (S, 2)
        A bound on each reading's error: its float rounding, and a DiskLight's polygon bound.
    disk_bound : ndarray, shape (S, 2)
        The DiskLights' polygon bound alone (the part that is not rounding).
    covered : ndarray of bool, shape (S, R)
        Per sensor and light record (the scene's lights, then the emissive triangles as one):
        whether its direct light is in ``mean``.
    """

    mean: np.ndarray
    bound: np.ndarray
    covered: np.ndarray
    disk_bound: np.ndarray | None = None

    def __post_init__(self):
        if self.disk_bound is None:
            self.disk_bound = np.zeros_like(self.bound)


# ---------------------------------------------------------------- emitters as polygons


def _merge_quads(g, tris: np.ndarray) -> tuple[list[np.ndarray], np.ndarray]:
    """Emissive triangles as convex polygons: pairs sharing an edge, coplanar, of equal radiance and
    sides merged into quads (greedily, in index order). Returns (vertex index lists, (n, 3) or (n, 4)),
    and for each polygon its first triangle."""
    t = g.triangles[tris]
    pts = g.points
    n = np.cross(pts[t[:, 1]] - pts[t[:, 0]], pts[t[:, 2]] - pts[t[:, 0]])
    nn = np.linalg.norm(n, axis=1)
    unit = n / np.where(nn > 0, nn, 1.0)[:, None]
    edge_of = {}
    for i, tri in enumerate(t.tolist()):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            edge_of.setdefault((min(a, b), max(a, b)), []).append((i, k))
    used = np.zeros(len(t), bool)
    quads, first = [], []
    for i, tri in enumerate(t.tolist()):
        if used[i] or nn[i] <= 0:
            continue
        done = False
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            others = [x for x in edge_of[(min(a, b), max(a, b))] if x[0] != i]
            if len(others) != 1:
                continue
            j, kj = others[0]
            if used[j] or nn[j] <= 0 or tris[j] < tris[i]:
                continue
            ti, tj = tris[i], tris[j]
            if not (np.array_equal(g.emission[ti], g.emission[tj]) and g.two_sided[ti] == g.two_sided[tj]):
                continue
            if abs(float(unit[i] @ unit[j]) - 1.0) > 1e-12:
                continue
            tj_l = t[j].tolist()
            if tj_l[kj] != b or tj_l[(kj + 1) % 3] != a:  # the shared edge run the other way: same facing
                continue
            x = tj_l[(kj + 2) % 3]
            quad = [a, x, b, tri[(k + 2) % 3]]
            q = pts[quad]
            turn = np.cross(np.roll(q, -1, axis=0) - q, np.roll(q, -2, axis=0) - np.roll(q, -1, axis=0)) @ unit[i]
            if np.all(turn > 0):
                quads.append(quad)
                first.append(ti)
                used[i] = used[j] = True
                done = True
                break
        if not done and not used[i]:
            quads.append(tri)
            first.append(tris[i])
            used[i] = True
    return quads, np.asarray(first, np.int64)


@dataclass
class _Polygons:
    """One light record's emitter polygons: vertices (n, K, 3) padded, counts, radiance (n, 2), one-sided
    (n,), and how they combine: ``"sum"`` or ``"bound"`` (two polygons, inner and outer)."""

    V: np.ndarray
    cnt: np.ndarray
    radiance: np.ndarray
    one_sided: np.ndarray
    combine: str = "sum"


def _pad(polys: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    k = max(len(p) for p in polys)
    V = np.stack([np.concatenate([p, np.repeat(p[-1:], k - len(p), axis=0)]) for p in polys])
    return V, np.array([len(p) for p in polys], np.int64)


def record_polygons(scene, r: int) -> _Polygons | None:
    """Light record ``r``'s emitter polygons (the scene's lights, then the emissive triangles), wound
    so that the emitting side is the right-hand turn's; None for a dome (its faces are per receiver)."""
    if r < len(scene.lights):
        light = scene.lights[r]
        L = np.asarray(light.emission, float)[None]
        if light.kind == LightKind.RECT:
            V = rect_vertices(light)[::-1].copy()  # emits toward −Z: that side's turn
            return _Polygons(V[None], np.array([4]), L, np.array([True]))
        if light.kind == LightKind.DISK:
            n = DISK_SIDES
            a = 2.0 * np.pi * np.arange(n)[::-1] / n  # clockwise about +Z: emits toward −Z
            ring = np.cos(a)[:, None] * light.frame[:, 0] + np.sin(a)[:, None] * light.frame[:, 1]
            inner = light.position + light.radius * ring
            outer = light.position + (light.radius / np.cos(np.pi / n)) * ring
            return _Polygons(np.stack([inner, outer]), np.array([n, n]), np.repeat(L, 2, axis=0), np.array([True, True]),
                             "bound")  # fmt: skip
        return None
    g = scene.geometry
    tris = np.flatnonzero(np.any(g.emission > 0, axis=1))
    quads, first = _merge_quads(g, tris)
    V, cnt = _pad([g.points[q] for q in quads])
    return _Polygons(V, cnt, g.emission[first].astype(float), ~g.two_sided[first].astype(bool))


def _dome_faces(P: np.ndarray, N: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """The half cube about each receiver, ``reach`` metres out: (S, 5, 4, 3) polygons (the top square,
    then the upper halves of the four sides), each wound to face the receiver."""
    t1 = np.cross(N, np.where(np.abs(N[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]]))
    t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
    t2 = np.cross(N, t1)
    D = reach
    top = P[:, None] + D * N[:, None] + D * np.stack([-t1 - t2, t1 - t2, t1 + t2, -t1 + t2], axis=1)
    faces = [top]
    for a, b in ((t1, t2), (t2, -t1), (-t1, -t2), (-t2, t1)):  # a side's outward axis a, its width along b
        faces.append(P[:, None] + D * a[:, None] + D * np.stack([-b, b, b + N, -b + N], axis=1))
    return np.stack(faces, axis=1), np.full((len(P), 5), 4)


# ---------------------------------------------------------------- the occluder index, kept per geometry

_INDEX: dict = {}


def occluder_index(scene, subset: np.ndarray | None = None):
    """The scene's :class:`simulator.engine.occluders.OccluderIndex` (over ``subset`` of its triangles
    where given), kept for the scene's geometry object while it lives (the planner and the engine ask
    for the same one)."""
    from simulator.engine.occluders import OccluderIndex

    g = scene.geometry
    key = (id(g), g.n_triangles, None if subset is None else subset.tobytes())
    hit = _INDEX.get(key)
    if hit is not None and hit[0] is g:
        return hit[1]
    tris = g.points[g.triangles] if g.n_triangles else np.zeros((0, 3, 3))
    if subset is not None:
        tris = tris[subset]
    idx = OccluderIndex(tris)
    if len(_INDEX) > 8:
        _INDEX.clear()
    _INDEX[key] = (g, idx)
    return idx


# ---------------------------------------------------------------- per receiver and emitter


def _scene_scale(scene, P: np.ndarray) -> float:
    g = scene.geometry
    s = float(np.abs(g.points).max()) if g.n_triangles else 0.0
    return max(1.0, s, float(np.abs(P).max()) if len(P) else 0.0)


def _jobs_factors(scene, V, cnt, one_sided, P, N, rec, slack, trans_idx, shared: bool = False):
    """The visible-part factor (sr) and bound of each job (polygon V[k] at receiver rec[k]); and
    whether a transmitting face may stand in each job's way. ``shared``: every job has the same
    polygon (its receivers are then culled in clusters, :func:`simulator.engine.occluders.cull_clustered`)."""
    from simulator.engine.occluders import cull_clustered, pyramid_planes

    idx = occluder_index(scene)
    tris = idx.tris_by_original() if idx.n else np.zeros((0, 3, 3))
    F = np.zeros(len(rec))
    B = np.zeros(len(rec))
    blocked = np.zeros(len(rec), bool)
    if shared and len(rec):
        if trans_idx is not None:
            tj, _ = cull_clustered(trans_idx, P[rec], N[rec], V[0], int(cnt[0]))
            blocked[tj] = True
        oj, ot = cull_clustered(idx, P[rec], N[rec], V[0], int(cnt[0]))
        bounds = np.searchsorted(oj, np.arange(0, len(rec) + _JOBS, _JOBS))
        for i, a in enumerate(range(0, len(rec), _JOBS)):
            sl = slice(a, a + _JOBS)
            q = slice(bounds[i], bounds[i + 1])
            F[sl], B[sl] = visible_factors(V[sl], cnt[sl], P[rec[sl]], N[rec[sl]], oj[q] - a, tris[ot[q]], one_sided[sl], slack)
        return F, B, blocked
    for a in range(0, len(rec), _JOBS):
        sl = slice(a, a + _JOBS)
        p, n, v, c = P[rec[sl]], N[rec[sl]], V[sl], cnt[sl]
        planes = pyramid_planes(p, n, v, c)
        if trans_idx is not None:
            blocked[sl] = trans_idx.cull(planes, count_only=True) > 0
        oj, ot = idx.cull(planes)
        F[sl], B[sl] = visible_factors(v, c, p, n, oj, tris[ot], one_sided[sl], slack)
    return F, B, blocked


def _light_reaches(V, cnt, one_sided, P, N, rec) -> np.ndarray:
    """Jobs whose receiver can see some of the polygon: on its emitting side and not wholly below its
    horizon (a cheap test before the cull; the visible-part code would read 0 for the others)."""
    valid = np.arange(V.shape[1])[None, :] < cnt[:, None]
    d = V - P[rec][:, None]
    above = np.any(valid & (np.einsum("jkd,jd->jk", d, N[rec]) > 0.0), axis=1)
    m = np.cross(V[:, 1] - V[:, 0], V[:, 2] - V[:, 0])
    side = np.einsum("jd,jd->j", P[rec] - V[:, 0], m) > 0.0
    return above & (~one_sided | side)


def covered_records(scene) -> list[tuple[int, str | None]]:
    """Per light record (the scene's lights, then the emissive triangles if any): ``(r, why not)``, the
    reason None where its direct light can be computed."""
    out = [(r, exact_refusal(l)) for r, l in enumerate(scene.lights)]
    g = scene.geometry
    if g.n_triangles and np.any(g.emission > 0):
        out.append((len(scene.lights), emissive_refusal(g)))
    return out


def exact_direct(scene, sensors, sensor_ids: np.ndarray, light_mask: np.ndarray | None = None,
                 want: np.ndarray | None = None) -> ExactDirect:  # fmt: skip
    """Direct irradiance of irradiance sensors from the emitters that can be computed, exactly.

    Parameters
    ----------
    scene : simulator.scene.model.Scene
    sensors : list of Sensor
    sensor_ids : ndarray of int
        The sensors to read.
    light_mask : ndarray, shape (S, L) or (S, R), optional
        0 where light l cannot reach sensor s (culled: wholly behind it).
    want : ndarray of bool, shape (S, R), optional
        Per sensor, the light records to compute (default: every one :func:`covered_records`
        allows; records it does not allow are never computed).

    Returns
    -------
    ExactDirect
        A record a pane or a cut-out may stand before, for a sensor, is left out for it
        (``covered`` False there).
    """
    from simulator.engine import exact_memo

    n_l = len(scene.lights)
    allowed = [r for r, why in covered_records(scene) if why is None]
    n_rec = n_l + (1 if any(r == n_l for r, _ in covered_records(scene)) else 0)
    records = allowed if want is None else [r for r in allowed if r < want.shape[1] and want[:, r].any()]
    S = len(sensors)
    out = ExactDirect(np.zeros((S, 2)), np.zeros((S, 2)), np.zeros((S, n_rec), bool))
    ids = np.asarray(sensor_ids, np.int64)
    if not len(ids) or not records:
        return out
    P = np.array([sensors[i].position for i in ids], float)
    N = np.array([sensors[i].normal for i in ids], float)
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    g = scene.geometry
    scale = _scene_scale(scene, P)
    slack = PLANE_SLACK * scale
    trans = transmitting(g)
    trans_idx = occluder_index(scene, trans) if trans.any() else None
    tris_all = g.points[g.triangles] if g.n_triangles else np.zeros((0, 3, 3))
    scene_key = exact_memo.digest(tris_all, [scale, PLANE_SLACK], trans)
    for r in records:
        on = np.ones(len(ids), bool)
        if light_mask is not None and r < light_mask.shape[1]:
            on = light_mask[ids, r] != 0
        if want is not None:
            on &= want[ids, r]
        k = np.flatnonzero(on)
        if not len(k):
            continue
        polys = record_polygons(scene, r)
        if polys is None:  # a uniform dome: its half cube per receiver
            lo = g.points.min(axis=0) if g.n_triangles else np.zeros(3)
            hi = g.points.max(axis=0) if g.n_triangles else np.zeros(3)
            far = np.maximum(np.abs(P[k][:, None] - lo), np.abs(P[k][:, None] - hi)).max(axis=(1, 2)) if len(k) else 0
            reach = 4.0 * float(np.max(far) + 1.0)
            faces, fc = _dome_faces(P[k], N[k], reach)
            key = scene_key + exact_memo.digest(P[k], N[k], [reach])

            def dome():
                rec = np.repeat(np.arange(len(k)), 5)
                F, B, blocked = _jobs_factors(scene, faces.reshape(-1, 4, 3), fc.reshape(-1), np.zeros(len(rec), bool),
                                              P[k], N[k], rec, slack, trans_idx)  # fmt: skip
                return np.stack([np.add.reduceat(F, np.arange(0, len(rec), 5)), np.add.reduceat(B, np.arange(0, len(rec), 5)),
                                 np.logical_or.reduceat(blocked, np.arange(0, len(rec), 5)).astype(float)])  # fmt: skip

            F, B, blocked = exact_memo.factor(key, dome)
            emission = np.asarray(scene.lights[r].emission, float)
            ok = blocked == 0
            out.mean[ids[k[ok]]] += F[ok, None] * emission[None]
            out.bound[ids[k[ok]]] += B[ok, None] * emission[None]
            out.covered[ids[k[ok]], r] = True
            continue
        # jobs: each receiver against each of the record's polygons it can see
        n_p = len(polys.cnt)
        rec = np.repeat(np.arange(len(k)), n_p)
        pid = np.tile(np.arange(n_p), len(k))
        key = scene_key + exact_memo.digest(polys.V, polys.cnt, polys.one_sided, P[k], N[k])
        groups = np.unique(polys.radiance, axis=0) if polys.combine == "sum" else polys.radiance[:1]

        def compute():
            reach = _light_reaches(polys.V[pid], polys.cnt[pid], polys.one_sided[pid], P[k], N[k], rec)
            F = np.zeros(len(rec))
            B = np.zeros(len(rec))
            blocked = np.zeros(len(rec), bool)
            for q in range(n_p):  # each polygon with the receivers that can see it (culled in clusters)
                j = np.flatnonzero(reach & (pid == q))
                F[j], B[j], blocked[j] = _jobs_factors(scene, polys.V[pid[j]], polys.cnt[pid[j]], polys.one_sided[pid[j]],
                                                       P[k], N[k], rec[j], slack, trans_idx, shared=True)  # fmt: skip
            blocked_r = np.zeros(len(k), bool)
            np.logical_or.at(blocked_r, rec, blocked)
            if polys.combine == "bound":  # inner and outer polygons: the mean, half the gap in the bound
                fi, fo = F[pid == 0], F[pid == 1]
                bi, bo = B[pid == 0], B[pid == 1]
                return np.stack([0.5 * (fi + fo), 0.5 * (fo - fi) + np.maximum(bi, bo), blocked_r.astype(float),
                                 0.5 * (fo - fi)])[None]  # fmt: skip
            rows = []
            for L in groups:  # one factor per radiance: a change of intensity alone reuses them
                w = np.all(polys.radiance[pid] == L, axis=1)
                rows.append(np.stack([np.bincount(rec, F * w, len(k)), np.bincount(rec, B * w, len(k)), blocked_r.astype(float),
                                      np.zeros(len(k))]))  # fmt: skip
            return np.stack(rows)

        res = exact_memo.factor(key, compute)
        blocked = res[0, 2] != 0
        ok = ~blocked
        for L, (F, B, _, D) in zip(groups, res):
            out.mean[ids[k[ok]]] += F[ok, None] * L[None]
            out.bound[ids[k[ok]]] += B[ok, None] * L[None]
            out.disk_bound[ids[k[ok]]] += D[ok, None] * L[None]
        out.covered[ids[k[ok]], r] = True
    return out


def visible_polygon_irradiance(radiance, light, tris, P, N, one_sided_normal=None, length_scale_m=1.0):
    """Irradiance from the visible part of a uniform convex polygonal light past the triangles ``tris``.

    Parameters
    ----------
    radiance : float
        Radiance of the light, W m⁻² sr⁻¹ (or cd/m²).
    light : array_like, shape (V, 3)
        The light's vertices (a convex planar polygon), metres.
    tris : array_like, shape (T, 3, 3)
        Occluder triangles, metres: any that may block (those that cannot are set aside exactly).
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
    from simulator.engine.occluders import OccluderIndex, pyramid_planes

    light = np.asarray(light, float)
    tris = np.asarray(tris, float).reshape(-1, 3, 3)
    single = np.ndim(P) == 1
    P = np.atleast_2d(np.asarray(P, float))
    N = np.atleast_2d(np.asarray(N, float))
    N = N / np.linalg.norm(N, axis=1, keepdims=True)
    m = np.cross(light[1] - light[0], light[2] - light[0])
    one_sided = one_sided_normal is not None
    if one_sided and float(m @ np.asarray(one_sided_normal, float)) < 0.0:
        light = light[::-1].copy()  # wound so that the emitting side is the right-hand turn's
    J = len(P)
    V = np.broadcast_to(light, (J, *light.shape))
    cnt = np.full(J, len(light))
    scale = max(length_scale_m, float(np.abs(light).max()), float(np.abs(P).max()) if J else 0.0)
    oj, ot = OccluderIndex(tris).cull(pyramid_planes(P, N, V, cnt)) if len(tris) else (np.zeros(0, int), np.zeros(0, int))
    F, _ = visible_factors(V, cnt, P, N, oj, tris[ot], np.full(J, one_sided), PLANE_SLACK * scale)
    e = np.maximum(F, 0.0) * float(radiance)
    return float(e[0]) if single else e
