"""Emissive geometry: one light record for all emitting triangles.

The triangles are grouped into pieces (:mod:`simulator.scene.emitters`:
one prim's triangles, large ones cut, split until compact). A sample picks
piece k with

    P(k | x) = (1 − α)·w_k/Σw + α·c_k/Σc,   w_k = ê_k(x)·f_k,

ê_k a cheap small-source estimate of the piece's unoccluded irradiance at
the receiver (:func:`piece_estimate`), f_k a factor a pilot learnt (Σ
shadowed value / Σ ê over its samples of the piece: mostly the share of it
the receivers see, so a window emitter behind its wall is sampled where it
is seen), c_k = 0 only where the piece lies wholly below the receiver's
horizon, α = :data:`PIECE_UNIFORM` (as the light pick's, light_pick.py);
then a triangle of the piece ∝ its power, then a point uniform in its area:
pdf P(k | x)·P(tri | k)·d²/(A·|cosθl|). A lone piece has P = 1 (the
triangle ∝ power over all of them, as before pieces). The record has no
shape of its own: the triangles are the scene's.

Where the engine built the pieces' table (``simulator.engine.piece_table``),
a receiver in one of its cells (a voxel of the stage and one of six normal
buckets, :func:`piece_cell`) picks piece k with that cell's own probability

    P(k | c) = (1 − α)·T_ck/Σ_j T_cj + α·π_k,

T_ck the piece's shadowed irradiance over the cell measured by rays, π_k its
share of the emitted power (> 0 for every piece, so any piece a receiver
sees keeps a probability): one binary search of the cell's CDF instead of a
pass over the pieces, and each cell's own visibility in place of one factor
per piece for the whole stage. Receivers outside every cell keep the pick
above. The cell is a function of (p, n) alone, so a sample and the pdf of
the same direction read the same P.
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..sampling import patch_index, patch_point, sample_triangle_bary
from .base import LightKernel, LightRec, LightSample, SceneRec, empty_sample, tri_emitted, tri_params, tri_vertex

#: the uniform share α of the piece pick (the light pick's, kernels/light_pick.py)
PIECE_UNIFORM = wp.constant(0.1)
_PI = wp.constant(3.14159265358979)


# -- the tables (SceneRec.emit_ints, emit_floats; their layout is written beside those fields)


@wp.func
def emit_base(scene: SceneRec, tri: int) -> int:
    """Triangle ``tri``'s first element, −1 when it emits nothing."""
    return scene.emit_ints[tri]


@wp.func
def emit_m(scene: SceneRec, tri: int) -> int:
    """Triangle ``tri``'s cut: its elements are its m × m patches (1: the triangle itself)."""
    return scene.emit_ints[scene.n_emit_tris + tri]


@wp.func
def elem_tri(scene: SceneRec, e: int) -> int:
    """Element e's triangle."""
    return scene.emit_ints[2 * scene.n_emit_tris + e]


@wp.func
def elem_piece(scene: SceneRec, e: int) -> int:
    """Element e's piece."""
    return scene.emit_ints[2 * scene.n_emit_tris + scene.n_elems + e]


@wp.func
def piece_entry(scene: SceneRec, i: int) -> int:
    """Entry i of the elements grouped by piece."""
    return scene.emit_ints[2 * scene.n_emit_tris + 2 * scene.n_elems + i]


@wp.func
def piece_first(scene: SceneRec, k: int) -> int:
    """Piece k's first entry among the grouped elements."""
    return scene.emit_ints[2 * scene.n_emit_tris + 3 * scene.n_elems + k]


@wp.func
def piece_count(scene: SceneRec, k: int) -> int:
    """Piece k's number of elements."""
    return scene.emit_ints[2 * scene.n_emit_tris + 3 * scene.n_elems + scene.n_pieces + k]


@wp.func
def cell_slot(scene: SceneRec, g: int) -> int:
    """Grid slot g's cell, −1 for none."""
    return scene.emit_ints[2 * scene.n_emit_tris + 3 * scene.n_elems + 2 * scene.n_pieces + g]


@wp.func
def elem_prob(scene: SceneRec, e: int) -> float:
    """Element e's share of its piece's power."""
    return scene.emit_floats[e]


@wp.func
def piece_cdf(scene: SceneRec, i: int) -> float:
    """The inclusive CDF over each piece's elements, at entry i of the grouped elements."""
    return scene.emit_floats[scene.n_elems + i]


@wp.func
def piece_factor(scene: SceneRec, k: int) -> float:
    """Piece k's learned factor (a pilot's; 1 before)."""
    return scene.emit_floats[2 * scene.n_elems + k]


