"""Rect light: width × height along the local X and Y axes, radiance L
emitted to one side, along local −Z.

Sampled uniformly in the spherical rectangle it subtends (pdf 1/Ω); when
Ω is below ``SPHRECT_MIN_SOLID_ANGLE`` (float32 cannot resolve it) uniformly
in area instead (pdf d²/(A·cosθl)).

At a narrow sensor head's own vertex (kernels.optics) the light may instead
be sampled within the head's field only (:func:`sample_field`, pdf
:func:`pdf_field`): in the sub-rectangle that bounds the ellipse the field's
cone (half-angle α about the head's axis a) cuts in the light's plane. A
point x = corner + u·ex + v·ey lies in the cone where
Q(u, v) = (w·a)² − cos²α·(w·w) ≥ 0, w = x − p: a conic
[u v 1] M [u v 1]ᵀ ≥ 0 with

    M11 = a_u² − k,  M22 = a_v² − k,  M12 = a_u·a_v,
    M13 = a_0·a_u − k·b_u,  M23 = a_0·a_v − k·b_v,  M33 = a_0² − k·|w₀|²,

k = cos²α, w₀ = corner − p, a_0 = w₀·a, a_u = ex·a, a_v = ey·a,
b_u = w₀·ex, b_v = w₀·ey. The lines u = u₀ tangent to it are those of its
dual conic C = adj M: C11 − 2u₀·C13 + u₀²·C33 = 0, so the ellipse spans
u ∈ (C13 ± √(C13² − C11·C33))/C33, and v likewise with C22, C23
(docs/REFERENCES.md §Light samples in a narrow field). The cone cuts an ellipse, bounded, when it lies wholly on the
light's side of p, a·ez > sin α; elsewhere the window is the whole light.
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..optics import OpticsRec, optics_response, optics_to_local
from ..sampling import SPHRECT_MIN_SOLID_ANGLE, SphRect, sphrect_sample, sphrect_setup
from .base import (
    LightKernel, LightRec, LightSample, SceneRec, area_pdf, area_sample, behind, empty_sample, hit_inside, near_planar, plane_hit,
)  # fmt: skip


#: candidates of a light sample within a head's field (sample_field): the light sample's variance from the
#: response's spread over the light falls about as 1/M, for M cheap draws and still one shadow ray
FIELD_CANDIDATES = wp.constant(16)


@wp.func
def corner(l: LightRec) -> wp.vec3:
    return l.position - 0.5 * l.width * l.ex - 0.5 * l.height * l.ey


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    if behind(l, p):
        return s  # behind a one-sided emitter
    c = corner(l)
    sr = sphrect_setup(p, c, l.ex, l.ey, l.width, l.height)
    if sr.solid_angle <= SPHRECT_MIN_SOLID_ANGLE:
        q = c + (u[0] * l.width) * l.ex + (u[1] * l.height) * l.ey
        return area_sample(l, p, n, q, -l.ez)
    q = sphrect_sample(sr, wp.vec2(u[0], u[1]))
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    s.wi = d / dist
    s.dist = dist
    s.pdf = 1.0 / sr.solid_angle
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r * sr.solid_angle)
    return s


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    sr = sphrect_setup(p, corner(l), l.ex, l.ey, l.width, l.height)
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        return 1.0 / sr.solid_angle
    return area_pdf(l, wp.dot(wi, l.ez), t)


@wp.func
def hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    h = plane_hit(l, o, d, t_max)
    return hit_inside(h, wp.abs(h[1]) <= 0.5 * l.width and wp.abs(h[2]) <= 0.5 * l.height)


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    if behind(l, p):
        return wp.vec2(0.0, 0.0)  # behind a one-sided emitter
    hx = 0.5 * l.width * l.ex
    hy = 0.5 * l.height * l.ey
    c = l.position
    return l.emission * polygon_irradiance4(c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy, 4, p, n)


@wp.func
def field_window(l: LightRec, p: wp.vec3, a: wp.vec3, cos_f: float) -> wp.vec4:
    """(u0, u1, v0, v1), metres from the corner along ex and ey: the part of the light whose points are
    seen from ``p`` within the cone of half-angle α = acos(``cos_f``) about the unit axis ``a`` (the
    bounding box of the ellipse it cuts in the light's plane, module docstring), clipped to the light.
    The whole light where ``cos_f`` ≤ 0 or the cone is not bounded there; u0 ≥ u1 or v0 ≥ v1 where the
    field misses it."""
    full = wp.vec4(0.0, l.width, 0.0, l.height)
    if cos_f <= 0.0:
        return full
    sin_f = wp.sqrt(wp.max(0.0, 1.0 - cos_f * cos_f))
    if wp.dot(a, l.ez) <= sin_f + 1.0e-3:
        return full
    w0 = corner(l) - p
    k = cos_f * cos_f
    a0 = wp.dot(w0, a)
    au = wp.dot(l.ex, a)
    av = wp.dot(l.ey, a)
    bu = wp.dot(w0, l.ex)
    bv = wp.dot(w0, l.ey)
    m11 = au * au - k
    m22 = av * av - k
    m12 = au * av
    m13 = a0 * au - k * bu
    m23 = a0 * av - k * bv
    m33 = a0 * a0 - k * wp.dot(w0, w0)
    c33 = m11 * m22 - m12 * m12
    if c33 <= 0.0:
        return full
    c11 = m22 * m33 - m23 * m23
    c22 = m11 * m33 - m13 * m13
    c13 = m12 * m23 - m13 * m22
    c23 = m12 * m13 - m11 * m23
    du = c13 * c13 - c11 * c33
    dv = c23 * c23 - c22 * c33
    if du <= 0.0 or dv <= 0.0:
        return full
    su = wp.sqrt(du)
    sv = wp.sqrt(dv)
    return wp.vec4(wp.max(0.0, (c13 - su) / c33), wp.min(l.width, (c13 + su) / c33),
                   wp.max(0.0, (c23 - sv) / c33), wp.min(l.height, (c23 + sv) / c33))


@wp.struct
class FieldDraw:
    """A light sample within a head's field, and the random stream after its candidates."""

    s: LightSample
    rng: wp.uint32


@wp.func
def window_point(l: LightRec, p: wp.vec3, c: wp.vec3, w: float, h: float, sr: SphRect, u: wp.vec2) -> LightSample:
    """One point of the window ``c + [0, w]·ex + [0, h]·ey`` drawn uniformly in its solid angle (in its
    area where float32 cannot resolve that): its direction, distance and pdf (value unset)."""
    s = empty_sample()
    q = c + (u[0] * w) * l.ex + (u[1] * h) * l.ey
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        q = sphrect_sample(sr, u)
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    s.wi = d / dist
    s.dist = dist
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        s.pdf = 1.0 / sr.solid_angle
    else:
        cos_l = wp.dot(s.wi, l.ez)
        if cos_l > 0.0:
            s.pdf = dist * dist / (w * h * cos_l)
    return s


@wp.func
def sample_field(l: LightRec, p: wp.vec3, n: wp.vec3, a: wp.vec3, cos_f: float, o: OpticsRec, ox: wp.vec3,
                 rng_in: wp.uint32) -> FieldDraw:
    """A light sample for a head of response r (``o``, azimuth origin ``ox``, axis ``a``) at ``p``: points
    of :func:`field_window` drawn uniformly in its solid angle (pdf p, :func:`pdf_field`), and of
    ``FIELD_CANDIDATES`` such candidates x_j one picked with probability ∝ r(x_j)/p(x_j) (resampled
    importance sampling toward r, L being the same over the light). The picked y carries the weight
    W = (1/r(y))·(1/M)·Σ r(x_j)/p(x_j) in place of 1/p(y): E[g(y)·W] = ∫ g dω over the window for any g
    that is 0 where r is (docs/REFERENCES.md §Light samples in a narrow field), so value = L·cosθ·W keeps every estimate that weighs it
    unbiased, and one shadow ray reads M candidates' worth of the response's spread over the light.
    Its ``pdf`` is p(y), the uniform window's density, which MIS weighs (any weights that sum to 1 with
    the directions' own keep the sum unbiased). Nothing where the window is empty or r is 0 on every
    candidate."""
    out = FieldDraw()
    out.s = empty_sample()
    rng = rng_in
    if behind(l, p):
        out.rng = rng
        return out
    win = field_window(l, p, a, cos_f)
    w = win[1] - win[0]
    h = win[3] - win[2]
    if w <= 0.0 or h <= 0.0:
        out.rng = rng
        return out
    c = corner(l) + win[0] * l.ex + win[2] * l.ey
    sr = sphrect_setup(p, c, l.ex, l.ey, w, h)
    total = float(0.0)  # Σ r(x_j)/p(x_j) over the candidates so far
    pick = empty_sample()
    r_pick = float(0.0)
    for j in range(FIELD_CANDIDATES):
        x = window_point(l, p, c, w, h, sr, wp.vec2(wp.randf(rng), wp.randf(rng)))
        keep = wp.randf(rng)
        if x.pdf > 0.0:
            rj = optics_response(o, optics_to_local(x.wi, ox, a))
            wj = rj / x.pdf
            if wj > 0.0:
                total += wj
                if keep * total < wj:  # kept with probability w_j/Σ_{i≤j} w_i: the last kept is x_j ∝ w_j
                    pick = x
                    r_pick = rj
    out.rng = rng
    if r_pick <= 0.0:
        return out
    cos_r = wp.dot(pick.wi, n)
    pick.value = wp.vec2(0.0, 0.0)
    if cos_r > 0.0:
        pick.value = l.emission * (cos_r * total / (float(FIELD_CANDIDATES) * r_pick))
    out.s = pick
    return out


@wp.func
def pdf_field(l: LightRec, p: wp.vec3, a: wp.vec3, cos_f: float, q: wp.vec3) -> float:
    """Solid-angle density p with which :func:`sample_field` from ``p`` draws each candidate toward ``q``,
    a point of the light (uniform over the window's solid angle): 0 outside the window. MIS weighs it."""
    if behind(l, p):
        return 0.0
    win = field_window(l, p, a, cos_f)
    w = win[1] - win[0]
    h = win[3] - win[2]
    if w <= 0.0 or h <= 0.0:
        return 0.0
    c0 = corner(l)
    qu = wp.dot(q - c0, l.ex)
    qv = wp.dot(q - c0, l.ey)
    if qu < win[0] or qu > win[1] or qv < win[2] or qv > win[3]:
        return 0.0
    c = c0 + win[0] * l.ex + win[2] * l.ey
    sr = sphrect_setup(p, c, l.ex, l.ey, w, h)
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        return 1.0 / sr.solid_angle
    d = q - p
    dist = wp.length(d)
    cos_l = wp.dot(d, l.ez) / wp.max(dist, 1.0e-30)
    return wp.where(cos_l > 0.0, dist * dist / (w * h * cos_l), 0.0)


def upload(rec, light, keep) -> None:
    rec.area = light.width * light.height


KERNEL = LightKernel(LightKind.RECT, sample=sample, pdf=pdf, hit=hit, near=near_planar, analytic=analytic, upload=upload)
