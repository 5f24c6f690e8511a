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
"""

import warp as wp

from .bsdf import COAT_F0, Bsdf, has_mirror, is_delta_coat, is_delta_specular, mirror_reflectance, preview_bsdf, schlick
from .lights import SceneRec


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
