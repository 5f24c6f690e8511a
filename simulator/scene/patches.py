"""Surface patches for the path guide: every triangle cut into m × m
congruent sub-triangles, and the patch distribution a pilot's tallies give.

A triangle (a, b, c) is parametrised by (s, t), point = a + s·(b − a) +
t·(c − a), s, t ≥ 0, s + t ≤ 1. The barycentric grid of spacing 1/m cuts it
into m² congruent sub-triangles of area A/m²: in grid row j (t ∈ [j/m,
(j+1)/m)) cell i holds a *lower* sub-triangle (i, j), (i+1, j), (i, j+1)
and, when i + j ≤ m − 2, an *upper* one (i+1, j), (i, j+1), (i+1, j+1). Row
j holds 2(m − j) − 1 sub-triangles, so it starts at j·(2m − j), and the
sub-triangle's index within the triangle is

    k = j·(2m − j) + 2i + upper,        0 ≤ k < m².

The device twins of these maps are ``patch_index`` / ``patch_point`` in
:mod:`simulator.kernels.estimators`; this module is numpy only (the planner
reports the layout without Warp).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "TARGET_PATCH_M", "MAX_PATCHES", "MAX_M", "MAX_GUIDE_ENTRIES", "PatchLayout", "patch_layout", "patch_index_np",
    "source_rows", "concentration", "patch_distribution", "patch_distribution_rows",
]  # fmt: skip

#: target patch size (metres): a triangle's longest edge over this gives its m
TARGET_PATCH_M = 0.25
#: most patches a stage's guide may have; past it the patch size grows, and a
#: stage with more triangles than this gets no guide
MAX_PATCHES = 16384
#: most entries (rows × patches) of the per-source guide tables
MAX_GUIDE_ENTRIES = 1 << 22
#: most subdivisions per triangle edge (a 42 m ground triangle gets m = 64,
#: 0.66 m patches, rather than taking the whole budget)
MAX_M = 64


@dataclass(frozen=True)
class PatchLayout:
    """How a stage's triangles are cut into patches.

    Attributes
    ----------
    m : ndarray of int32, shape (T,)
        Subdivisions per edge of each triangle (m² patches each).
    offset : ndarray of int32, shape (T,)
        Index of each triangle's first patch.
    patch_tri : ndarray of int32, shape (N,)
        The triangle each patch lies on.
    patch_area_m2 : ndarray of float64, shape (N,)
        A_j = A_tri / m² (m²).
    patch_size_m : float
        The target patch size used (metres): ``TARGET_PATCH_M``, or larger
        when the stage needed more than ``MAX_PATCHES`` patches at it.
    reason : str
        One line for ``probesim plan``: the layout, or why there is no guide.
    """

    m: np.ndarray
    offset: np.ndarray
    patch_tri: np.ndarray
    patch_area_m2: np.ndarray
    patch_size_m: float
    reason: str

    @property
    def n_patches(self) -> int:
        return int(len(self.patch_tri))

    @property
    def usable(self) -> bool:
        """Whether the stage has a guide (some patch of positive area)."""
        return self.n_patches > 0 and bool(np.any(self.patch_area_m2 > 0))


def _subdivisions(edge_m: np.ndarray, h: float, max_m: int) -> np.ndarray:
    return np.clip(np.ceil(edge_m / h), 1, max_m).astype(np.int64)


def patch_layout(points: np.ndarray, triangles: np.ndarray, target_m: float = TARGET_PATCH_M,
                 cap: int = MAX_PATCHES, max_m: int = MAX_M) -> PatchLayout:  # fmt: skip
    """Cut each triangle into m² patches, m = ⌈longest edge / h⌉ (1 … ``max_m``).

    h is ``target_m`` when the total stays within ``cap``; otherwise the
    smallest h that fits (bisection: the total only falls as h grows). With
    more triangles than ``cap`` there is no guide (an empty layout).

    Parameters
    ----------
    points : ndarray, shape (V, 3)
        Vertices (metres).
    triangles : ndarray of int, shape (T, 3)
    target_m, cap, max_m
        Target patch size (m), most patches, most subdivisions per edge.
    """
    tris = np.asarray(triangles, np.int64).reshape(-1, 3)
    n_tri = len(tris)
    empty = np.zeros(0, np.int32)
    if n_tri == 0:
        return PatchLayout(empty, empty, empty, np.zeros(0), target_m, "no guide: the stage has no surfaces")
    if n_tri > cap:
        return PatchLayout(np.ones(n_tri, np.int32), np.zeros(n_tri, np.int32), empty, np.zeros(0), target_m,
                           f"no guide: {n_tri} triangles exceed the {cap}-patch cap")  # fmt: skip
    p = np.asarray(points, np.float64)[tris]  # (T, 3, 3)
    edge = np.max(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2), axis=1)
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    h = float(target_m)
    if np.sum(_subdivisions(edge, h, max_m) ** 2) > cap:
        lo, hi = h, max(h, float(edge.max()))  # at hi every m is 1: T ≤ cap patches
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if np.sum(_subdivisions(edge, mid, max_m) ** 2) > cap:
                lo = mid
            else:
                hi = mid
        h = hi
    m = _subdivisions(edge, h, max_m)
    counts = m * m
    offset = np.cumsum(counts) - counts
    patch_tri = np.repeat(np.arange(n_tri), counts)
    patch_area = np.repeat(area / counts, counts)
    n = int(counts.sum())
    grew = "" if h == target_m else f" (grown from {target_m:g} m to fit the {cap}-patch cap)"
    reason = f"surface guide: {n} patches of about {h:.2g} m{grew} on {n_tri} triangles"
    return PatchLayout(m.astype(np.int32), offset.astype(np.int32), patch_tri.astype(np.int32), patch_area, h, reason)


def patch_index_np(s: np.ndarray, t: np.ndarray, m: np.ndarray) -> np.ndarray:
    """The sub-triangle index k of the point (s, t) on a triangle cut m × m
    (see the module docstring); the numpy twin of the kernel's ``patch_index``."""
    m = np.asarray(m, np.int64)
    i = np.clip(np.floor(s * m).astype(np.int64), 0, m - 1)
    j = np.clip(np.floor(t * m).astype(np.int64), 0, m - 1)
    over = i + j > m - 1  # rounding past the hypotenuse: the last lower sub-triangle of the row
    i = np.where(over, m - 1 - j, i)
    upper = (~over) & (i + j <= m - 2) & ((s * m - i) + (t * m - j) >= 1.0)
    return j * (2 * m - j) + 2 * i + upper.astype(np.int64)


