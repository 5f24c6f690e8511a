"""Lights seen in planar mirrors: the image-source connection, as ``@wp.func``.

A point light (or an angle-0 distant light) reflected by a mirror (a face
with a delta specular part, a mirror base or clearcoat, :func:`.bsdf.
has_mirror`, or a pane's slab, whose reflection is a mirror's of
reflectance R(θ), :func:`.surfaces.slab_rt`) reaches a receiver along one direction only, which neither a
light sample (it aims at the light itself) nor a direction sample (a delta
meets a delta with probability 0) can find; the sun's disc (a distant light
with an angle) is found by a direction sample only when it falls in a cone
of 10⁻⁵ sr, so in practice never. Each flat mirror plane k
(``scene.mirror_planes``, n·x = d, grouped on the host) gives the light an
image: the point reflected in the plane, L' = L − 2(n·L − d) n, or the
direction toward a distant light reflected (for the sun, a direction drawn
uniformly in its cone, pdf 1/Ω, reflected: the reflection keeps solid
angle). The receiver at x connects to the image: the segment from x along
wi passes what it meets before the plane at its share (panes, cut-outs,
:func:`.surfaces.pass_factor`) and must meet the plane on a mirror face of
plane k (at m), which reflects its share c·F(cos θ_m) (c its coverage
there: a perforated screen); from m the light must be visible (panes and
cut-outs pass their share, :func:`.surfaces.transmittance_along`). Its
irradiance on (x, n_x) is then

    E = T_xm · c·F(cos θ_m) · T_ml · I(ω) · cos θ_x / |x − L'|²   (point, intensity I toward m)
    E = T_xm · c·F(cos θ_m) · T_ml · E⊥ · cos θ_x                 (angle-0 distant)
    E ≈ T_xm · c·F(cos θ_m) · T_ml · L · cos θ_x / (1/Ω)          (the sun: one sample of its cone)

with F the mirror's reflectance at its incidence angle (:func:`.bsdf.
mirror_reflectance`): the image source of a plane mirror. One reflection
only (light seen through two mirrors is not connected). A path that makes
the same trip (x, a mirror face of a plane in the table, its mirror part,
the sun) leaves the sun out where x ran this connection
(``estimators.vertex_estimate``), so each path is counted by one strategy.
"""

import warp as wp

from simulator.scene.model import LightKind

from .bsdf import mirror_reflectance
from .coverage import coverage_at
from .glossy import face_bsdf
from .lights import RAY_INF, LightRec, SceneRec
from .rays import first_hit, offset_length
from .sampling import pdf_uniform_cone, sample_uniform_cone, to_world
from .shaping import shaping_factor
from .surfaces import MAX_PASSES, pane_rt, pass_factor, transmittance_along

_POINT_M = wp.constant(int(LightKind.POINT))
_DISTANT_M = wp.constant(int(LightKind.DISTANT))


@wp.struct
class ImageSample:
    wi: wp.vec3  # unit direction from the receiver toward the image (and the mirror)
    value: wp.vec2  # irradiance on the receiver's plane (W/m², lx), 0 when the connection fails
    # for spectral lanes (kernels.spectral_surfaces): the mirror triangle, its incidence cosine and
    # (grey) reflectance F (its coverage aside), and the segment toward the light with its (grey) visibility; the distance
    # t_m from the ray origin to the mirror and the (grey) share vis_in passed on the way there
    face: int
    cos_m: float
    refl: float
    m_off: wp.vec3
    to_l: wp.vec3
    dist_l: float
    vis: float
    t_m: float
    vis_in: float
    pane: int  # 1: the mirror face is a pane's (its reflectance is the slab's, grey)


@wp.func
def has_image(l: LightRec) -> bool:
    """Whether :func:`image_source` connects light ``l``: a point light, or a distant light of any angle."""
    return l.kind == _POINT_M or l.kind == _DISTANT_M


@wp.func
def is_cone_light(l: LightRec) -> bool:
    """A distant light with an angle (the sun's disc): direction samples could meet it, so a path that
    reaches it off a mirror the image source connected leaves it out (module docstring)."""
    return l.kind == _DISTANT_M and l.one_minus_cos > 0.0


