"""Host rays through a stage: what a straight line passes, face by face, for the sun's direct light and the eye's view.

A ray from ``o`` along unit ``d`` meets every triangle on its way (Möller and
Trumbore, float64, all hits with t > :data:`T_MIN_M`). Each face it meets
passes a share of the light, as the kernels' shadow rays take it
(:func:`simulator.kernels.surfaces.pass_factor`;
docs/REFERENCES.md §Thin slab, §Coverage):

- a matte face: 0 (it is *opaque*: the ray ends there);
- a surface of coverage c that is not a pane (presence, a threshold): 1 − c;
- a pane of ``ior`` n and internal transmittance τ₀: (1 − c) + c·T(θ), T the
  thin slab's transmittance at the incidence θ (:func:`simulator.scene.surfaces.slab_rt`);
  on a closed pane mesh (``Geometry.solid_side`` ≠ 0) the face the ray
  enters by passes the whole slab's T and the face it leaves by passes 1;
- a translucent layer (0 < opacity o < 1): (1 − o)·T(θ).

:func:`cast` reports per ray the product of those shares over the faces
before the first opaque one (``before``), that first opaque face and its
distance, and the product over all faces when none is opaque (``through``,
0 otherwise): what reaches ``o`` from infinity along −d. An opacity texture
is read at its face's mean coverage (the host does not look texels up);
:func:`textured_faces` says whether a stage has any, for a note.

Pure numpy; chunks of rays keep the (rays × triangles) arrays small.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["T_MIN_M", "RayScene", "RayHits", "ray_scene", "cast", "has_surfaces", "textured_faces"]

#: a hit nearer than this (metres) along the ray is the origin's own surface, not an occluder
T_MIN_M = 1e-6
#: rays per chunk: (chunk × triangles) float64 arrays of a few MB
_CHUNK = 1024


@dataclass
class RayScene:
    """A stage's triangles and what each face passes (module docstring).

    Attributes
    ----------
    v0, e1, e2 : ndarray, shape (T, 3)
        First vertex and the two edges of each triangle.
    normal : ndarray, shape (T, 3)
        Unit geometric normals (the front face).
    matte : ndarray of bool, shape (T,)
        Opaque faces.
    coverage, ior, tau : ndarray, shape (T,)
        Per face, its surface's coverage (opacity of a translucent layer), index and internal transmittance.
    pane, layered : ndarray of bool, shape (T,)
    side : ndarray of int8, shape (T,)
        ``Geometry.solid_side`` (0 on open faces).
    prim : ndarray of int, shape (T,)
        Index into ``prim_names``.
    prim_names : list of str
    """

    v0: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    normal: np.ndarray
    matte: np.ndarray
    coverage: np.ndarray
    ior: np.ndarray
    tau: np.ndarray
    pane: np.ndarray
    layered: np.ndarray
    side: np.ndarray
    prim: np.ndarray
    prim_names: list


@dataclass
class RayHits:
    """Per ray (shape (N,) each): see :func:`cast`."""

    through: np.ndarray  #: share reaching the origin from infinity (0 if an opaque face is met)
    before: np.ndarray  #: share passed by the faces before the first opaque one
    face: np.ndarray  #: the first opaque face, −1 for none
    t: np.ndarray  #: its distance, metres (inf for none)


def has_surfaces(scene) -> bool:
    """Whether any face of ``scene`` is more than matte for a shadow ray (a pane, a layer, a coverage)."""
    g = scene.geometry
    return g.surface_id is not None and bool(np.any(np.asarray(g.surface_id) >= 0))


def textured_faces(scene) -> bool:
    """Whether some face's coverage comes from an opacity texture (read at its mean by these rays)."""
    g = scene.geometry
    return g.texture_id is not None and bool(np.any(np.asarray(g.texture_id) >= 0))


def ray_scene(scene) -> RayScene:
    """The :class:`RayScene` of a read stage (:class:`simulator.scene.model.Scene`)."""
    g = scene.geometry
    tri = np.asarray(g.points, np.float64)[np.asarray(g.triangles)]
    n_t = len(tri)
    v0 = tri[:, 0] if n_t else np.zeros((0, 3))
    e1 = (tri[:, 1] - v0) if n_t else np.zeros((0, 3))
    e2 = (tri[:, 2] - v0) if n_t else np.zeros((0, 3))
    nrm = np.cross(e1, e2)
    ln = np.linalg.norm(nrm, axis=1, keepdims=True)
    nrm = np.where(ln > 0, nrm / np.where(ln > 0, ln, 1.0), 0.0)
    matte = np.ones(n_t, bool)
    coverage = np.ones(n_t)
    ior = np.ones(n_t)
    tau = np.ones(n_t)
    pane = np.zeros(n_t, bool)
    layered = np.zeros(n_t, bool)
    if g.surface_id is not None:
        sid = np.asarray(g.surface_id)
        for k, s in enumerate(g.surfaces):
            m = sid == k
            if not m.any():
                continue
            coverage[m] = float(s.coverage)
            ior[m] = float(s.ior)
            tau[m] = float(s.tau)
            pane[m] = bool(s.pane)
            layered[m] = bool(s.layered)
            # a face passes light when it is a pane or a layer, or when its coverage leaves gaps
            matte[m] = not (s.pane or s.coverage < 1.0 or s.opacity_texture >= 0)
    side = np.zeros(n_t, np.int8) if g.solid_side is None else np.asarray(g.solid_side, np.int8)
    prim = np.asarray(g.prim) if len(g.prim) == n_t else np.zeros(n_t, np.int64)
    return RayScene(v0, e1, e2, nrm, matte, coverage, ior, tau, pane, layered, side, prim, list(g.prim_names))


