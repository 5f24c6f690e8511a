"""Emissive geometry as pieces for next-event estimation.

The emissive light samples a *piece* first, then a triangle of the piece
∝ its power, then a point uniform on it (``kernels/lights/emissive.py``).
A piece is a compact group of one prim's emitting triangles, so that the
pick can weigh each by its own distance, orientation and learned
visibility: a window emitter most of which its wall hides from the room is
then sampled where the room sees it. Large triangles (a window quad is two)
are first cut on their barycentric grid into m × m congruent coplanar
sub-triangles (the surface and its emission are unchanged, so every reading
keeps its expectation), then each prim's triangles are split by the median
of their centroids along the longest axis until a piece's bounding box
diagonal is at most ``h``; ``h`` grows until there are at most
:data:`MAX_PIECES` pieces (a stage with more emitting prims than that has
its triangles split all together, prims aside).

All host-side numpy; the device upload is ``engine/device.py``'s.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from simulator.scene.model import Geometry
from simulator.scene.vectors import cross3

__all__ = ["MAX_PIECES", "PIECE_M", "PIECES_MIN_GAIN", "SPLIT_M", "EmitterPieces", "split_emitters", "emitter_cuts",
           "element_index", "emitter_pieces", "pieces_note"]

#: target size of a piece (bounding-box diagonal, metres) before the cap grows it
PIECE_M = 0.5
#: emitting triangles with a longer edge than this (metres) are cut
SPLIT_M = 1.0
#: most pieces: a receiver outside every cell of the pieces' table (engine.piece_table) weighs every
#: piece (a loop over them); in a cell the pick is a binary search of the cell's CDF
MAX_PIECES = 128
#: most subdivisions per edge of one emitting triangle
MAX_SPLIT = 16
#: pieces are kept where the pick pilot predicts that one piece would have at least this many times
#: their mean relative variance (engine.driver.Engine._choose_pieces); else the device scene goes back
#: to the stage's own triangles and one piece. The pieces cost 1.2× the CPU per sample on the emissive
#: office and 2.5× (cut triangles and the pieces' loop) on the furnace, whose predicted gains are
#: 2.2 and 1.24 (docs/DESIGN.md §Emissive geometry in pieces)
PIECES_MIN_GAIN = 1.5


@dataclass(frozen=True)
class EmitterPieces:
    """The pieces of a scene's emissive triangles.

    Attributes
    ----------
    tris : ndarray of int, shape (E,)
        Emitting triangles, grouped by piece (piece k is
        ``tris[first[k]:first[k] + count[k]]``).
    first, count : ndarray of int, shape (K,)
    prob : ndarray, shape (E,)
        Each triangle's share of its piece's power.
    centre : ndarray, shape (K, 3)
        Area-weighted centroid (m).
    normal : ndarray, shape (K, 3)
        Area-weighted mean unit normal (front faces); length 1 for a flat piece.
    area : ndarray, shape (K,)
        m².
    radiance : ndarray, shape (K,)
        Mean emitted radiance as W + lm/683 (the light pick's importance).
    reach : ndarray, shape (K,)
        Largest distance of a vertex from ``centre`` (m).
    two_sided : ndarray of bool, shape (K,)
        Some triangle of the piece emits from both faces.
    power_share : ndarray, shape (K,)
        The piece's share of all emitted power (the triangle shares' measure):
        P(k) of a pick ∝ power, which one piece amounts to.
    size_m : float
        The ``h`` used.
    """

    tris: np.ndarray
    first: np.ndarray
    count: np.ndarray
    prob: np.ndarray
    centre: np.ndarray
    normal: np.ndarray
    area: np.ndarray
    radiance: np.ndarray
    reach: np.ndarray
    two_sided: np.ndarray
    size_m: float
    power_share: np.ndarray | None = None

    @property
    def n(self) -> int:
        return int(len(self.first))


#: lumens per watt in the light pick's one number per light, W + lm/PICK_LM_PER_W (a sampling weight, as
#: in kernels/light_pick.py: any fixed scale between the channels serves, so it is not K_m's conversion)
PICK_LM_PER_W = 683.0


def _importance(emission: np.ndarray) -> np.ndarray:
    """W + lm/:data:`PICK_LM_PER_W` per row of (W, lm), the light pick's one number per light."""
    return np.maximum(emission[:, 0], 0.0) + np.maximum(emission[:, 1], 0.0) / PICK_LM_PER_W


def emitter_cuts(g: Geometry, h: float = SPLIT_M, max_m: int = MAX_SPLIT) -> np.ndarray:
    """Subdivisions per edge of each triangle of ``g``: m = ⌈longest edge/h⌉ ≤ ``max_m`` for an
    emitting one, 1 for the rest."""
    m = np.ones(g.n_triangles, np.int64)
    lit = np.flatnonzero(np.any(g.emission > 0, axis=1)) if g.n_triangles else np.zeros(0, np.int64)
    p = g.points[g.triangles[lit]]  # only emitters are cut: measure only their edges
    edge = np.max(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2), axis=1) if len(lit) else np.zeros(0)
    m[lit] = np.clip(np.ceil(edge / h), 1, max_m).astype(np.int64)
    return m


