"""The device record of one surface beyond Lambert (a row of ``Geometry.surfaces``).

With :class:`TexRec`, an opacity texture read per texel. Kept apart from
:mod:`.surfaces` (the functions that read them) so that
:class:`~simulator.kernels.lights.base.SceneRec` can hold a table of them
without importing the ray code.
"""

import warp as wp


@wp.struct
class SurfRec:
    coverage: float  # probability in (0, 1] that a ray meets the surface (presence, cut-outs); 1: opaque
    # 1: a dielectric slab of ior where the surface is (thin pane, or a face of a slab-like closed mesh);
    # 2: a translucent layer: the share ``coverage`` is the matte face, the rest (the gap) that slab
    pane: int
    ior: float  # index of refraction (≥ 1)
    tau: float  # internal transmittance of one normal pass through the pane (1: clear)
    # the UsdPreviewSurface BSDF (kernels.bsdf), when glossy is 1; the diffuse ρ is the face's albedo
    glossy: int
    roughness: float
    metallic: float
    specular: float  # the specular workflow's F0 (grey)
    workflow: int  # 1: specular workflow
    coat: float
    coat_roughness: float
    # per-texel coverage (kernels.coverage): textured 1 reads the face's opacity texture at the hit
    # (scene.tex_id[face] ≥ 0; else ``coverage``); threshold > 0: c = 1 where opacity ≥ it, else 0
    textured: int
    threshold: float


@wp.struct
class TexRec:
    """One opacity texture (``Geometry.coverage_textures``): ``h × w`` texels of ``scene.texels`` from
    ``offset``, row 0 at the top (t = 1); wrap codes per axis (0 black, 1 clamp, 2 repeat, 3 mirror);
    ``border`` the value a black wrap reads outside the image."""

    offset: int
    w: int
    h: int
    wrap_s: int
    wrap_t: int
    border: float


@wp.struct
class GlintRec:
    """One glint pair (:mod:`.glints`): a flat glossy plane n·x = d and a distant light whose glossy
    reflection in it the glint strategy samples; ``alpha`` the plane's GGX α."""

    plane: wp.vec4  # (n, d), n unit
    alpha: float
    light: int  # index into scene.lights (a distant light)
    s: wp.vec3  # the unit direction toward that light (its +ez), kept here so no light record is read
