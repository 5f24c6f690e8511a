"""Disk light: radius r in the local XY plane, radiance L emitted to one
side, along local −Z. Sampled uniformly in area (concentric map), pdf
d²/(A·cosθl)."""

import math

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import disk_irradiance
from ..sampling import sample_concentric_disk
from .base import (
    LightKernel, LightRec, LightSample, SceneRec, area_pdf, area_sample, behind, empty_sample, hit_inside, near_planar, plane_hit,
)  # fmt: skip


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    if behind(l, p):
        return empty_sample()  # behind a one-sided emitter
    dp = sample_concentric_disk(wp.vec2(u[0], u[1])) * l.radius
    return area_sample(l, p, n, l.position + dp[0] * l.ex + dp[1] * l.ey, -l.ez)


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    return area_pdf(l, wp.dot(wi, l.ez), t)


@wp.func
def hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    h = plane_hit(l, o, d, t_max)
    return hit_inside(h, h[1] * h[1] + h[2] * h[2] <= l.radius * l.radius)


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    if behind(l, p):
        return wp.vec2(0.0, 0.0)  # behind a one-sided emitter
    return l.emission * disk_irradiance(l.position, l.ex, l.ey, l.radius, p, n)


def upload(rec, light, keep) -> None:
    rec.area = math.pi * light.radius**2


KERNEL = LightKernel(LightKind.DISK, sample=sample, pdf=pdf, hit=hit, near=near_planar, analytic=analytic, upload=upload)