def element_index(orig: np.ndarray) -> np.ndarray:
    """Per triangle of :func:`split_emitters`' geometry, its index among the sub-triangles of its
    original: the patch index k = j·(2m − j) + 2i + upper of simulator.scene.patches (0 for a triangle
    not cut), since the sub-triangles of one original come together in that order."""
    first = np.full(int(orig.max()) + 1 if len(orig) else 0, -1, np.int64)
    idx = np.arange(len(orig))
    first[orig[::-1]] = idx[::-1]  # each original's first position
    return idx - first[orig]


def split_emitters(g: Geometry, h: float = SPLIT_M, max_m: int = MAX_SPLIT) -> tuple[Geometry, np.ndarray]:
    """``g`` with each emitting triangle longer than ``h`` (longest edge)
    cut into m × m coplanar sub-triangles, m = ⌈edge/h⌉ ≤ ``max_m``; the
    others as they are. Returns the geometry and, per new triangle, the
    original it came from. The emitter pieces are grouped over these
    sub-triangles; the device keeps ``g``'s own triangles and samples a
    sub-triangle as a patch of its original (kernels/lights/emissive.py)."""
    n_tri = g.n_triangles
    if n_tri == 0:
        return g, np.zeros(0, np.int64)
    m = emitter_cuts(g, h, max_m)
    if not (m > 1).any():
        return g, np.arange(n_tri)
    keep = m == 1
    points = [g.points]
    tris = [g.triangles[keep].astype(np.int64)]
    orig = [np.flatnonzero(keep)]
    bary = [np.broadcast_to(np.eye(3)[:, :2], (int(keep.sum()), 3, 2))]  # (b, c) weights of each new corner
    base = len(g.points)
    for t in np.flatnonzero(~keep):  # the split ones go after the rest, in order
        k = int(m[t])
        a, b, c = g.points[g.triangles[t]]
        # lattice nodes (i, j), i + j ≤ k: a + (i/k)(b − a) + (j/k)(c − a)
        ij = [(i, j) for j in range(k + 1) for i in range(k + 1 - j)]
        index = {node: base + n for n, node in enumerate(ij)}
        nodes = np.array([a + (i / k) * (b - a) + (j / k) * (c - a) for i, j in ij])
        points.append(nodes)
        base += len(ij)
        sub = []
        for j in range(k):
            for i in range(k - j):
                sub.append((index[(i, j)], index[(i + 1, j)], index[(i, j + 1)]))  # same winding as (a, b, c)
                if i + j <= k - 2:
                    sub.append((index[(i + 1, j + 1)], index[(i, j + 1)], index[(i + 1, j)]))
        tris.append(np.array(sub, np.int64))
        orig.append(np.full(len(sub), t))
        node_bc = np.array(ij, float) / k
        bary.append(node_bc[np.array(sub, np.int64) - (base - len(ij))])
    orig = np.concatenate(orig)

    def take(a):
        return None if a is None else np.asarray(a)[orig]

    out = replace(
        g, points=np.concatenate(points), triangles=np.concatenate(tris).astype(np.int32), albedo=g.albedo[orig],
        emission=g.emission[orig], two_sided=g.two_sided[orig],
        prim=g.prim[orig] if len(g.prim) == n_tri else g.prim, albedo_rgb=take(g.albedo_rgb),
        reflectance_id=take(g.reflectance_id), emission_rgb=take(g.emission_rgb),
        surface_id=take(g.surface_id), solid_side=take(g.solid_side), texture_id=take(g.texture_id),
        texture_uv=None if g.texture_uv is None else _corner_uv(g.texture_uv[orig], np.concatenate(bary)),
        shading_normals=None if g.shading_normals is None else  # linear over the triangle, as st (unit in the kernels)
        _corner_uv(g.shading_normals[orig].astype(np.float64), np.concatenate(bary)).astype(np.float32),
    )  # fmt: skip
    return out, orig


def _split_group(ids: np.ndarray, centroid: np.ndarray, lo: np.ndarray, hi: np.ndarray, h: float, out: list) -> None:
    """Median splits of ``ids`` along the longest axis of their triangles'
    bounding box until each group's diagonal is at most ``h``."""
    stack = [ids]
    while stack:
        g = stack.pop()
        box = hi[g].max(axis=0) - lo[g].min(axis=0)
        if len(g) == 1 or np.linalg.norm(box) <= h:
            out.append(g)
            continue
        axis = int(np.argmax(np.ptp(centroid[g], axis=0)))
        order = g[np.argsort(centroid[g, axis], kind="stable")]
        half = len(order) // 2
        stack += [order[half:], order[:half]]


