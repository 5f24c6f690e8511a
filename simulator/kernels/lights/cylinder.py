"""Cylinder light: radius r, ``length`` along the local X axis, radiance L
emitted outward from its side (the caps neither emit nor block).

Sampled uniformly in area on the side, pdf d²/(A·cosθl), A = 2π r·length;
only points whose outward normal faces the receiver emit toward it. No
closed form.
"""

import math

import warp as wp

from simulator.scene.model import LightKind

from ..sampling import TWO_PI
from .base import LightKernel, LightRec, LightSample, SceneRec, area_pdf, area_sample, near_box


@wp.func
def side_normal(l: LightRec, q: wp.vec3) -> wp.vec3:
    """Outward unit normal of the cylinder's side at (or nearest to) q."""
    r = q - l.position
    r = r - wp.dot(r, l.ex) * l.ex
    return wp.normalize(r)


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """Uniform point on the side (area pdf 1/A); a point facing p is also
    the first point of the cylinder the ray meets (it is convex), so no
    self-occlusion test is needed."""
    phi = TWO_PI * u[1]
    nl = wp.cos(phi) * l.ey + wp.sin(phi) * l.ez
    return area_sample(l, p, n, l.position + ((u[0] - 0.5) * l.length) * l.ex + l.radius * nl, nl)


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    return area_pdf(l, -wp.dot(wi, side_normal(l, p + t * wi)), t)


@wp.func
def hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    """Where a ray enters the side from outside (the emitting, outward
    face), or −1. A ray through a cap sees only the inside of the side: nothing."""
    oc = o - l.position
    ox = wp.dot(oc, l.ex)
    dx = wp.dot(d, l.ex)
    op = oc - ox * l.ex  # parts across the axis
    dp = d - dx * l.ex
    a = wp.length_sq(dp)
    b = wp.dot(op, dp)
    c = wp.length_sq(op) - l.radius * l.radius
    if c <= 0.0 or a <= 0.0 or b >= 0.0:
        return -1.0  # inside the infinite cylinder, parallel to its axis, or moving away
    disc = b * b - a * c
    if disc < 0.0:
        return -1.0
    t = c / (wp.sqrt(disc) - b)  # nearer root (t0·t1 = c/a), free of cancellation
    if t <= 0.0 or t >= t_max:
        return -1.0
    if wp.abs(ox + t * dx) > 0.5 * l.length:
        return -1.0
    return t


@wp.func
def near(l: LightRec, d: wp.vec3, reach: float) -> bool:
    return near_box(l, d, reach, l.radius)


def upload(rec, light, keep) -> None:
    rec.area = 2.0 * math.pi * light.radius * light.length


KERNEL = LightKernel(LightKind.CYLINDER, sample=sample, pdf=pdf, hit=hit, near=near, upload=upload)
