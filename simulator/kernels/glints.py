"""The glint strategy: directions toward a distant light's reflection in a flat glossy plane.

A sunlit glossy floor lights the ceiling and walls above it with the sun's
glossy reflection, a bright lobe about the mirror direction whose size is
set by the floor's roughness (α = roughness², GGX). A matte vertex x that
draws its next direction by the cosine (or the surface guide) finds that
lobe's floor points only by chance, so the light reflected there (L = f·E
cosθ of the sun, at most D(h)/(4 cos cos) times brighter than a matte
floor's) is a noisy part of the reading: 10% of the glazed office's variance
per sample with the guide, 22% with plain paths.

The glint strategy samples what the floor does, seen from x: a microfacet
normal h ∝ D(h)·cosθ_h about the plane's normal N (facing x), the light's
direction s reflected about it, wo = 2(s·h)h − s (the direction a ray
leaves the floor toward its viewer), and x's direction ω = −wo. Its solid-
angle density is the microfacet sampler's, p(ω) = D(h)·cosθ_h / (4 s·h),
h = normalize(s − ω): a density over directions alone, whatever the ray
then meets, so it joins the vertex's other direction strategy (the cosine)
in every multiple-importance weight exactly (:func:`glint_pdf`), and the
guide's area density is set beside their mixture as it is for a glossy
vertex's lobes. It is drawn with probability :data:`GLINT_SHARE` of the
vertex's direction samples, only where x lies on the lit side of a glint's
plane and faces the light's mirror direction (:func:`glint_share`).

Glint pairs (``scene.glints``, host: :func:`simulator.scene.surfaces.
glint_planes`) are the largest flat glossy planes (roughness above the
mirror limit) with the distant lights; at most :data:`MAX_GLINTS`, each
drawn with probability 1/n.

References
----------
B. Walter, S. R. Marschner, H. Li, K. E. Torrance, "Microfacet models for
refraction through rough surfaces", EGSR 2007 (sampling h ∝ D(h)·cosθ_h, and
the reflected direction's density D(h)·cosθ_h / (4 |wo·h|)).
E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD
thesis, Stanford, 1997, §9.2.4 (one-sample MIS over a mixture of strategies).
"""

import warp as wp

from .bsdf import ggx_d, microfacet_sample
from .surface_rec import GlintRec
from .sampling import frame_x, frame_y

#: share of a matte vertex's direction samples that go to the glint strategy where it applies (the rest:
#: the cosine); measured on the glazed office (docs/DESIGN.md §Glints)
GLINT_SHARE = wp.constant(0.1)


@wp.func
def glint_normal(g: GlintRec, x: wp.vec3) -> wp.vec3:
    """The plane normal of glint ``g`` facing x, or zero when x lies on the plane or the light is on
    the plane's other side from x (its reflection is not seen from there)."""
    nrm = wp.vec3(g.plane[0], g.plane[1], g.plane[2])
    side = wp.dot(nrm, x) - g.plane[3]
    if side == 0.0:
        return wp.vec3(0.0, 0.0, 0.0)
    if side < 0.0:
        nrm = -nrm
    if wp.dot(nrm, g.s) <= 0.0:
        return wp.vec3(0.0, 0.0, 0.0)
    return nrm


@wp.func
def glint_share(glints: wp.array(dtype=GlintRec), n_glints: int, x: wp.vec3, n: wp.vec3) -> float:
    """The probability :data:`GLINT_SHARE` with which a matte vertex at x of normal n draws the glint
    strategy, or 0 where no glint's mirror direction s − 2(s·N)N lies in front of it. (The glint
    functions take the table, not the scene record: Warp passes structs by value.)"""
    for k in range(n_glints):
        nrm = glint_normal(glints[k], x)
        if wp.length(nrm) > 0.0:
            s = glints[k].s
            if wp.dot(n, s - (2.0 * wp.dot(s, nrm)) * nrm) > 0.0:
                return GLINT_SHARE
    return 0.0


@wp.func
def glint_direction(nrm: wp.vec3, s: wp.vec3, alpha: float, u: wp.vec2) -> wp.vec3:
    """A direction ω toward the plane of unit normal ``nrm`` (facing the viewer) along which it reflects
    light from the unit direction ``s`` by a microfacet normal h drawn ∝ D(h)·cosθ_h of GGX ``alpha``:
    ω = −(2(s·h)h − s); zero where that reflection falls below the plane (no sample)."""
    tx = frame_x(nrm)
    ty = frame_y(nrm)
    s_l = wp.vec3(wp.dot(s, tx), wp.dot(s, ty), wp.dot(s, nrm))
    r = microfacet_sample(s_l, alpha, u)
    if r[2] <= 0.0:
        return wp.vec3(0.0, 0.0, 0.0)
    return -(r[0] * tx + r[1] * ty + r[2] * nrm)


@wp.func
def glint_density(nrm: wp.vec3, s: wp.vec3, alpha: float, w: wp.vec3) -> float:
    """Solid-angle density (sr⁻¹) of :func:`glint_direction` at the unit direction w:
    D(h)·cosθ_h / (4 s·h), h = normalize(s − w); 0 unless w points into the plane and s leaves it
    (tested first: most directions a vertex weighs, toward lights above the plane, stop there)."""
    cos_o = -wp.dot(w, nrm)
    cos_s = wp.dot(s, nrm)
    if cos_o <= 0.0 or cos_s <= 0.0:
        return 0.0
    h = wp.normalize(s - w)
    ch = wp.dot(h, nrm)
    return ggx_d(ch, alpha) * ch / (4.0 * wp.max(wp.dot(s, h), 1.0e-12))


@wp.func
def glint_sample(glints: wp.array(dtype=GlintRec), n_glints: int, x: wp.vec3, u: wp.vec3) -> wp.vec3:
    """A direction ω from x by the glint strategy (module docstring): glint k = ⌊u₀·n⌋, then
    :func:`glint_direction` of its light about its plane; zero where glint k does not apply at x or
    the reflection falls below the plane (the sample gives nothing)."""
    k = wp.min(int(u[0] * float(n_glints)), n_glints - 1)
    g = glints[k]
    nrm = glint_normal(g, x)
    if wp.length(nrm) <= 0.0:
        return wp.vec3(0.0, 0.0, 0.0)
    return glint_direction(nrm, g.s, g.alpha, wp.vec2(u[1], u[2]))


@wp.func
def glint_pdf(glints: wp.array(dtype=GlintRec), n_glints: int, x: wp.vec3, w: wp.vec3) -> float:
    """Solid-angle density (sr⁻¹) with which :func:`glint_sample` draws the unit direction w from x:
    (1/n)·Σ_k :func:`glint_density` over the glints that apply at x."""
    total = float(0.0)
    for k in range(n_glints):
        g = glints[k]
        nrm = glint_normal(g, x)
        if wp.length(nrm) > 0.0:
            total += glint_density(nrm, g.s, g.alpha, w)
    return total / float(wp.max(n_glints, 1))
