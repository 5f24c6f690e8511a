"""Dome light: the environment at infinity, radiance L from every direction
(× ``map[texel]`` when textured).

An untextured dome is sampled by a cosine lobe about the receiver normal
(pdf cosθ/π, zero variance unoccluded); a textured one by its texels ∝
value·sinθ, uniform in (u, v) inside the texel (pdf pdf_uv/(2π² sinθ),
:mod:`simulator.kernels.distributions`). The map is looked up *nearest*, so
the radiance is piecewise constant exactly like the sampling density.

A dome with UsdLux PortalLights (``l.n_portals`` > 0) is sampled through
them at every receiver that some portal *guides*: the receiver lies on the
side the portal passes light toward (in front of its plane along −ez) and
the portal is at least partly above the receiver's horizon. There a portal
k is picked with probability P_k = Π_k / Σ_j Π_j, Π the portal's projected
solid angle ∫cosθ dω (Lambert's formula, clipped to the horizon; with one
portal P = 1), then a direction uniform in the spherical rectangle it
subtends (pdf 1/Ω_k; uniform in area, pdf d²/(A·cosθ_portal), when Ω_k is
below ``SPHRECT_MIN_SOLID_ANGLE``), and the sample's value is
L(ω)·cosθ/pdf(ω) with L the dome's radiance along ω (its map texel when
textured). The density of any direction is

    pdf(ω) = Σ_{k : ω passes through portal k} P_k · pdf_k(ω),

0 for a direction through no portal: such directions are left to the
cosine-weighted strategy, whose MIS weight there is 1, so the estimate stays
unbiased in any scene (a portal is a sampling hint: the dome still lights
whatever it lights, through the portals or past them). Where no portal
guides the receiver (behind all of them, or all below its horizon, e.g. the
outside of the building) the dome is sampled as without portals.
Overlapping portals are allowed (the sum counts each one a direction
crosses).
"""

import numpy as np
import warp as wp

from simulator.scene.model import LightKind

from ..closed_forms import polygon_irradiance4
from ..distributions import direction_to_latlong_uv, latlong_texel, pdf_latlong, sample_latlong
from ..sampling import PI, SPHRECT_MIN_SOLID_ANGLE, pdf_cosine_hemisphere, sample_cosine_hemisphere, sphrect_sample, sphrect_setup, to_world
from .base import RAY_INF, LightKernel, LightRec, LightSample, PortalRec, SceneRec, empty_sample

#: how a portal is picked among several: 1 ∝ its projected solid angle Π
#: (clipped to the receiver's horizon), 0 ∝ its solid angle Ω (see
#: docs/DESIGN.md, "Portals", for the measurement that chose it)
PORTAL_PICK_PROJECTED = wp.constant(1)


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
def escaped(l: LightRec, d: wp.vec3) -> wp.vec2:
    if l.has_map != 0:
        uv = direction_to_latlong_uv(d, l.ex, l.ey, l.ez)
        return l.emission * l.map[latlong_texel(uv, l.map_w, l.map_h)]
    return l.emission


# ---------------------------------------------------------------- portals


@wp.func
def portal_guides(pt: PortalRec, p: wp.vec3, n: wp.vec3) -> bool:
    """Whether portal ``pt`` guides the receiver (p, n): p strictly on the
    side it passes light toward, and some corner strictly above the horizon
    (the rectangle is convex, so then part of it is)."""
    if wp.dot(p - pt.corner, pt.ez) >= 0.0:
        return False
    a = pt.width * pt.ex
    b = pt.height * pt.ey
    h0 = wp.dot(pt.corner - p, n)
    h1 = h0 + wp.dot(a, n)
    h2 = h1 + wp.dot(b, n)
    h3 = h0 + wp.dot(b, n)
    return wp.max(wp.max(h0, h1), wp.max(h2, h3)) > 0.0


@wp.func
def portal_weight(pt: PortalRec, p: wp.vec3, n: wp.vec3, single: bool) -> float:
    """Unnormalised probability of picking portal ``pt`` at (p, n): 0 where
    it does not guide; 1 when it is the dome's only portal; else its
    projected solid angle Π (sr) or its solid angle Ω (sr), as
    ``PORTAL_PICK_PROJECTED`` says."""
    if not portal_guides(pt, p, n):
        return 0.0
    if single:
        return 1.0
    if PORTAL_PICK_PROJECTED != 0:
        c1 = pt.corner + pt.width * pt.ex
        c3 = pt.corner + pt.height * pt.ey
        return polygon_irradiance4(pt.corner, c1, c1 + pt.height * pt.ey, c3, 4, p, n)
    return sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height).solid_angle


@wp.func
def portals_total(l: LightRec, p: wp.vec3, n: wp.vec3) -> float:
    """Σ of :func:`portal_weight` over the dome's portals (0: none guides p)."""
    total = float(0.0)
    single = l.n_portals == 1
    for j in range(l.n_portals):
        total += portal_weight(l.portals[j], p, n, single)
    return total