@wp.func
def piece_power(scene: SceneRec, k: int) -> float:
    """Piece k's share of the emitted power, π_k (a pick ∝ power's)."""
    return scene.emit_floats[2 * scene.n_elems + scene.n_pieces + k]


@wp.func
def piece_vec3(scene: SceneRec, k: int, at: int) -> wp.vec3:
    """Floats ``at`` … ``at`` + 2 of piece k's ten: its centre (0) or mean front normal (3)."""
    i = 2 * scene.n_elems + 2 * scene.n_pieces + 10 * k + at
    return wp.vec3(scene.emit_floats[i], scene.emit_floats[i + 1], scene.emit_floats[i + 2])


@wp.func
def piece_shape(scene: SceneRec, k: int) -> wp.vec4:
    """Piece k's (area m², radiance W + lm/683, reach m, two-sided 0/1)."""
    i = 2 * scene.n_elems + 2 * scene.n_pieces + 10 * k + 6
    return wp.vec4(scene.emit_floats[i], scene.emit_floats[i + 1], scene.emit_floats[i + 2], scene.emit_floats[i + 3])


@wp.func
def cell_header(scene: SceneRec) -> int:
    """Where the table's floats begin: the grid's lowest corner (3) and 1/spacing, then the cells' CDFs
    and totals."""
    return 2 * scene.n_elems + 12 * scene.n_pieces