def emitter_pieces(g: Geometry, h: float = PIECE_M, cap: int = MAX_PIECES) -> EmitterPieces | None:
    """The pieces of ``g``'s emitting triangles (None: none emit); ``h``
    grows ×1.5 until there are at most ``cap``."""
    emit = np.flatnonzero(np.any(g.emission > 0, axis=1)) if g.n_triangles else np.zeros(0, np.int64)
    if not len(emit):
        return None
    p = g.points[g.triangles[emit]]
    cr = cross3(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area = 0.5 * np.linalg.norm(cr, axis=1)
    unit = cr / np.maximum(2.0 * area, 1e-300)[:, None]
    sides = np.where(g.two_sided[emit], 2.0, 1.0)
    lum = _importance(g.emission[emit])
    power = area * lum * sides
    # a triangle's share of its piece: ∝ W emitted (lm where no triangle has W), as before pieces
    share_power = area * g.emission[emit, 0] * sides
    if share_power.sum() <= 0:
        share_power = area * g.emission[emit, 1]
    centroid = p.mean(axis=1)
    lo, hi = p.min(axis=1), p.max(axis=1)
    prim = g.prim[emit] if len(g.prim) == g.n_triangles else np.zeros(len(emit), np.int64)
    if len(np.unique(prim)) > cap:  # more emitting prims than pieces: split them all together
        prim = np.zeros(len(emit), np.int64)
    while True:
        groups: list = []
        for q in np.unique(prim):
            _split_group(np.flatnonzero(prim == q), centroid, lo, hi, h, groups)
        if len(groups) <= cap:
            break
        h *= 1.5
    order = np.concatenate(groups)
    count = np.array([len(x) for x in groups], np.int64)
    first = np.cumsum(count) - count
    piece_of = np.repeat(np.arange(len(groups)), count)
    a = area[order]
    pw = power[order]
    sp = share_power[order]
    total_a = np.bincount(piece_of, a, minlength=len(groups))
    total_pw = np.bincount(piece_of, pw, minlength=len(groups))
    piece_sp = np.bincount(piece_of, sp, minlength=len(groups))
    total_sp = piece_sp[piece_of]
    share = np.where(total_sp > 0, sp / np.where(total_sp > 0, total_sp, 1.0), a / np.maximum(total_a[piece_of], 1e-300))
    centre = np.stack([np.bincount(piece_of, a * centroid[order, k]) for k in range(3)], axis=1) / np.maximum(total_a, 1e-300)[:, None]
    normal = np.stack([np.bincount(piece_of, a * unit[order, k]) for k in range(3)], axis=1) / np.maximum(total_a, 1e-300)[:, None]
    reach = np.zeros(len(groups))
    np.maximum.at(reach, piece_of, np.max(np.linalg.norm(p[order] - centre[piece_of][:, None, :], axis=2), axis=1))
    two = np.bincount(piece_of, g.two_sided[emit][order].astype(np.float64)) > 0
    radiance = total_pw / np.maximum(np.bincount(piece_of, a * sides[order]), 1e-300)
    return EmitterPieces(
        tris=emit[order].astype(np.int64), first=first, count=count, prob=share, centre=centre, normal=normal,
        area=total_a, radiance=radiance, reach=reach, two_sided=two, size_m=float(h),
        power_share=piece_sp / piece_sp.sum() if piece_sp.sum() > 0 else total_a / total_a.sum(),
    )  # fmt: skip


def pieces_note(g: Geometry) -> str | None:
    """One line for ``probesim plan``: how emissive geometry is sampled (None: nothing emits)."""
    split, orig = split_emitters(g, SPLIT_M)
    pieces = emitter_pieces(split, PIECE_M, MAX_PIECES)
    if pieces is None:
        return None
    n_prims = len(np.unique(split.prim[pieces.tris])) if len(split.prim) == split.n_triangles else 1
    cut = split.n_triangles - g.n_triangles
    how = (f"{pieces.n} pieces of at most {pieces.size_m:.2g} m over {n_prims} emitting prim{'s' * (n_prims != 1)}"
           + (f" (large triangles sampled in {split.n_triangles} elements, patches of them: the hierarchy keeps "
              "the stage's triangles)" if cut else ""))
    if pieces.n == 1:
        return f"emissive geometry: {how}, a triangle picked ∝ its power"
    return (f"emissive geometry: {how}, a piece picked by the table of the receiver's cell (each piece's "
            "irradiance there, shadow rays measure it: engine.piece_table; elsewhere its estimated irradiance × a "
            "visibility a pilot learns), then an element ∝ its power; kept where that pilot predicts one piece would "
            f"have at least {PIECES_MIN_GAIN:g}× their relative variance, else one piece over the triangles uncut "
            "(the run record's emitter_pieces says which)")


def _corner_uv(uv: np.ndarray, bc: np.ndarray) -> np.ndarray:
    """Texture coordinates (T, 3, 2) of cut triangles: their original's corner ``uv`` (T, 3, 2) at the
    barycentric weights ``bc`` (T, 3, 2) of b and c of each new corner (st is linear over the triangle)."""
    b, c = bc[..., :1], bc[..., 1:]
    a0, a1, a2 = uv[:, None, 0], uv[:, None, 1], uv[:, None, 2]
    return a0 + b * (a1 - a0) + c * (a2 - a0)
