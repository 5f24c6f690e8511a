"""Lossless enclosures: closed surfaces of albedo 1 with light inside them (pure numpy).

A surface of albedo 1 absorbs nothing. Light that cannot escape a closed
surface of albedo 1 bounces for ever: the radiance inside grows without
bound (the furnace limit ``L_e / (1 - rho)`` at rho = 1), so no reading there
is finite. The kernels do not know that: their paths keep a throughput of 1
on such walls, never meet Russian roulette, and stop only at ``max_depth``
or at their 65,536-vertex cap, which gives a finite, meaningless number
after minutes of tracing. :func:`sealed_light` finds that case so the reader
can refuse it.

Method
------
The albedo-1 triangles are welded by position (to 1e-9 of the scene's
extent), split into connected components (shared vertices), and a
component is *closed* when every one of its edges is shared by an even
number of its triangles (a watertight surface). A light is *inside* a closed
component when a ray from it crosses the component an odd number of times
(the parity rule; the ray's direction is fixed and generic, so it grazes no
edge of an axis-aligned room). A closed component that emits itself, or
holds a light or an emitting triangle inside, seals that light in.

Open or not-quite-welded white surfaces (a room of separate quads whose
corners do not meet exactly, T-junctions) are not recognised: those rooms
still get the reader's albedo-1 warning only.
"""

from __future__ import annotations

import numpy as np

#: most albedo-1 triangles the check looks at (beyond that it is skipped; the warning remains)
MAX_CHECKED_TRIANGLES = 500_000

# a generic direction for the parity rays (not along any axis or diagonal)
_RAY = np.array([0.5377, 0.6133, 0.5786])
_RAY = _RAY / np.linalg.norm(_RAY)


def sealed_light(points: np.ndarray, triangles: np.ndarray, albedo: np.ndarray, emission: np.ndarray,
                 sources: list[tuple[str, np.ndarray]]) -> tuple[str, int] | None:
    """The first light sealed inside a closed albedo-1 surface, or None.

    Parameters
    ----------
    points : ndarray, shape (P, 3)
    triangles : ndarray, shape (T, 3)
    albedo : ndarray, shape (T,)
    emission : ndarray, shape (T, 2)
    sources : list of (name, position (3,))
        Lights at a finite place (not distant or dome lights).

    Returns
    -------
    (name, triangle) or None
        The sealed light's name (``"emissive surface"`` for emitting
        triangles) and one triangle (index into ``triangles``) of the
        enclosure around it.
    """
    white = np.flatnonzero(albedo >= 1.0)
    if len(white) == 0 or len(white) > MAX_CHECKED_TRIANGLES:
        return None
    tris = _welded(points, triangles[white])
    keep = (tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2]) & (tris[:, 0] != tris[:, 2])
    white, tris = white[keep], tris[keep]
    if len(tris) == 0:
        return None
    label = _components(tris)
    closed = _closed_components(tris, label)
    emitting = np.flatnonzero(np.any(emission > 0, axis=1))
    glowing = [("emissive surface", points[triangles[k]].mean(axis=0)) for k in emitting[:64]]
    for comp in closed:
        members = label == comp
        if np.any(np.any(emission[white[members]] > 0, axis=1)):
            return "emissive surface", int(white[members][0])
        tri_pts = points[triangles[white[members]]]
        for name, p in list(sources) + glowing:
            if _inside(np.asarray(p, float), tri_pts):
                return name, int(white[members][0])
    return None


def closed_shells(points: np.ndarray, triangles: np.ndarray) -> list[np.ndarray]:
    """Triangle indices (into ``triangles``) of each closed connected component of the whole soup.

    The same welding, components and closure test as :func:`sealed_light`
    applies to the albedo-1 triangles, on every triangle (degenerate ones
    left out); used by :mod:`simulator.scene.sanity` to tell a sensor inside
    a solid or outside a room.
    """
    if len(triangles) == 0:
        return []
    tris = _welded(points, np.asarray(triangles))
    keep = np.flatnonzero((tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2]) & (tris[:, 0] != tris[:, 2]))
    if len(keep) == 0:
        return []
    tris = tris[keep]
    label = _components(tris)
    return [keep[label == c] for c in _closed_components(tris, label)]


def _welded(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Triangle vertex ids after merging points that coincide (to 1e-9 of the extent)."""
    used = np.unique(tris)
    p = points[used]
    extent = float(np.max(np.abs(p))) if len(p) else 1.0
    q = max(1e-9 * extent, 1e-300)
    _, ids = np.unique(np.round(p / q).astype(np.int64), axis=0, return_inverse=True)
    remap = np.zeros(int(used.max()) + 1, np.int64)
    remap[used] = ids.ravel()
    return remap[tris]


def _components(tris: np.ndarray) -> np.ndarray:
    """Connected component label (T,) of triangles that share vertices (min-label propagation)."""
    n = int(tris.max()) + 1
    lab = np.arange(n)
    a = np.concatenate([tris[:, 0], tris[:, 1], tris[:, 2]])
    b = np.concatenate([tris[:, 1], tris[:, 2], tris[:, 0]])
    while True:
        m = np.minimum(lab[a], lab[b])
        new = lab.copy()
        np.minimum.at(new, a, m)
        np.minimum.at(new, b, m)
        new = new[new]  # pointer jumping: follow labels to their roots
        if np.array_equal(new, lab):
            break
        lab = new
    return lab[tris[:, 0]]


def _closed_components(tris: np.ndarray, label: np.ndarray) -> list[int]:
    """Labels of components all of whose edges are shared by an even number of their triangles."""
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1).astype(np.int64)
    owner = np.tile(label, 3)
    key = edges[:, 0] * (int(edges.max()) + 1) + edges[:, 1]  # one integer per edge: a 1-D unique, not a row-wise one
    _, inv, counts = np.unique(key, return_inverse=True, return_counts=True)
    odd = counts[inv.ravel()] % 2 == 1
    open_labels = set(np.unique(owner[odd]).tolist())
    return [int(c) for c in np.unique(label) if int(c) not in open_labels]


def _inside(p: np.ndarray, tri_pts: np.ndarray) -> bool:
    """Parity rule: a ray from ``p`` along ``_RAY`` crosses the triangles (N, 3, 3) an odd number of times.

    Möller-Trumbore intersection, all triangles at once.
    """
    v0, v1, v2 = tri_pts[:, 0], tri_pts[:, 1], tri_pts[:, 2]
    e1, e2 = v1 - v0, v2 - v0
    h = np.cross(_RAY, e2)
    det = np.einsum("ij,ij->i", e1, h)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = p - v0
    u = inv * np.einsum("ij,ij->i", s, h)
    qv = np.cross(s, e1)
    v = inv * (qv @ _RAY)
    t = inv * np.einsum("ij,ij->i", e2, qv)
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
    return bool(np.count_nonzero(hit) % 2)
