"""Point light: a delta source of intensity I (W/sr, cd) at ``position``.

No direction sample can hit it (pdf 0): only next-event estimation sees
it, exactly, E = I·cosξ/d².
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import point_irradiance, triangle_solid_angle
from .base import LightKernel, LightRec, LightSample, SceneRec, empty_sample


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """The exact direction toward the light (delta: pdf 0)."""
    s = empty_sample()
    d = l.position - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    s.wi = d / dist
    s.dist = dist
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / (dist * dist))  # E = I·cosξ/d²
    return s


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    return l.emission * point_irradiance(l.position, p, n)


@wp.func
def analytic_patch(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:
    """Mean irradiance on a w × h patch centred at c facing n: I·Ω/A, Ω the
    patch's solid angle seen from the light, counted when the light is on
    the side it faces."""
    if wp.dot(l.position - c, n) <= 0.0:
        return wp.vec2(0.0, 0.0)
    hx = 0.5 * w * right
    hy = 0.5 * h * up
    r = c - l.position
    omega = triangle_solid_angle(r - hx - hy, r + hx - hy, r + hx + hy) + triangle_solid_angle(
        r - hx - hy, r + hx + hy, r - hx + hy
    )
    return l.emission * (omega / (w * h))


KERNEL = LightKernel(LightKind.POINT, sample=sample, analytic=analytic, analytic_patch=analytic_patch)