@wp.func
def image_source(scene: SceneRec, li: int, k: int, p: wp.vec3, n: wp.vec3, o: wp.vec3, u: wp.vec2) -> ImageSample:
    """The light of light ``li`` (:func:`has_image`) reaching (p, n) off mirror plane ``k``; rays start at
    o; ``u`` draws the direction in a distant light's cone."""
    out = ImageSample()
    out.value = wp.vec2(0.0, 0.0)
    out.wi = n
    l = scene.lights[li]
    pl = scene.mirror_planes[k]
    pn = wp.vec3(pl[0], pl[1], pl[2])
    side_x = wp.dot(pn, p) - pl[3]
    wi = wp.vec3(0.0, 0.0, 1.0)
    dist_img = float(RAY_INF)
    if l.kind == _POINT_M:
        side_l = wp.dot(pn, l.position) - pl[3]
        if side_l * side_x <= 0.0:
            return out  # light and receiver on opposite sides of the plane (or on it)
        image = l.position - (2.0 * side_l) * pn
        d = image - p
        dist_img = wp.length(d)
        if dist_img <= 0.0:
            return out
        wi = d / dist_img
    to_sun = l.ez
    inv_pdf = float(1.0)
    if l.kind == _DISTANT_M:
        if l.one_minus_cos > 0.0:  # one direction of the cone, pdf 1/Ω
            to_sun = to_world(sample_uniform_cone(u, l.one_minus_cos), l.ez)
            inv_pdf = 1.0 / pdf_uniform_cone(l.one_minus_cos)
        if wp.dot(to_sun, pn) * side_x <= 0.0:
            return out  # the sun lights the other side of the mirror
        wi = to_sun - (2.0 * wp.dot(to_sun, pn)) * pn
    elif l.kind != _POINT_M:
        return out
    cos_x = wp.dot(wi, n)
    if cos_x <= 0.0:
        return out
    dn = wp.dot(wi, pn)
    if dn * side_x >= 0.0:
        return out  # heading away from the plane
    # to the plane, through what passes light on the way, to a mirror face of plane k
    vis_in = float(1.0)
    start = float(0.0)
    face = int(-1)
    ng_m = pn
    for j in range(MAX_PASSES):
        if face < 0:
            h = first_hit(scene, o + start * wi, wi, RAY_INF)
            if h.face < 0:
                return out
            if scene.face_mirror[h.face] == k:
                face = h.face
                ng_m = h.ng
                start = start + h.t
            else:
                if scene.surf_id[h.face] < 0:
                    return out  # a matte face blocks it
                q = o + (start + h.t) * wi
                vis_in = vis_in * pass_factor(scene, h.face, wi, h.ng, q)
                if vis_in <= 0.0:
                    return out
                start = start + h.t + offset_length(scene, q)
    if face < 0:
        return out
    m = o + start * wi
    srow = scene.surf[scene.surf_id[face]]
    cover = coverage_at(scene, srow, face, m)
    if srow.pane == 2:  # a translucent layer: its slab is the gap 1 − c, the share c its matte face (surfaces.pass_factor)
        cover = 1.0 - cover
    if cover <= 0.0:
        return out
    to_l = to_sun
    dist_l = float(RAY_INF)
    if l.kind == _POINT_M:
        dl = l.position - m
        dist_l = wp.length(dl)
        to_l = dl / dist_l
    side_n = wp.where(side_x > 0.0, pn, -pn)
    m_off = m + offset_length(scene, m) * side_n
    vis = transmittance_along(scene, m_off, to_l, dist_l, -1)
    if vis <= 0.0:
        return out
    cos_m = wp.abs(dn)
    refl = float(0.0)
    if srow.pane != 0:  # a pane's slab reflects R(θ) (kernels.surfaces.slab_rt; 0 off a closed pane's inner face)
        refl = pane_rt(scene, face, wi, ng_m)[0]
    else:
        refl = mirror_reflectance(face_bsdf(scene, face), cos_m)
    e = vis_in * vis * cover * refl * cos_x
    if l.kind == _POINT_M:
        e = e * shaping_factor(l, -to_l) / (dist_img * dist_img)
    else:
        e = e * inv_pdf
    out.wi = wi
    out.value = e * l.emission
    out.face = face
    out.cos_m = cos_m
    out.refl = refl
    out.m_off = m_off
    out.to_l = to_l
    out.dist_l = dist_l
    out.vis = vis
    out.t_m = start
    out.vis_in = vis_in
    out.pane = srow.pane
    return out