def source_rows(prim: np.ndarray, n_patches: int, per_prim: bool = True, max_entries: int = MAX_GUIDE_ENTRIES) -> tuple[np.ndarray, int]:
    """Which guide (row) a path vertex on each triangle samples from.

    Row 0 serves a path's first vertex (the sensor, or a radiance meter's
    first surface); a surface vertex uses the row of its prim (1 + prim
    index), so the guide from the ceiling holds what the pilot's paths found
    from the ceiling. Without ``per_prim``, or with more rows than
    ``max_entries`` / ``n_patches`` allows, every surface shares row 1.

    Returns
    -------
    tri_row : ndarray of int32, shape (T,)
    n_rows : int
    """
    prim = np.asarray(prim, np.int64)
    n_prims = int(prim.max()) + 1 if len(prim) else 0
    if per_prim and (1 + n_prims) * max(n_patches, 1) <= max_entries:
        return (1 + prim).astype(np.int32), 1 + n_prims
    return np.ones(len(prim), np.int32), 2


def patch_distribution_rows(tally: np.ndarray, layout: PatchLayout) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`patch_distribution` for each row of ``tally`` (R, N).

    Returns
    -------
    ids, cdf : ndarray, shape (K,)
        Each row's ids and CDF, concatenated.
    row_start : ndarray of int32, shape (R + 1,)
        Row r's entries are ``ids[row_start[r]:row_start[r + 1]]``.
    density : ndarray of float32, shape (R·N,)
        Row r's P_j/A_j at ``r·N + j``.
    """
    parts = [patch_distribution(t, layout) for t in np.asarray(tally).reshape(-1, layout.n_patches)]
    sizes = [len(p[0]) for p in parts]
    row_start = np.r_[0, np.cumsum(sizes)].astype(np.int32)
    ids = np.concatenate([p[0] for p in parts]).astype(np.int32)
    cdf = np.concatenate([p[1][: len(p[0])] for p in parts]).astype(np.float32)
    return ids, cdf, row_start, np.concatenate([p[2] for p in parts])


def concentration(tally: np.ndarray, layout: PatchLayout) -> float:
    """How much a tally concentrates light beyond area: D = A·Σ_j P_j²/A_j,
    P_j ∝ tally_j, A the area of the patches with P_j > 0 (1 when P ∝ area
    over them, as in a furnace, where cosine sampling is already ideal and a
    guide only adds the variance of its mixture weights; large when a few
    bright patches hold the light). 0 for an empty tally.

    Notes
    -----
    By Cauchy–Schwarz Σ P_j = 1 ≤ (Σ P_j²/A_j)·(Σ A_j), so D ≥ 1; it is the
    mean over the guide's own samples of its density relative to the
    uniform one, p_j·A = P_j·A/A_j."""
    t = np.where((np.asarray(tally, np.float64) > 0) & (layout.patch_area_m2 > 0), tally, 0.0)
    if not np.any(t > 0) or not np.all(np.isfinite(t)):
        return 0.0
    p = t / t.sum()
    live = p > 0
    return float(np.sum(p[live] ** 2 / layout.patch_area_m2[live]) * layout.patch_area_m2[live].sum())


def patch_distribution(tally: np.ndarray, layout: PatchLayout) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The patch sampler's tables from a pilot's per-patch tallies.

    P_j ∝ tally_j (patches with tally ≤ 0, or zero area, get P_j = 0).
    The sampler draws entry k of ``ids`` with probability cdf[k] − cdf[k−1]
    of the float32 ``cdf`` it reads, so the density it reports is formed from
    those same float32 differences: a patch whose share rounds away in the
    CDF is never drawn and gets density 0, and pdf and sampler agree.

    Returns
    -------
    ids : ndarray of int32, shape (K,)
        Patches with P_j > 0.
    cdf : ndarray of float32, shape (K,)
        Inclusive CDF over ``ids``; last entry 1.
    density : ndarray of float32, shape (N,)
        P_j / A_j per patch (m⁻²), the guide's area pdf on it.
    """
    n = layout.n_patches
    density = np.zeros(n, np.float32)
    w = np.where((np.asarray(tally, np.float64) > 0) & (layout.patch_area_m2 > 0), tally, 0.0)
    if n == 0 or not np.any(w > 0) or not np.all(np.isfinite(w)):
        return np.zeros(0, np.int32), np.ones(1, np.float32), density
    ids = np.flatnonzero(w > 0)
    cdf = np.cumsum(w[ids]).astype(np.float32)
    cdf = (cdf / cdf[-1]).astype(np.float32)
    cdf[-1] = np.float32(1.0)
    prob = np.diff(np.r_[np.float32(0.0), cdf].astype(np.float64))
    keep = prob > 0
    ids, cdf, prob = ids[keep], cdf[keep], prob[keep]
    density[ids] = (prob / layout.patch_area_m2[ids]).astype(np.float32)
    return ids.astype(np.int32), cdf, density