def _pass_factors(rs: RayScene, faces: np.ndarray, cos_d: np.ndarray) -> np.ndarray:
    """The share each (face, cos d·n) passes (module docstring); ``faces`` and ``cos_d`` of one shape."""
    from simulator.scene.surfaces import slab_rt

    out = np.ones(faces.shape)
    pane = rs.pane[faces]
    if pane.any():
        f = faces[pane]
        c = cos_d[pane]
        t = np.empty(len(f))
        side = rs.side[f]
        entering = (c < 0.0) == (side > 0)
        # one slab formula per surface row (few of them): group by (ior, tau)
        keys = np.stack([rs.ior[f], rs.tau[f]], axis=1)
        for n_, tau0 in np.unique(keys, axis=0):
            m = (keys[:, 0] == n_) & (keys[:, 1] == tau0)
            _, tm = slab_rt(np.abs(c[m]), float(n_), float(tau0))
            t[m] = tm
        t = np.where((side != 0) & ~entering, 1.0, t)
        cov = rs.coverage[f]
        out[pane] = np.where(rs.layered[f], (1.0 - cov) * t, (1.0 - cov) + cov * t)
    gap = ~pane & ~rs.matte[faces]
    out[gap] = 1.0 - rs.coverage[faces[gap]]
    return out


def cast(rs: RayScene, origins: np.ndarray, dirs: np.ndarray) -> RayHits:
    """Cast N rays; ``origins`` (N, 3) or (3,), ``dirs`` (N, 3) or (3,) unit (broadcast to N)."""
    o = np.asarray(origins, np.float64)
    d = np.asarray(dirs, np.float64)
    n = max(len(o) if o.ndim == 2 else 1, len(d) if d.ndim == 2 else 1)
    o = np.broadcast_to(o, (n, 3))
    d = np.broadcast_to(d, (n, 3))
    through = np.ones(n)
    before = np.ones(n)
    face = np.full(n, -1, np.int64)
    tmin = np.full(n, np.inf)
    if len(rs.v0) == 0 or n == 0:
        return RayHits(through, before, face, tmin)
    for lo in range(0, n, _CHUNK):
        hi = min(lo + _CHUNK, n)
        oc, dc = o[lo:hi], d[lo:hi]
        pvec = np.cross(dc[:, None, :], rs.e2[None, :, :])  # (B, T, 3)
        det = np.einsum("tk,btk->bt", rs.e1, pvec)
        ok = np.abs(det) > 1e-14
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tvec = oc[:, None, :] - rs.v0[None, :, :]
        u = np.einsum("btk,btk->bt", tvec, pvec) * inv
        qvec = np.cross(tvec, rs.e1[None, :, :])
        v = np.einsum("bk,btk->bt", dc, qvec) * inv
        t = np.einsum("btk,tk->bt", qvec, rs.e2) * inv
        hit = ok & (u >= 0.0) & (v >= 0.0) & (u + v <= 1.0) & (t > T_MIN_M)
        t_opq = np.where(hit & rs.matte[None, :], t, np.inf)
        first = np.argmin(t_opq, axis=1)
        t_first = t_opq[np.arange(hi - lo), first]
        has = np.isfinite(t_first)
        face[lo:hi] = np.where(has, first, -1)
        tmin[lo:hi] = t_first
        passing = hit & ~rs.matte[None, :]
        if passing.any():
            b, f = np.nonzero(passing)
            cosd = np.einsum("ik,ik->i", dc[b], rs.normal[f])
            pf = _pass_factors(rs, f, cosd)
            share = np.ones((hi - lo, len(rs.v0)))
            share[b, f] = pf
            front = np.where(t < t_first[:, None], share, 1.0)
            before[lo:hi] = np.prod(front, axis=1)
            through[lo:hi] = np.where(has, 0.0, np.prod(share, axis=1))
        else:
            through[lo:hi] = np.where(has, 0.0, 1.0)
    return RayHits(through, before, face, tmin)
