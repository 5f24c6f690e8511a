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
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..sampling import sample_triangle_bary
from .base import LightKernel, LightRec, LightSample, SceneRec, empty_sample, tri_emitted, tri_vertex

#: the uniform share α of the piece pick (the light pick's, kernels/light_pick.py)
PIECE_UNIFORM = wp.constant(0.1)
_PI = wp.constant(3.14159265358979)


@wp.func
def piece_estimate(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(ê, c) of piece k at the receiver (p, n): ê = L̄·A·cosθl·cosθ/d² (W +
    lm/683 per m², capped by πL̄), cosθ from the piece's centre lifted by its
    reach (so a piece the horizon cuts keeps a share), cosθl from its mean
    normal (a curved piece, |n̄| < 1, keeps (1 − |n̄|)/2); c = 0 only where
    every point of it is below the receiver's plane."""
    sh = scene.piece_shape[k]
    d = scene.piece_centre[k] - p
    d2 = wp.length_sq(d)
    cap = _PI * sh[1]
    if d2 <= 0.0:
        return wp.vec2(cap, 1.0)
    dist = wp.sqrt(d2)
    h = wp.dot(d, n)
    if h + sh[2] < -1.0e-6 * dist:
        return wp.vec2(0.0, 0.0)
    cos_r = wp.clamp((h + sh[2]) / (dist + sh[2]), 0.0, 1.0)
    nn = scene.piece_normal[k]
    flat = wp.length(nn)
    s = -wp.dot(d, nn) / dist  # > 0: the receiver is on the front side
    cos_l = wp.where(sh[3] > 0.0, wp.abs(s), wp.max(s, 0.0)) + 0.5 * (1.0 - flat)
    return wp.vec2(wp.min(sh[1] * sh[0] * cos_l * cos_r / d2, cap), 1.0)


@wp.func
def piece_weights(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(w_k, c_k) of the piece pick at the receiver (module docstring)."""
    e = piece_estimate(scene, k, p, n)
    return wp.vec2(e[0] * scene.piece_factor[k], e[1])


@wp.func
def piece_totals(scene: SceneRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(Σ w, Σ c) over the pieces at the receiver."""
    tot = wp.vec2(0.0, 0.0)
    for k in range(scene.n_pieces):
        tot += piece_weights(scene, k, p, n)
    return tot


@wp.func
def piece_probability(scene: SceneRec, k: int, p: wp.vec3, n: wp.vec3, tot: wp.vec2) -> float:
    """P(k | x) for the totals ``tot`` (:func:`piece_totals`); 1 for a lone piece."""
    if scene.n_pieces <= 1:
        return 1.0
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
    the pieces: totals, then the running sum), and u rescaled within k's
    interval for the triangle pick (no extra random numbers)."""
    pk = PiecePick()
    pk.k = 0
    pk.prob = 1.0
    pk.u = u
    if scene.n_pieces <= 1:
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
    """Index into emit_tris, within piece k, with P(i) = cdf[i] − cdf[i−1]
    (binary search over the piece's own inclusive CDF)."""
    lo = scene.piece_first[k]
    hi = lo + scene.piece_count[k] - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if scene.emit_cdf[mid] <= u:
            lo = mid + 1
        else:
            hi = mid
    return lo


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    if scene.emit_tris.shape[0] == 0:
        return s
    pp = pick_piece(scene, p, n, u[0])
    if pp.k < 0:
        return s
    tri = scene.emit_tris[pick(scene, pp.k, pp.u)]
    a = tri_vertex(scene, tri, 0)
    b = tri_vertex(scene, tri, 1)
    c = tri_vertex(scene, tri, 2)
    bc = sample_triangle_bary(wp.vec2(u[1], u[2]))
    q = a + bc[0] * (b - a) + bc[1] * (c - a)
    ng2 = wp.cross(b - a, c - a)
    area = 0.5 * wp.length(ng2)
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0 or area <= 0.0:
        return s
    wi = d / dist
    cos_l = -wp.dot(wi, ng2) / (2.0 * area)  # > 0 when p is in front
    le = tri_emitted(scene, tri, cos_l)
    if wp.abs(cos_l) < 1.0e-9:
        return s
    s.wi = wi
    s.dist = dist
    s.tri = tri
    s.pdf = pp.prob * scene.emit_prob[tri] * dist * dist / (area * wp.abs(cos_l))
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0 and s.pdf > 0.0:
        s.value = le * (cos_r / s.pdf)
    return s


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    a = tri_vertex(scene, tri, 0)
    ng2 = wp.cross(tri_vertex(scene, tri, 1) - a, tri_vertex(scene, tri, 2) - a)
    area = 0.5 * wp.length(ng2)
    cos_l = wp.abs(wp.dot(wi, ng2)) / (2.0 * area)
    if cos_l <= 0.0:
        return 0.0
    prob = float(1.0)
    if scene.n_pieces > 1:
        pc = scene.emit_piece[tri]
        if pc < 0:  # a triangle that emits nothing: no piece, and emit_prob 0 besides
            return 0.0
        prob = piece_probability(scene, pc, p, n, piece_totals(scene, p, n))
    return prob * scene.emit_prob[tri] * t * t / (area * cos_l)


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    total = wp.vec2(0.0, 0.0)
    for k in range(scene.emit_tris.shape[0]):
        tri = scene.emit_tris[k]
        a = tri_vertex(scene, tri, 0)
        b = tri_vertex(scene, tri, 1)
        c = tri_vertex(scene, tri, 2)
        facing = wp.dot(p - a, wp.cross(b - a, c - a))  # > 0: p in front
        le = tri_emitted(scene, tri, facing)
        if le[0] > 0.0 or le[1] > 0.0:
            total += le * polygon_irradiance4(a, b, c, c, 3, p, n)
    return total


KERNEL = LightKernel(LightKind.EMISSIVE, sample=sample, pdf=pdf, analytic=analytic)
