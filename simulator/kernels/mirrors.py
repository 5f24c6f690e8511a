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

Curved mirrors (``k`` past the flat planes: ``scene.n_curves`` pieces of
shaded mirror faces) are solved by Newton's method instead of imaged
(:func:`curve_image`, :mod:`.curved`).

**Area lights in flat mirrors** (sphere, disk, rect and cylinder lights):
a direction sample meets a small light's image only with the light's solid
angle, so an irradiance sensor that sees a globe only in a mirror read it
with the noise of a rare hit (at 256 samples a third of the runs read none
of it, with a standard error of 0, and an adaptive run stopped on such an
underestimated error). :func:`area_image` samples the light as seen from
the receiver's mirror image x' = x − 2(n·x − d)n, with its own sampler and
pdf (its normal mirrored likewise, so the cosine at x' is the one at x):
the direction w' from x' to the light point y crosses the plane at m, and
the real path is x → m → y, leaving x along w' mirrored; reflection keeps
solid angle, so the sample's solid-angle pdf at x is the light's from x'.
The segment x → m must meet a mirror face of the plane, which reflects
c·F(cos θ_m), and m → y passes what lets light through at its share. A
path that makes the same trip (x, a direction sample, a face of that plane
taken as a mirror, the light hit) is the other strategy for the same
light: both are weighed by the power heuristic (``estimators``, with
:func:`image_light_pdf` at the mirror point), the path's density being its
direction's pdf at x times the probability of the mirror event at m (the
glossy vertex's mirror share, a pane's R/(R + T)), so nothing is counted
twice. Only planes that hold a mirror face are sampled so (``scene.
plane_mirror``): a pane reflects R ≈ 4–8%, and its paths find that share at
the noise of any other reflection.
"""

import warp as wp

from simulator.scene.model import LightKind

from .bsdf import mirror_reflectance
from .coverage import coverage_at
from .curved import curve_solve
from .glossy import face_bsdf, mirror_share, spawn_origin
from .lights import RAY_INF, LightRec, SceneRec, pdf_light, sample_light, tri_vertex
from .rays import first_hit, offset_length
from .sampling import pdf_uniform_cone, sample_uniform_cone, to_world
from .shaping import shaping_factor
from .surfaces import MAX_PASSES, pane_rt, pass_factor, transmittance_along

_POINT_M = wp.constant(int(LightKind.POINT))
_DISTANT_M = wp.constant(int(LightKind.DISTANT))
_SPHERE_M = wp.constant(int(LightKind.SPHERE))
_RECT_M = wp.constant(int(LightKind.RECT))
_DISK_M = wp.constant(int(LightKind.DISK))
_CYLINDER_M = wp.constant(int(LightKind.CYLINDER))


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
    pdf: float  # an area light's image sample: its solid-angle pdf at the receiver (0 for a delta light's image)
    tri: int  # the emissive triangle the light sample ends on, −1 for UsdLux lights
    traced: int  # 1 once the connection casts a ray (the ray tally counts it then: kernels.rays.count_shadow_ray)


@wp.func
def has_image(l: LightRec) -> bool:
    """Whether :func:`image_source` connects light ``l``: a point light, or a distant light of any angle."""
    return l.kind == _POINT_M or l.kind == _DISTANT_M


@wp.func(inline=True)
def image_may_exist(scene: SceneRec, li: int, k: int, p: wp.vec3) -> bool:
    """False only where :func:`image_source` surely finds no image of light ``li`` in flat mirror plane
    ``k`` at p: the light wholly on the plane's other side (a point light's centre; every direction of a
    distant light's cone, whose largest component along the plane's normal toward p is
    cos(θ − α) ≤ 0 when n̂·ez ≤ −sin α, with 10⁻⁵ spare for the float32 draw). Settled here, before the
    call (which copies the scene record), the office with a pane takes 7% less CPU per sample: most
    vertices of a room lie on the side of its windows that the sun does not reach."""
    pl = scene.mirror_planes[k]
    pn = wp.vec3(pl[0], pl[1], pl[2])
    side_x = wp.dot(pn, p) - pl[3]
    if side_x == 0.0:
        return False
    l = scene.lights[li]
    if l.kind == _POINT_M:
        return (wp.dot(pn, l.position) - pl[3]) * side_x > 0.0
    c = wp.dot(l.ez, pn) * wp.sign(side_x)
    sin_a = wp.sqrt(wp.max(l.one_minus_cos * (2.0 - l.one_minus_cos), 0.0))
    return c > -sin_a - 1.0e-5


@wp.func
def is_cone_light(l: LightRec) -> bool:
    """A distant light with an angle (the sun's disc): direction samples could meet it, so a path that
    reaches it off a mirror the image source connected leaves it out (module docstring)."""
    return l.kind == _DISTANT_M and l.one_minus_cos > 0.0


@wp.func
def no_image(n: wp.vec3) -> ImageSample:
    """A connection that found nothing."""
    out = ImageSample()
    out.value = wp.vec2(0.0, 0.0)
    out.wi = n
    out.pdf = 0.0
    out.tri = -1
    out.traced = 0
    return out


@wp.struct
class MirrorPoint:
    """Where a connection's ray from the receiver meets the mirror face it aims at (:func:`reach_mirror`)."""

    face: int  # the mirror triangle, −1 where the ray meets none (or a matte face, or nothing passes)
    ng: wp.vec3  # its geometric normal
    t: float  # from the ray's origin to the mirror point
    vis: float  # the share the faces passed on the way let through (panes, cut-outs)
    m_off: wp.vec3  # the mirror point, offset to the receiver's side of the plane
    cover: float  # the face's mirror share there: its coverage, or a translucent layer's gap 1 − c
    pane: int  # the face's surface row's pane kind


@wp.func
def reach_mirror(scene: SceneRec, k: int, o: wp.vec3, wi: wp.vec3, pn: wp.vec3, side_x: float) -> MirrorPoint:
    """Follow the ray (o, wi) through what passes light to a face of mirror plane ``k`` (normal ``pn``, the
    receiver at signed distance ``side_x`` from it): the face, the share passed on the way, and the mirror
    point's coverage (``face`` −1 where it gets there with nothing to reflect)."""
    r = MirrorPoint()
    r.face = -1
    r.ng = pn
    r.t = 0.0
    r.vis = 1.0
    r.m_off = o
    r.cover = 0.0
    r.pane = 0
    vis_in = float(1.0)
    start = float(0.0)
    face = int(-1)
    ng_m = pn
    for j in range(MAX_PASSES):
        if face < 0:
            h = first_hit(scene, o + start * wi, wi, RAY_INF)
            if h.face < 0:
                return r
            if scene.face_mirror[h.face] == k:
                face = h.face
                ng_m = h.ng
                start = start + h.t
            else:
                if scene.surf_id[h.face] < 0:
                    return r  # a matte face blocks it
                q = o + (start + h.t) * wi
                vis_in = vis_in * pass_factor(scene, h.face, wi, h.ng, q)
                if vis_in <= 0.0:
                    return r
                start = start + h.t + offset_length(scene, q)
    if face < 0:
        return r
    m = o + start * wi
    srow = scene.surf[scene.surf_id[face]]
    cover = coverage_at(scene, srow, face, m)
    if srow.pane == 2:  # a translucent layer: its slab is the gap 1 − c, the share c its matte face (surfaces.pass_factor)
        cover = 1.0 - cover
    if cover <= 0.0:
        return r
    side_n = wp.where(side_x > 0.0, pn, -pn)
    r.face = face
    r.ng = ng_m
    r.t = start
    r.vis = vis_in
    r.m_off = m + offset_length(scene, m) * side_n
    r.cover = cover
    r.pane = srow.pane
    return r


@wp.func
def mirror_face_reflectance(scene: SceneRec, mp: MirrorPoint, wi: wp.vec3, cos_m: float) -> float:
    """F of the mirror face at ``mp`` for the ray along ``wi``: a pane's slab reflects R(θ)
    (kernels.surfaces.slab_rt; 0 off a closed pane's inner face), a metal or glossy face its mirror part."""
    if mp.pane != 0:
        return pane_rt(scene, mp.face, wi, mp.ng)[0]
    return mirror_reflectance(face_bsdf(scene, mp.face), cos_m)


@wp.func
def image_found(out: ImageSample, wi: wp.vec3, mp: MirrorPoint, cos_m: float, refl: float, to_l: wp.vec3,
                dist_l: float, vis: float) -> ImageSample:
    """``out`` with the connection's geometry filled in (its value and pdf are the caller's)."""
    out.wi = wi
    out.face = mp.face
    out.cos_m = cos_m
    out.refl = refl
    out.m_off = mp.m_off
    out.to_l = to_l
    out.dist_l = dist_l
    out.vis = vis
    out.t_m = mp.t
    out.vis_in = mp.vis
    out.pane = mp.pane
    return out


@wp.func
def image_source(scene: SceneRec, li: int, k: int, p: wp.vec3, n: wp.vec3, o: wp.vec3, u: wp.vec2,
                 shaded: int) -> ImageSample:
    """The light of light ``li`` (:func:`has_image`) reaching (p, n) off mirror plane ``k``, or off curved
    mirror ``k`` − ``scene.n_mirror_planes`` (:func:`curve_image`); rays start at o (past the face a
    direction heads into, on a ``shaded`` glossy vertex: :func:`.glossy.spawn_origin`); ``u`` draws the
    direction in a distant light's cone."""
    if k >= scene.n_mirror_planes:
        return curve_image(scene, li, k - scene.n_mirror_planes, p, n, o, u)
    out = no_image(n)
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
    o_w = o
    if shaded != 0:
        o_w = spawn_origin(p, o, wi)
    out.traced = 1
    mp = reach_mirror(scene, k, o_w, wi, pn, side_x)  # to a face of plane k, through what passes light
    if mp.face < 0:
        return out
    m = mp.m_off
    to_l = to_sun
    dist_l = float(RAY_INF)
    if l.kind == _POINT_M:
        dl = l.position - (o_w + mp.t * wi)
        dist_l = wp.length(dl)
        to_l = dl / dist_l
    vis = transmittance_along(scene, m, to_l, dist_l, -1)
    if vis <= 0.0:
        return out
    cos_m = wp.abs(dn)
    refl = mirror_face_reflectance(scene, mp, wi, cos_m)
    e = mp.vis * vis * mp.cover * refl * cos_x
    if l.kind == _POINT_M:
        e = e * shaping_factor(l, -to_l) / (dist_img * dist_img)
    else:
        e = e * inv_pdf
    out = image_found(out, wi, mp, cos_m, refl, to_l, dist_l, vis)
    out.value = e * l.emission
    return out


@wp.func
def face_normal(scene: SceneRec, face: int) -> wp.vec3:
    """The unit front normal of triangle ``face``."""
    a = tri_vertex(scene, face, 0)
    return wp.normalize(wp.cross(tri_vertex(scene, face, 1) - a, tri_vertex(scene, face, 2) - a))


@wp.func
def curve_image(scene: SceneRec, li: int, c: int, p: wp.vec3, n: wp.vec3, o: wp.vec3, u: wp.vec2) -> ImageSample:
    """The light of light ``li`` (:func:`has_image`) reaching (p, n) off curved mirror ``c``
    (:mod:`.curved`): E = F·I·cos θ_x/(|l − m|²·|det A|) for a point light, F·E⊥·cos θ_x/|det A| for
    an angle-0 distant one, and for the sun one direction of its cone (pdf 1/Ω) as the latter; rays
    from o."""
    out = no_image(n)
    l = scene.lights[li]
    point = int(0)
    tgt = l.ez
    inv_pdf = float(1.0)
    if l.kind == _POINT_M:
        point = 1
        tgt = l.position
    elif l.kind == _DISTANT_M:
        if l.one_minus_cos > 0.0:  # one direction of the cone, pdf 1/Ω
            tgt = to_world(sample_uniform_cone(u, l.one_minus_cos), l.ez)
            inv_pdf = 1.0 / pdf_uniform_cone(l.one_minus_cos)
    else:
        return out
    sph = scene.curve_sphere[c]
    if wp.dot(n, wp.vec3(sph[0], sph[1], sph[2]) - p) <= -sph[3]:
        return out  # the mirror lies wholly behind the receiver's plane
    out.traced = 1
    cs = curve_solve(scene, c, o, tgt, point)
    if cs.ok == 0:
        return out
    cos_x = wp.dot(cs.d, n)
    if cos_x <= 0.0:
        return out
    face = cs.face
    cover = coverage_at(scene, scene.surf[scene.surf_id[face]], face, cs.m)
    if cover <= 0.0:
        return out
    ng = face_normal(scene, face)
    side = wp.where(wp.dot(cs.q, ng) > 0.0, ng, -ng)  # the reflected ray leaves past the face it heads into
    m_off = cs.m + offset_length(scene, cs.m) * side
    dist_l = float(RAY_INF)
    if point != 0:
        dist_l = cs.dist
    vis = transmittance_along(scene, m_off, cs.q, dist_l, -1)
    if vis <= 0.0:
        return out
    cos_m = wp.abs(wp.dot(cs.d, cs.ns))
    refl = mirror_reflectance(face_bsdf(scene, face), cos_m)
    e = cs.vis_in * vis * cover * refl * cos_x / cs.det
    if point != 0:
        e = e * shaping_factor(l, -cs.q) / (cs.dist * cs.dist)
    else:
        e = e * inv_pdf
    out.wi = cs.d
    out.value = e * l.emission
    out.face = face
    out.cos_m = cos_m
    out.refl = refl
    out.m_off = m_off
    out.to_l = cs.q
    out.dist_l = dist_l
    out.vis = vis
    out.t_m = cs.t
    out.vis_in = cs.vis_in
    out.pane = 0
    return out


@wp.func
def has_area_image(scene: SceneRec, l: LightRec) -> bool:
    """Whether :func:`area_image` samples light ``l``: a sphere, disk, rect or cylinder light, on a stage
    with a flat mirror plane."""
    if scene.n_mirror_planes == 0:
        return False
    return l.kind == _SPHERE_M or l.kind == _RECT_M or l.kind == _DISK_M or l.kind == _CYLINDER_M


@wp.func
def mirror_image_point(pl: wp.vec4, p: wp.vec3) -> wp.vec3:
    """p reflected in the plane n·x = d."""
    pn = wp.vec3(pl[0], pl[1], pl[2])
    return p - (2.0 * (wp.dot(pn, p) - pl[3])) * pn


@wp.func
def mirror_image_dir(pl: wp.vec4, v: wp.vec3) -> wp.vec3:
    """Direction v reflected in the plane of normal n (pl's first three numbers)."""
    pn = wp.vec3(pl[0], pl[1], pl[2])
    return v - (2.0 * wp.dot(pn, v)) * pn


@wp.func
def mirror_event_prob(scene: SceneRec, face: int, d: wp.vec3, ng: wp.vec3, pm: float) -> float:
    """The probability a path's ray along ``d`` takes face ``face`` as a mirror once it stops there: a pane's
    slab reflects with R/(R + T) (:func:`.surfaces.surface_event`), a glossy face's mirror part with ``pm``
    (:func:`.glossy.mirror_share`)."""
    s = scene.surf[scene.surf_id[face]]
    if s.pane != 0:
        rt = pane_rt(scene, face, d, ng)
        if rt[0] + rt[1] <= 0.0:
            return 0.0
        return rt[0] / (rt[0] + rt[1])
    return pm


@wp.func
def area_image(scene: SceneRec, li: int, k: int, p: wp.vec3, n: wp.vec3, o: wp.vec3, u: wp.vec3,
               shaded: int) -> ImageSample:
    """One sample of area light ``li`` (:func:`has_area_image`) seen from (p, n) in flat mirror plane ``k``
    (module docstring): drawn by the light's sampler from p's image, its value L·cos θ·c·F·(visibility)/pdf
    and its solid-angle pdf at p; rays start at o (:func:`image_source`)."""
    out = no_image(n)
    pl = scene.mirror_planes[k]
    pn = wp.vec3(pl[0], pl[1], pl[2])
    side_x = wp.dot(pn, p) - pl[3]
    if side_x == 0.0:
        return out
    ls = sample_light(scene, li, mirror_image_point(pl, p), mirror_image_dir(pl, n), u)
    if ls.pdf <= 0.0 or (ls.value[0] <= 0.0 and ls.value[1] <= 0.0):
        return out
    dn = wp.dot(ls.wi, pn)
    if dn * side_x <= 0.0:
        return out  # from the image away from the plane: the light is not seen in it
    t_plane = side_x / dn  # from the image to the plane along w'
    if t_plane >= ls.dist:
        return out  # the light lies beyond the mirror
    wi = mirror_image_dir(pl, ls.wi)
    if wp.dot(wi, n) <= 0.0:
        return out
    o_w = o
    if shaded != 0:
        o_w = spawn_origin(p, o, wi)
    out.traced = 1
    mp = reach_mirror(scene, k, o_w, wi, pn, side_x)
    if mp.face < 0:
        return out
    dist_l = ls.dist - t_plane
    vis = transmittance_along(scene, mp.m_off, ls.wi, dist_l, ls.tri)
    if vis <= 0.0:
        return out
    cos_m = wp.abs(dn)
    refl = mirror_face_reflectance(scene, mp, wi, cos_m)
    l = scene.lights[li]
    out = image_found(out, wi, mp, cos_m, refl, ls.wi, dist_l, vis)
    out.value = ls.value * (mp.vis * vis * mp.cover * refl * shaping_factor(l, -ls.wi))
    out.pdf = ls.pdf
    out.tri = ls.tri
    return out


@wp.func
def area_image_mirror_prob(scene: SceneRec, im: ImageSample) -> float:
    """The probability a path along the sample's direction takes its mirror face as a mirror
    (:func:`mirror_event_prob`: the path strategy's discrete share of the same trip)."""
    if im.pane != 0:
        return mirror_event_prob(scene, im.face, im.wi, face_normal(scene, im.face), 0.0)
    return mirror_share(face_bsdf(scene, im.face), im.cos_m)


@wp.func
def image_light_pdf(scene: SceneRec, li: int, face: int, x: wp.vec3, nx: wp.vec3, o: wp.vec3, wi: wp.vec3,
                    t: float) -> float:
    """The solid-angle pdf with which :func:`area_image` at the vertex (x, nx) before a mirror point would
    have drawn the path's light point: the light's pdf from x's image in the plane of mirror ``face``
    toward the ray (o, wi) that left the mirror point and meets the light at distance t; 0 where
    :func:`area_image` does not sample that light in that face."""
    k = scene.face_mirror[face]
    if k < 0:
        return 0.0
    if scene.plane_mirror[k] == 0 or not has_area_image(scene, scene.lights[li]):
        return 0.0
    pl = scene.mirror_planes[k]
    pn = wp.vec3(pl[0], pl[1], pl[2])
    if wp.dot(pn, x) - pl[3] == 0.0:
        return 0.0
    x_img = mirror_image_point(pl, x)
    return pdf_light(scene, li, x_img, mirror_image_dir(pl, nx), wi, wp.length(o - x_img) + t, -1)
