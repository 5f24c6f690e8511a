"""Delta lights seen in planar mirrors: the image-source connection, as ``@wp.func``.

A point light (or an angle-0 distant light) reflected by a mirror (a face
whose specular lobe is a delta, :func:`.bsdf.is_delta_specular`) reaches a
receiver along one direction only, which neither a light sample (it aims at
the light itself) nor a direction sample (a delta meets a delta with
probability 0) can find. Each flat mirror plane k (``scene.mirror_planes``,
n·x = d, grouped on the host) gives the light an image: the point reflected
in the plane, L' = L − 2(n·L − d) n (a distant light: its direction
reflected). The receiver at x connects to the image: the segment must meet
the plane on a mirror face of plane k, and from that point m the light must
be visible (panes and cut-outs pass their share, :func:`.surfaces.
transmittance_along`). Its irradiance on (x, n_x) is then exactly

    E = I(ω) · F(cos θ_m) · cos θ_x / |x − L'|²    (point, intensity I toward m)
    E = E⊥ · F(cos θ_m) · cos θ_x                  (distant)

with F the mirror's reflectance at its incidence angle (:func:`.bsdf.
mirror_reflectance`): the image source of a plane mirror. One reflection
only (light seen through two mirrors is not connected).
"""

import warp as wp

from simulator.scene.model import LightKind

from .bsdf import mirror_reflectance
from .glossy import face_bsdf
from .lights import RAY_INF, SceneRec
from .rays import first_hit, offset_length
from .shaping import shaping_factor
from .surfaces import transmittance_along

_POINT_M = wp.constant(int(LightKind.POINT))
_DISTANT_M = wp.constant(int(LightKind.DISTANT))


@wp.struct
class ImageSample:
    wi: wp.vec3  # unit direction from the receiver toward the image (and the mirror)
    value: wp.vec2  # irradiance on the receiver's plane (W/m², lx), 0 when the connection fails
    # for spectral lanes (kernels.spectral_surfaces): the mirror triangle, its incidence cosine and
    # (grey) reflectance, and the segment toward the light with its (grey) visibility
    face: int
    cos_m: float
    refl: float
    m_off: wp.vec3
    to_l: wp.vec3
    dist_l: float
    vis: float


@wp.func
def image_source(scene: SceneRec, li: int, k: int, p: wp.vec3, n: wp.vec3, o: wp.vec3) -> ImageSample:
    """The light of delta light ``li`` reaching (p, n) off mirror plane ``k``; rays start at o."""
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
    elif l.kind == _DISTANT_M and l.one_minus_cos <= 0.0:
        if wp.dot(l.ez, pn) * side_x <= 0.0:
            return out  # the sun lights the other side of the mirror
        wi = l.ez - (2.0 * wp.dot(l.ez, pn)) * pn
    else:
        return out
    cos_x = wp.dot(wi, n)
    if cos_x <= 0.0:
        return out
    dn = wp.dot(wi, pn)
    if dn * side_x >= 0.0:
        return out  # heading away from the plane
    h = first_hit(scene, o, wi, RAY_INF)
    if h.face < 0 or scene.face_mirror[h.face] != k:
        return out
    m = o + h.t * wi
    to_l = l.ez
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
    refl = mirror_reflectance(face_bsdf(scene, h.face), cos_m)
    e = vis * refl * cos_x
    if l.kind == _POINT_M:
        e = e * shaping_factor(l, -to_l) / (dist_img * dist_img)
    out.wi = wi
    out.value = e * l.emission
    out.face = h.face
    out.cos_m = cos_m
    out.refl = refl
    out.m_off = m_off
    out.to_l = to_l
    out.dist_l = dist_l
    out.vis = vis
    return out
