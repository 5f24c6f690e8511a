"""Path vertices on glossy faces: the face's BSDF and the choice of its mirror part, as ``@wp.func``.

A face whose surface row is glossy (``SurfRec.glossy``) scatters by the
UsdPreviewSurface BSDF of :mod:`.bsdf`, its diffuse ρ the face's albedo. At
such a vertex (see ``estimators.vertex_estimate``) light samples are
weighted by π·f(wi, wo) (the vertex's weight carries the arriving
throughput over π, as a diffuse vertex's carries ρ/π), the next direction
is drawn by :func:`.bsdf.bsdf_sample`, and both are combined by multiple
importance sampling with the BSDF's pdf. A mirror (delta) specular part is
chosen with probability :func:`mirror_share` and followed as a delta
vertex (no light sample can find it).

**Shading normals.** A glossy face cut from a curved surface (an authored
``normals`` primvar, an implicit Sphere's own; ``SceneRec.shade_id`` ≥ 0,
:mod:`simulator.scene.usd.normals`) reflects about its shading normal
:func:`shading_normal`, the corners' normals interpolated at the hit (the
true normal of a Sphere, whose corner normals are its radii: normalize(Σ
b_i n_i) = normalize(p − c) at the facet point p). Everything a glossy
vertex evaluates, as pbrt-v4 does it (its ``BSDF`` works in the shading
frame alone): the BSDF's value, pdf and samples, the mirror direction and
the cosine of light samples, in the frame of the shading normal
(:func:`vertex_normal`, turned to the viewer's side as pbrt-v4's two-sided
BxDFs do); a ray (a direction sample or a shadow ray) leaves from the side
of the geometric face its direction points to (:func:`spawn_origin`,
pbrt-v4's ``OffsetRayOrigin``), so a direction above the shading horizon
but below the facet (a reflected ray near a silhouette, a light just below
the facet's plane) enters the solid and meets its inside: a closed surface
stops it (no light leaks through a closed mirror ball, whose inside sees no
light), an open sheet passes it as pbrt-v4 does. Matte faces keep their
face normal (a shading normal changes little of a diffuse reading, and the
matte trace stays the one it was).
"""

import warp as wp

from .bsdf import COAT_F0, Bsdf, has_mirror, is_delta_coat, is_delta_specular, mirror_reflectance, preview_bsdf, schlick
from .lights import SceneRec, tri_params, tri_vertex


@wp.func
def is_glossy(scene: SceneRec, face: int) -> bool:
    """Whether triangle ``face`` scatters by the BSDF rather than Lambert (only read when scene.surfaces)."""
    if face < 0:
        return False
    sid = scene.surf_id[face]
    if sid < 0:
        return False
    return scene.surf[sid].glossy != 0


@wp.func
def face_bsdf(scene: SceneRec, face: int) -> Bsdf:
    """The BSDF of a glossy triangle: its surface row's lobes over its albedo."""
    s = scene.surf[scene.surf_id[face]]
    return preview_bsdf(scene.albedo[face], s.roughness, s.metallic, s.ior, s.specular, s.workflow, s.coat,
                        s.coat_roughness)


@wp.func
def mirror_share(b: Bsdf, co: float) -> float:
    """Probability of following the mirror (delta) part at a vertex viewed at cosine co: its reflectance
    over itself plus the other lobes' Fresnel-weighted shares (0 without a delta lobe, 1 for a pure
    mirror). The delta part is a mirror base, a mirror clearcoat or both (:func:`.bsdf.mirror_reflectance`)."""
    if not has_mirror(b):
        return 0.0
    wm = mirror_reflectance(b, co)
    fs = schlick(b.f0, b.f90, co)
    rest = (1.0 - fs) * b.diffuse
    if not is_delta_coat(b):
        rest += b.coat * schlick(COAT_F0, 1.0, co)
    if not is_delta_specular(b):
        rest += fs
    if wm + rest <= 0.0:
        return 0.0
    return wm / (wm + rest)


@wp.func
def shading_normal(scene: SceneRec, face: int, p: wp.vec3, n: wp.vec3) -> wp.vec3:
    """The unit shading normal at p on ``face``, on the side of ``n`` (the face's normal toward the viewer):
    its corner normals (``scene.shade_n``) interpolated at p's barycentric weights; ``n`` itself on a face
    without them."""
    if scene.n_shaded == 0 or face < 0:
        return n
    k = scene.shade_id[face]
    if k < 0:
        return n
    st = tri_params(scene, face, p)
    b1 = wp.clamp(st[0], 0.0, 1.0)
    b2 = wp.clamp(st[1], 0.0, 1.0 - b1)
    v = (1.0 - b1 - b2) * scene.shade_n[3 * k] + b1 * scene.shade_n[3 * k + 1] + b2 * scene.shade_n[3 * k + 2]
    ln = wp.length(v)
    if ln <= 0.0:
        return n
    a = tri_vertex(scene, face, 0)
    front = wp.cross(tri_vertex(scene, face, 1) - a, tri_vertex(scene, face, 2) - a)
    return wp.where(wp.dot(front, n) < 0.0, -1.0 / ln, 1.0 / ln) * v


@wp.func
def is_shaded(scene: SceneRec, face: int) -> bool:
    """Whether ``face`` has a shading normal of its own (:func:`shading_normal`)."""
    if scene.n_shaded == 0 or face < 0:
        return False
    return scene.shade_id[face] >= 0


@wp.func
def vertex_normal(scene: SceneRec, face: int, p: wp.vec3, n: wp.vec3, wo: wp.vec3) -> wp.vec3:
    """The normal a glossy vertex's BSDF frame stands on: :func:`shading_normal`, turned to the side of
    the direction ``wo`` toward the viewer where the viewer sees it from below (near a silhouette: pbrt-v4's
    BxDFs are two-sided, so a mirror still reflects wo about it)."""
    ns = shading_normal(scene, face, p, n)
    if wp.dot(ns, wo) < 0.0:
        return -ns
    return ns


@wp.func
def spawn_origin(p: wp.vec3, o: wp.vec3, wi: wp.vec3) -> wp.vec3:
    """Where a ray along ``wi`` leaves the surface point p whose rays start at o = p + δ·n (the geometric
    normal's side of the viewer): o, or p − δ·n when wi points below the face (pbrt-v4's
    ``OffsetRayOrigin``: a ray leaves from the side of the geometric face it heads into)."""
    return wp.where(wp.dot(wi, o - p) < 0.0, p - (o - p), o)