@wp.func
def portal_density(pt: PortalRec, p: wp.vec3, wi: wp.vec3) -> float:
    """Solid-angle density (sr⁻¹) with which a portal, once picked, draws
    direction wi from p: 1/Ω (or d²/(A·cosθ_portal) when Ω is below
    ``SPHRECT_MIN_SOLID_ANGLE``) when wi passes through the rectangle from
    its guided side, else 0."""
    denom = wp.dot(wi, pt.ez)
    if denom <= 0.0:
        return 0.0
    t = wp.dot(pt.corner - p, pt.ez) / denom
    if t <= 0.0:
        return 0.0
    q = p + t * wi - pt.corner
    x = wp.dot(q, pt.ex)
    y = wp.dot(q, pt.ey)
    if x < 0.0 or x > pt.width or y < 0.0 or y > pt.height:
        return 0.0
    sr = sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height)
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        return 1.0 / sr.solid_angle
    return t * t / (pt.width * pt.height * denom)


@wp.func
def pdf_portals(l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, total: float, skip: int) -> float:
    """Σ_k P_k·pdf_k(wi) over the portals except ``skip`` (−1: none), with
    P_k = weight_k / ``total``."""
    acc = float(0.0)
    single = l.n_portals == 1
    for j in range(l.n_portals):
        if j != skip:
            pt = l.portals[j]
            wj = portal_weight(pt, p, n, single)
            if wj > 0.0:
                acc += (wj / total) * portal_density(pt, p, wi)
    return acc


@wp.func
def sample_portals(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3, total: float) -> LightSample:
    """A direction through a portal picked ∝ its weight (``u[2]``), uniform
    in its spherical rectangle (``u[0]``, ``u[1]``); pdf as :func:`pdf`."""
    s = empty_sample()
    single = l.n_portals == 1
    target = u[2] * total
    k = int(-1)
    wk = float(0.0)
    acc = float(0.0)
    for j in range(l.n_portals):
        wj = portal_weight(l.portals[j], p, n, single)
        if wj > 0.0:
            k = j
            wk = wj
            acc += wj
            if target < acc:
                break
    if k < 0:
        return s
    pt = l.portals[k]
    sr = sphrect_setup(p, pt.corner, pt.ex, pt.ey, pt.width, pt.height)
    wi = wp.vec3(0.0, 0.0, 1.0)
    dens = float(0.0)
    if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
        wi = wp.normalize(sphrect_sample(sr, wp.vec2(u[0], u[1])) - p)
        dens = 1.0 / sr.solid_angle
    else:
        q = pt.corner + (u[0] * pt.width) * pt.ex + (u[1] * pt.height) * pt.ey
        d = q - p
        dist = wp.length(d)
        if dist <= 0.0:
            return s
        wi = d / dist
        cos_l = wp.dot(wi, pt.ez)
        if cos_l <= 0.0:
            return s
        dens = dist * dist / (pt.width * pt.height * cos_l)
    pdf_w = (wk / total) * dens
    if not single:
        pdf_w += pdf_portals(l, p, n, wi, total, k)
    s.wi = wi
    s.dist = RAY_INF
    s.pdf = pdf_w
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0:
        s.value = escaped(l, wi) * (cos_r / pdf_w)
    return s


# ---------------------------------------------------------------- the dome


@wp.func
def sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = empty_sample()
    if l.n_portals > 0:
        total = portals_total(l, p, n)
        if total > 0.0:
            return sample_portals(l, p, n, u, total)
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
    if l.n_portals > 0:
        total = portals_total(l, p, n)
        if total > 0.0:
            return pdf_portals(l, p, n, wi, total, -1)
    if l.has_map != 0:
        return pdf_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wi)
    return pdf_cosine_hemisphere(wp.dot(wi, n))


@wp.func
def analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    return l.emission * PI  # the whole upper hemisphere is sky


def upload(rec, light, keep) -> None:
    """A dome's portals (:class:`PortalRec` array), and a textured dome's
    lat-long map and sampling CDFs, on the record.

    Texels are importance-sampled ∝ value × sinθ (simulator.io.latlong); the
    arrays go on ``keep`` because the device record holds only their
    pointers. The CDFs are float32: a texel whose share of its row (or a row
    whose share of the map) is below float32 resolution (~6e-8) may never be
    drawn by light sampling; bsdf and mis still see it.
    """
    if light.portals:
        recs = []
        for portal in light.portals:
            r = PortalRec()
            f = portal.frame
            r.corner = wp.vec3(*map(float, portal.corners()[0]))
            r.ex, r.ey, r.ez = (wp.vec3(*map(float, f[:, i])) for i in range(3))
            r.width, r.height = float(portal.width), float(portal.height)
            recs.append(r)
        rec.n_portals = len(recs)
        rec.portals = wp.array(recs, dtype=PortalRec)
        keep.append(rec.portals)
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