@wp.func
def piece_estimate(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(ê, c) of piece k at the receiver (p, n): ê = L̄·A·cosθl·cosθ/d² (W +
    lm/683 per m², capped by πL̄), cosθ from the piece's centre lifted by its
    reach (so a piece the horizon cuts keeps a share), cosθl from its mean
    normal (a curved piece, |n̄| < 1, keeps (1 − |n̄|)/2); c = 0 only where
    every point of it is below the receiver's plane."""
    sh = piece_shape(scene, k)
    d = piece_vec3(scene, k, 0) - p
    d2 = wp.length_sq(d)
    cap = _PI * sh[1]
    if d2 <= 0.0:
        return wp.vec2(cap, 1.0)
    dist = wp.sqrt(d2)
    h = wp.dot(d, n)
    if h + sh[2] < -1.0e-6 * dist:
        return wp.vec2(0.0, 0.0)
    cos_r = wp.clamp((h + sh[2]) / (dist + sh[2]), 0.0, 1.0)
    nn = piece_vec3(scene, k, 3)
    flat = wp.length(nn)
    s = -wp.dot(d, nn) / dist  # > 0: the receiver is on the front side
    cos_l = wp.where(sh[3] > 0.0, wp.abs(s), wp.max(s, 0.0)) + 0.5 * (1.0 - flat)
    return wp.vec2(wp.min(sh[1] * sh[0] * cos_l * cos_r / d2, cap), 1.0)


@wp.func
def normal_bucket(n: wp.vec3) -> int:
    """Which of six buckets the normal n falls in: 2·(its largest axis, x first on ties) + 1 if that
    component is negative (the host's twin: ``simulator.engine.piece_table.normal_buckets``)."""
    ax = wp.abs(n[0])
    ay = wp.abs(n[1])
    az = wp.abs(n[2])
    if ax >= ay and ax >= az:
        return wp.where(n[0] < 0.0, 1, 0)
    if ay >= az:
        return wp.where(n[1] < 0.0, 3, 2)
    return wp.where(n[2] < 0.0, 5, 4)


@wp.func
def piece_cell(scene: SceneRec, p: wp.vec3, n: wp.vec3) -> int:
    """The cell of the pieces' table holding the receiver (p, n): its voxel and its normal's bucket;
    −1 where there is no table, or no cell there."""
    if scene.n_cells == 0:
        return -1
    h0 = cell_header(scene)
    lo = wp.vec3(scene.emit_floats[h0], scene.emit_floats[h0 + 1], scene.emit_floats[h0 + 2])
    q = (p - lo) * scene.emit_floats[h0 + 3]
    d = scene.cell_dims
    if not (q[0] >= 0.0 and q[1] >= 0.0 and q[2] >= 0.0):  # also false for a NaN
        return -1
    if q[0] >= float(d[0]) or q[1] >= float(d[1]) or q[2] >= float(d[2]):
        return -1
    ix = wp.min(int(q[0]), d[0] - 1)
    iy = wp.min(int(q[1]), d[1] - 1)
    iz = wp.min(int(q[2]), d[2] - 1)
    return cell_slot(scene, ((ix * d[1] + iy) * d[2] + iz) * 6 + normal_bucket(n))


@wp.func
def cell_probability(scene: SceneRec, c: int, k: int) -> float:
    """P(k | c) of cell c's table: the float32 CDF's own difference, so that the pick and its pdf agree."""
    base = cell_header(scene) + 4 + c * scene.n_pieces
    lo = float(0.0)
    if k > 0:
        lo = scene.emit_floats[base + k - 1]
    return scene.emit_floats[base + k] - lo


@wp.func
def piece_weights(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(w_k, c_k) of the piece pick at the receiver (module docstring)."""
    e = piece_estimate(scene, k, p, n)
    return wp.vec2(e[0] * piece_factor(scene, k), e[1])


@wp.func
def piece_totals(scene: SceneRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(Σ w, Σ c) over the pieces at the receiver; in a cell of the table, (its Σ_k T_ck, 1)."""
    c = piece_cell(scene, p, n)
    if c >= 0:
        return wp.vec2(scene.emit_floats[cell_header(scene) + 4 + scene.n_cells * scene.n_pieces + c], 1.0)
    tot = wp.vec2(0.0, 0.0)
    for k in range(scene.n_pieces):
        tot += piece_weights(scene, k, p, n)
    return tot


@wp.func
def piece_probability(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3, tot: wp.vec2) -> float:
    """P(k | x) for the totals ``tot`` (:func:`piece_totals`); 1 for a lone piece; in a cell of the
    table, the cell's (``tot`` unread)."""
    if scene.n_pieces <= 1:
        return 1.0
    c = piece_cell(scene, p, n)
    if c >= 0:
        return cell_probability(scene, c, k)
    wc = piece_weights(scene, k, p, n)
    a = wp.where(tot[0] > 0.0, PIECE_UNIFORM, 1.0)
    prob = float(0.0)
    if tot[0] > 0.0:
        prob += (1.0 - a) * wc[0] / tot[0]
    if tot[1] > 0.0:
        prob += a * wc[1] / tot[1]
    return prob


@wp.struct
class PiecePick:
    k: int  # the piece, −1 when none can reach the receiver
    prob: float  # P(k | x)
    u: float  # the uniform left for the triangle pick, in [0, 1)


@wp.func
def pick_piece(scene: SceneRec, p: wp.vec3, n: wp.vec3, u: float) -> PiecePick:
    """Piece k with P(k | x) by inversion of the uniform u (two passes over
    the pieces: totals, then the running sum; in a cell of the table, a
    binary search of its CDF), and u rescaled within k's interval for the
    triangle pick (no extra random numbers)."""
    pk = PiecePick()
    pk.k = 0
    pk.prob = 1.0
    pk.u = u
    if scene.n_pieces <= 1:
        return pk
    c = piece_cell(scene, p, n)
    if c >= 0:
        base = cell_header(scene) + 4 + c * scene.n_pieces
        lo = base
        hi = base + scene.n_pieces - 1
        while lo < hi:
            mid = (lo + hi) // 2
            if scene.emit_floats[mid] <= u:
                lo = mid + 1
            else:
                hi = mid
        pk.k = lo - base
        pk.prob = cell_probability(scene, c, pk.k)
        below = float(0.0)
        if pk.k > 0:
            below = scene.emit_floats[lo - 1]
        if pk.prob > 0.0:
            pk.u = wp.clamp((u - below) / pk.prob, 0.0, 0.99999994)
        return pk
    tot = piece_totals(scene, p, n)
    pk.k = -1
    if tot[1] <= 0.0:
        return pk
    run = float(0.0)
    last = int(-1)
    for k in range(scene.n_pieces):
        pr = piece_probability(scene, k, p, n, tot)
        if pr > 0.0:
            last = k
            if u < run + pr:
                pk.k = k
                pk.prob = pr
                pk.u = wp.clamp((u - run) / pr, 0.0, 0.99999994)
                return pk
            run += pr
    if last >= 0:  # u past the float32 sum of the probabilities: the last piece with any
        pk.k = last
        pk.prob = piece_probability(scene, last, p, n, tot)
        pk.u = 0.99999994
    return pk


@wp.func
def pick(scene: SceneRec, k: int, u: float) -> int:
    """Entry of the grouped elements, within piece k, with P(i) = cdf[i] − cdf[i−1]
    (binary search over the piece's own inclusive CDF)."""
    lo = piece_first(scene, k)
    hi = lo + piece_count(scene, k) - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if piece_cdf(scene, mid) <= u:
            lo = mid + 1
        else:
            hi = mid
    return lo


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    if scene.n_elems == 0:
        return empty_sample()
    pp = pick_piece(scene, p, n, u[0])
    if pp.k < 0:
        return empty_sample()
    return sample_piece(scene, pp.k, pp.prob, p, n, wp.vec3(pp.u, u[1], u[2]))


@wp.func
def sample_piece(scene: SceneRec, k: int, prob: float, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """A point of piece k, picked with probability ``prob``, for the receiver (p, n): a triangle of it
    ∝ its power by u[0], a point uniform on it by u[1], u[2]."""
    s = empty_sample()
    e = piece_entry(scene, pick(scene, k, u[0]))
    tri = elem_tri(scene, e)
    m = emit_m(scene, tri)
    a = tri_vertex(scene, tri, 0)
    b = tri_vertex(scene, tri, 1)
    c = tri_vertex(scene, tri, 2)
    bc = wp.vec2(0.0, 0.0)
    if m == 1:
        bc = sample_triangle_bary(wp.vec2(u[1], u[2]))
    else:  # uniform on the element, a patch of the triangle
        bc = patch_point(e - emit_base(scene, tri), m, wp.vec2(u[1], u[2]))
    q = a + bc[0] * (b - a) + bc[1] * (c - a)
    ng2 = wp.cross(b - a, c - a)
    area = 0.5 * wp.length(ng2)
    if m > 1:
        area = area / float(m * m)
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0 or area <= 0.0:
        return s
    wi = d / dist
    cos_l = -wp.dot(wi, ng2) / wp.length(ng2)  # > 0 when p is in front
    le = tri_emitted(scene, tri, cos_l)
    if wp.abs(cos_l) < 1.0e-9:
        return s
    s.wi = wi
    s.dist = dist
    s.tri = tri
    s.elem = e
    s.pdf = prob * elem_prob(scene, e) * dist * dist / (area * wp.abs(cos_l))
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0 and s.pdf > 0.0:
        s.value = le * (cos_r / s.pdf)
    return s


@wp.func
def element_at(scene: SceneRec, tri: int, y: wp.vec3) -> int:
    """The element of emitting triangle ``tri`` holding its point y (−1: the triangle emits nothing)."""
    e = emit_base(scene, tri)
    m = emit_m(scene, tri)
    if e >= 0 and m > 1:
        st = tri_params(scene, tri, y)
        e += patch_index(st[0], st[1], m)
    return e


@wp.func
def pdf_at(scene: SceneRec, p: wp.vec3, n: wp.vec3, y: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    """Solid-angle pdf with which :func:`sample` at the receiver (p, n) draws the point y of triangle
    ``tri``, met along wi at distance t."""
    a = tri_vertex(scene, tri, 0)
    ng2 = wp.cross(tri_vertex(scene, tri, 1) - a, tri_vertex(scene, tri, 2) - a)
    area = 0.5 * wp.length(ng2)
    cos_l = wp.abs(wp.dot(wi, ng2)) / (2.0 * area)
    if cos_l <= 0.0:
        return 0.0
    e = element_at(scene, tri, y)
    if e < 0:  # a triangle that emits nothing: no element, no piece
        return 0.0
    m = emit_m(scene, tri)
    if m > 1:
        area = area / float(m * m)
    prob = float(1.0)
    if scene.n_pieces > 1:
        prob = piece_probability(scene, elem_piece(scene, e), p, n, piece_totals(scene, p, n))
    return prob * elem_prob(scene, e) * t * t / (area * cos_l)


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    """:func:`pdf_at` for the point p + t·wi."""
    return pdf_at(scene, p, n, p + t * wi, wi, t, tri)


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    total = wp.vec2(0.0, 0.0)
    for k in range(scene.n_elems):
        e = piece_entry(scene, k)
        tri = elem_tri(scene, e)
        if e != emit_base(scene, tri):  # each triangle once: by its first element
            continue
        a = tri_vertex(scene, tri, 0)
        b = tri_vertex(scene, tri, 1)
        c = tri_vertex(scene, tri, 2)
        facing = wp.dot(p - a, wp.cross(b - a, c - a))  # > 0: p in front
        le = tri_emitted(scene, tri, facing)
        if le[0] > 0.0 or le[1] > 0.0:
            total += le * polygon_irradiance4(a, b, c, c, 3, p, n)
    return total


KERNEL = LightKernel(LightKind.EMISSIVE, sample=sample, pdf=pdf, analytic=analytic)
