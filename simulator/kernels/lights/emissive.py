"""Emissive geometry: one light record for all emitting triangles.

A triangle is picked with probability ∝ its emitted power (the engine's
``emit_cdf``), then a point uniform in its area: pdf P(tri)·d²/(A·|cosθl|).
The record has no shape of its own: the triangles are the scene's.
"""

import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..sampling import sample_triangle_bary
from .base import LightKernel, LightRec, LightSample, SceneRec, empty_sample, tri_emitted, tri_vertex


@wp.func
def pick(scene: SceneRec, u: float) -> int:
    """Index into emit_tris with P(i) = cdf[i] − cdf[i−1] (binary search)."""
    lo = int(0)
    hi = scene.emit_cdf.shape[0] - 1
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
    tri = scene.emit_tris[pick(scene, u[0])]
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
    s.pdf = scene.emit_prob[tri] * dist * dist / (area * wp.abs(cos_l))
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
    return wp.where(cos_l > 0.0, scene.emit_prob[tri] * t * t / (area * cos_l), 0.0)


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
