"""Dome light: the environment at infinity, radiance L from every direction
(× ``map[texel]`` when textured).

An untextured dome is sampled by a cosine lobe about the receiver normal
(pdf cosθ/π, zero variance unoccluded); a textured one by its texels ∝
value·sinθ, uniform in (u, v) inside the texel (pdf pdf_uv/(2π² sinθ),
:mod:`simulator.kernels.distributions`). The map is looked up *nearest*, so
the radiance is piecewise constant exactly like the sampling density.
"""

import numpy as np
import warp as wp

from simulator.scene.model import LightKind

from ..distributions import direction_to_latlong_uv, latlong_texel, pdf_latlong, sample_latlong
from ..sampling import PI, pdf_cosine_hemisphere, sample_cosine_hemisphere, to_world
from .base import RAY_INF, LightKernel, LightRec, LightSample, SceneRec, empty_sample


@wp.func
def sample_map(l: LightRec, n: wp.vec3, u: wp.vec3) -> LightSample:
    """A direction from the map's value·sinθ distribution (whole sphere;
    directions below the receiver's horizon add 0)."""
    s = empty_sample()
    ms = sample_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wp.vec2(u[0], u[1]))
    if ms.pdf <= 0.0:
        return s
    s.wi = ms.wi
    s.dist = RAY_INF
    s.pdf = ms.pdf
    cos_r = wp.dot(ms.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (l.map[ms.texel] * cos_r / ms.pdf)
    return s


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    if l.has_map != 0:
        return sample_map(l, n, u)
    local = sample_cosine_hemisphere(wp.vec2(u[0], u[1]))
    s.wi = to_world(local, n)
    s.dist = RAY_INF
    s.pdf = pdf_cosine_hemisphere(local[2])
    if s.pdf > 0.0:
        s.value = l.emission * PI  # L·cosθ / (cosθ/π)
    return s


@wp.func
def pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    if l.has_map != 0:
        return pdf_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wi)
    return pdf_cosine_hemisphere(wp.dot(wi, n))


@wp.func
def escaped(l: LightRec, d: wp.vec3) -> wp.vec2:
    if l.has_map != 0:
        uv = direction_to_latlong_uv(d, l.ex, l.ey, l.ez)
        return l.emission * l.map[latlong_texel(uv, l.map_w, l.map_h)]
    return l.emission


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    return l.emission * PI  # the whole upper hemisphere is sky


def upload(rec, light, keep) -> None:
    """A textured dome: its lat-long map and sampling CDFs on the record.

    Texels are importance-sampled ∝ value × sinθ (simulator.io.latlong); the
    arrays go on ``keep`` because the device record holds only their
    pointers. The CDFs are float32: a texel whose share of its row (or a row
    whose share of the map) is below float32 resolution (~6e-8) may never be
    drawn by light sampling; bsdf and mis still see it.
    """
    if light.texture_map is None:
        return
    from simulator.io import latlong

    grey = np.asarray(light.texture_map, np.float64)
    h, w = grey.shape
    marg, cond = latlong.build_distribution(latlong.sampling_weights(grey))
    rec.has_map, rec.map_w, rec.map_h = 1, int(w), int(h)
    rec.map = wp.array(grey.astype(np.float32).ravel(), dtype=float)
    rec.map_marg = wp.array(marg.astype(np.float32), dtype=float)
    rec.map_cond = wp.array(cond.astype(np.float32).ravel(), dtype=float)
    keep += [rec.map, rec.map_marg, rec.map_cond]


KERNEL = LightKernel(LightKind.DOME, sample=sample, pdf=pdf, escaped=escaped, analytic=analytic, upload=upload)
