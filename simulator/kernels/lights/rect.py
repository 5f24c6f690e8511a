"""Rect light: width × height along the local X and Y axes, radiance L
emitted to one side, along local −Z.

Sampled uniformly in the spherical rectangle it subtends (pdf 1/Ω); when
Ω is below ``SPHRECT_MIN_SOLID_ANGLE`` (float32 cannot resolve it) uniformly
in area instead (pdf d²/(A·cosθl)).
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..sampling import SPHRECT_MIN_SOLID_ANGLE, sphrect_sample, sphrect_setup
from .base import (
    LightKernel, LightRec, LightSample, SceneRec, area_pdf, area_sample, behind, empty_sample, hit_inside, near_planar, plane_hit,
)  # fmt: skip


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


def upload(rec, light, keep) -> None:
    rec.area = light.width * light.height


KERNEL = LightKernel(LightKind.RECT, sample=sample, pdf=pdf, hit=hit, near=near_planar, analytic=analytic, upload=upload)
