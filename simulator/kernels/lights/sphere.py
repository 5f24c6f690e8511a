"""Sphere light: radius r, radiance L (W m⁻² sr⁻¹, cd/m²) emitted outward.

Sampled uniformly in the cone it subtends, pdf 1/(2π(1 − cosθmax)); a
receiver inside it sees nothing (it emits outward only).
"""

import math

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import cap_irradiance
from ..sampling import one_minus_cos_from_sin2, pdf_uniform_cone, sample_uniform_cone, to_world
from .base import LightKernel, LightRec, LightSample, SceneRec, empty_sample


@wp.func
def cone(l: LightRec, p: wp.vec3) -> float:
    """1 − cosθmax of the cone a sphere light subtends from p (0 if p is inside)."""
    d2 = wp.length_sq(l.position - p)
    r2 = l.radius * l.radius
    if d2 <= r2:
        return 0.0
    return one_minus_cos_from_sin2(r2 / d2)


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    omc = cone(l, p)
    if omc <= 0.0:
        return s  # inside a sphere light: it emits outward only
    axis = wp.normalize(l.position - p)
    wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), omc), axis)
    # distance to the near side of the sphere along wi
    oc = l.position - p
    b = wp.dot(oc, wi)
    disc = l.radius * l.radius - (wp.length_sq(oc) - b * b)
    t = b - wp.sqrt(wp.max(disc, 0.0))
    s.wi = wi
    s.dist = wp.max(t, 0.0)
    s.pdf = pdf_uniform_cone(omc)
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    omc = cone(l, p)
    return wp.where(omc > 0.0, pdf_uniform_cone(omc), 0.0)


@wp.func
def hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    oc = l.position - o
    b = wp.dot(oc, d)
    c = wp.length_sq(oc) - l.radius * l.radius
    if c <= 0.0:
        return -1.0  # inside: the sphere emits outward
    disc = b * b - c
    if disc < 0.0 or b <= 0.0:
        return -1.0
    t = b - wp.sqrt(disc)
    if t >= t_max:
        return -1.0
    return t


@wp.func
def near(l: LightRec, d: wp.vec3, reach: float) -> bool:
    return wp.length(d) - l.radius < reach


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    d = l.position - p
    d2 = wp.length_sq(d)
    if d2 <= l.radius * l.radius:
        return wp.vec2(0.0, 0.0)
    return l.emission * cap_irradiance(d / wp.sqrt(d2), l.radius * l.radius / d2, n)


def upload(rec, light, keep) -> None:
    rec.area = 4.0 * math.pi * light.radius**2


KERNEL = LightKernel(LightKind.SPHERE, sample=sample, pdf=pdf, hit=hit, near=near, analytic=analytic, upload=upload)
