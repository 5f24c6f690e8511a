"""Distant light: light from infinitely far away, toward ``+ez``.

Half-angle 0 is a delta direction of normal irradiance E⊥ (W/m², lx): pdf 0,
E = E⊥·cosξ. A half-angle θ > 0 is a cone of uniform radiance, sampled
uniformly in it, pdf 1/(2π(1 − cosθ)).
"""

import math

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import cap_irradiance
from ..sampling import pdf_uniform_cone, sample_uniform_cone, to_world
from .base import RAY_INF, LightKernel, LightRec, LightSample, SceneRec, empty_sample


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    s.dist = RAY_INF
    if l.one_minus_cos <= 0.0:
        s.wi = l.ez
        cos_r = wp.dot(l.ez, n)
        if cos_r > 0.0:
            s.value = l.emission * cos_r  # E = E⊥·cosξ
        return s
    s.wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), l.one_minus_cos), l.ez)
    s.pdf = pdf_uniform_cone(l.one_minus_cos)
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    return wp.where(l.one_minus_cos > 0.0, pdf_uniform_cone(l.one_minus_cos), 0.0)


@wp.func
def escaped(l: LightRec, d: wp.vec3) -> wp.vec2:
    if l.one_minus_cos > 0.0:
        if 1.0 - wp.dot(d, l.ez) <= l.one_minus_cos:
            return l.emission
    return wp.vec2(0.0, 0.0)


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    if l.one_minus_cos <= 0.0:
        return l.emission * wp.max(0.0, wp.dot(l.ez, n))
    omc = l.one_minus_cos
    return l.emission * cap_irradiance(l.ez, omc * (2.0 - omc), n)


def upload(rec, light, keep) -> None:
    # the cone: 1 − cosθ as 2·sin²(θ/2), without cancellation; 0 = delta
    rec.one_minus_cos = 2.0 * math.sin(0.5 * light.half_angle) ** 2


KERNEL = LightKernel(LightKind.DISTANT, sample=sample, pdf=pdf, escaped=escaped, analytic=analytic, upload=upload)
