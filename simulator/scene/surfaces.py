"""Surfaces beyond Lambert: the per-material table the reader fills and the thin-slab closed forms.

Most faces of a stage are matte: their albedo (``Geometry.albedo``) is all
the kernels read. A material whose UsdPreviewSurface inputs make a face more
than matte gets one :class:`Surface` row in ``Geometry.surfaces``, and its
faces that row's index in ``Geometry.surface_id`` (-1: matte). Few
materials, many faces: the table stays small.

What is modelled (the rest is read, validated and named in the summary
warning):

- **coverage** (``opacityMode = "presence"``, or ``opacityThreshold`` > 0):
  a ray meets the surface with probability ``coverage`` and otherwise passes
  it untouched. With a threshold the coverage is 1 where ``opacity`` ≥ the
  threshold and 0 (the face is left out) below it (UsdPreviewSurface:
  "fragments with opacity < opacityThreshold are fully transparent").
  Where a ``UsdUVTexture`` drives ``opacity`` the coverage is read per
  texel at the hit (:class:`CoverageTexture`; ``Surface.opacity_texture``).
- **panes** (``opacity`` 0 in the default ``transparent`` mode, or a
  ``probesim:transmittance``): a dielectric of the material's ``ior``. An
  open surface is a *thin slab*: two parallel interfaces with no offset
  between them, the inner reflections summed (:func:`slab_rt`). A face of a
  closed (watertight) mesh is one face of a slab-like solid: a ray entering
  it meets the whole slab (reflectance and transmittance of
  :func:`slab_rt`), the face it leaves by passes it (its share was summed on
  entry). Two parallel faces a few millimetres apart (glazing exported as a
  thin box) are then exactly the sheet; a solid that is not a parallel slab
  (a lens, a glass sphere) keeps the slab's reflectance and transmittance
  but not refraction's bend (named in the summary warning).
- **translucent layers** (0 < ``opacity`` < 1 in ``transparent`` mode,
  ``Surface.layered``): the face is its opaque (matte) surface over a share
  ``opacity`` of it and a clear pane of its ``ior`` over the rest, so it
  passes (1 − o)·T(θ) and reflects (1 − o)·R(θ) of the light as a mirror,
  and a share o scatters off the matte part. This is the reading of
  UsdPreviewSurface's own path-traced reference (OpenUSD's hdPrman,
  ``UsdPreviewSurfaceParameters.osl``: for opacity < 1 the diffuse gain is
  ``opacity``, the refraction gain ``1 − opacity``, glass of ``ior`` at
  roughness 0). Two such layers pass (1 − o)²·T² (at ior 1: (1 − o)²).
  ``coverage`` holds o; an opacity texture gives o per texel.

Thin-slab formulas (unpolarised light, each polarisation summed on its own,
then averaged; Born & Wolf, *Principles of Optics*, §1.5; the incoherent
multiple-reflection sum of a plane-parallel plate, docs/REFERENCES.md
§Thin slab). With r the single-interface Fresnel reflectance of one
polarisation at the angle of incidence θ and τ the internal transmittance
of one pass at that angle,

    T = (1 − r)² τ / (1 − r² τ²),    R = r + (1 − r)² r τ² / (1 − r² τ²),

and for a clear slab (τ = 1) T = (1 − r)/(1 + r), R = 2r/(1 + r). A pane
given by its normal-incidence transmittance T₀ (``probesim:transmittance``)
has the τ₀ that gives T₀ at θ = 0 (:func:`internal_transmittance`), and at
θ the path length through the glass grows as 1/cos θ_t (Snell: sin θ_t =
sin θ / n), so τ(θ) = τ₀^(1/cos θ_t): the ior's angular fall-off.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Surface", "CoverageTexture", "WRAP_MODES", "OPACITY_MODES", "fresnel_sp", "slab_rt", "internal_transmittance", "clear_slab_transmittance",
           "solid_sides", "mirror_planes", "mirror_limits", "glint_planes", "glint_pairs", "MAX_GLINTS", "shaded_faces",
           "curved_mirrors", "curved_notes", "CurvedMirrors", "MAX_CURVES"]

#: UsdPreviewSurface ``opacityMode`` tokens
OPACITY_MODES = ("transparent", "presence")

#: UsdUVTexture ``wrapS`` / ``wrapT`` tokens probesim reads, in the order of their kernel codes
#: (:func:`simulator.kernels.coverage.wrap_index`); ``useMetadata`` is read as ``black`` (below)
WRAP_MODES = ("black", "clamp", "repeat", "mirror")


@dataclass(frozen=True)
class CoverageTexture:
    """The per-texel opacity a ``UsdUVTexture`` feeds into ``inputs:opacity``, decoded.

    Attributes
    ----------
    name : str
        The UsdUVTexture prim and the file it reads, for messages and the plan.
    opacity : ndarray, shape (H, W), float32
        ``scale·decode(texel) + bias`` of the output's channel, clipped to
        [0, 1]; row 0 at the top of the image (``t`` = 1).
    wrap : tuple of (str, str)
        ``wrapS``, ``wrapT``: one of :data:`WRAP_MODES`.
    border : float
        The value outside the image where a wrap is ``black``: ``bias``
        clipped to [0, 1] (a black texel, scaled and biased).
    primvar : str
        The texture coordinate primvar a ``UsdPrimvarReader_float2`` reads
        (``varname``), without the ``primvars:`` prefix.
    st_affine : ndarray, shape (2, 3), float64
        A ``UsdTransform2d`` between reader and texture as ``st' = A @ (s, t, 1)``:
        ``in·scale``, rotated by ``rotation`` degrees, plus ``translation``;
        the identity without one.
    """

    name: str
    opacity: np.ndarray
    wrap: tuple = ("black", "black")
    border: float = 0.0
    primvar: str = "st"
    st_affine: np.ndarray = field(default_factory=lambda: np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))

    @property
    def mean(self) -> float:
        """The texture's mean opacity over its texels (the coverage of a face without texture coordinates)."""
        return float(np.mean(self.opacity))


@dataclass(frozen=True)
class Surface:
    """One material's UsdPreviewSurface inputs beyond Lambert, validated.

    Attributes
    ----------
    name : str
        The material's prim path.
    coverage : float
        Probability in (0, 1] that a ray meets the surface (1: opaque); on a
        ``layered`` row the share o of the face that is opaque (the rest is
        the pane).
    pane : bool
        A dielectric pane of ``ior``: thin slab (open surface) or slab-like
        solid (closed mesh).
    layered : bool
        A translucent layer (``transparent`` mode, 0 < opacity < 1; module
        docstring): ``coverage`` of the face is its matte surface, the rest
        the pane (``pane`` is then True too).
    thin_walled : bool
        A pane whose every face is a thin sheet, on a closed mesh too (MaterialX
        ``thin_walled``, MDL ``thin_walled``); else a closed pane mesh is a
        slab-like solid entered once.
    ior : float
        Index of refraction (≥ 1).
    tau : float
        Internal transmittance of one normal pass through the pane, in
        (0, 1]: 1 for clear glass, below 1 for a datasheet transmittance.
    transmittance : float or None
        The authored ``probesim:transmittance`` (normal incidence), if any.
    glossy : bool
        The face has the UsdPreviewSurface BSDF (:mod:`simulator.kernels.bsdf`):
        some of roughness, metallic, specularColor, useSpecularWorkflow,
        clearcoat, clearcoatRoughness authored away from their fallbacks.
    roughness, metallic, clearcoat, clearcoat_roughness : float
        In [0, 1].
    specular_color : tuple of float
    use_specular_workflow : bool
    opacity, opacity_threshold : float
    opacity_mode : str
    unmodelled : tuple of str
        The inputs authored away from their fallback that no lobe models yet
        (for the summary warning and the plan).
    opacity_texture : int
        Index into ``Geometry.coverage_textures`` of the texture whose texels
        give the coverage (presence: c = opacity(st); a threshold: c = 1 where
        opacity(st) ≥ it, else 0), -1 for none; ``coverage`` is then what a
        face without texture coordinates gets (from the texture's mean).
    transmittance_spectrum : (str, ndarray (401,)) or None
        A pane's measured normal-incidence transmittance T0(λ) (file name and
        values on the grid; ``transmittance`` is its grey), for spectral runs.
    """

    name: str
    coverage: float = 1.0
    pane: bool = False
    layered: bool = False
    thin_walled: bool = False
    ior: float = 1.5
    tau: float = 1.0
    transmittance: float | None = None
    roughness: float = 0.5
    metallic: float = 0.0
    clearcoat: float = 0.0
    clearcoat_roughness: float = 0.01
    specular_color: tuple = (0.0, 0.0, 0.0)
    use_specular_workflow: bool = False
    opacity: float = 1.0
    opacity_threshold: float = 0.0
    opacity_mode: str = "transparent"
    unmodelled: tuple = field(default_factory=tuple)
    glossy: bool = False
    opacity_texture: int = -1
    transmittance_spectrum: tuple | None = field(default=None, compare=False)

    @property
    def modelled(self) -> bool:
        """Whether the kernels read anything of this row beyond the face's albedo."""
        return self.pane or self.coverage < 1.0 or self.glossy or self.opacity_texture >= 0

    @property
    def specular_grey(self) -> float:
        """The specular workflow's F0 as a luminance grey (BT.709 weights)."""
        r, g, b = self.specular_color
        return 0.2126 * r + 0.7152 * g + 0.0722 * b

    @property
    def delta_base(self) -> bool:
        """The base specular lobe is a mirror (roughness ≤ 0.01, :data:`simulator.kernels.bsdf.DELTA_ROUGHNESS`)."""
        return self.glossy and self.roughness <= 0.01

    @property
    def delta_coat(self) -> bool:
        """The clearcoat is there and a mirror (clearcoatRoughness ≤ 0.01; its fallback is)."""
        return self.glossy and self.clearcoat > 0.0 and self.clearcoat_roughness <= 0.01

    @property
    def delta(self) -> bool:
        """The BSDF has a mirror part, its base or its clearcoat (:func:`simulator.kernels.bsdf.has_mirror`):
        its faces belong to the image-source connection's mirror planes."""
        return self.delta_base or self.delta_coat

    def lobes(self) -> tuple[str, ...]:
        """What this surface needs beyond a matte face, in words, for the plan."""
        out = []
        if self.opacity_texture >= 0:
            rule = (f"opacity >= {self.opacity_threshold:g}" if self.opacity_threshold > 0
                    else "translucent layer" if self.layered else "presence")
            out.append(f"coverage per texel ({rule})")
        elif self.coverage < 1.0 and not self.layered:
            out.append(f"coverage {self.coverage:g}")
        if self.layered:
            out.append(f"translucent: matte over {self.coverage:g} of it, a clear slab (ior {self.ior:g}) over the rest")
        elif self.pane:
            what = f"T0 {self.transmittance:g}" if self.transmittance is not None else "clear"
            if self.transmittance_spectrum is not None:
                what += f" from {self.transmittance_spectrum[0]}"
            out.append(f"dielectric slab (ior {self.ior:g}, {what})")
        if self.glossy:
            spec = ("mirror (delta)" if self.delta_base else f"GGX specular (roughness {self.roughness:g})")
            wf = (f"specular workflow F0 {self.specular_grey:.3g}" if self.use_specular_workflow
                  else f"metallic {self.metallic:g}, ior {self.ior:g}")
            out.append(f"diffuse + {spec}, {wf}" + (f" + clearcoat {self.clearcoat:g}" + (" (mirror)" if self.delta_coat else "")
                                                         if self.clearcoat > 0 else ""))
        return tuple(out)


def fresnel_sp(cos_i, n: float):
    """Fresnel reflectances ``(r_s, r_p)`` of one interface from a medium of index 1 into one of index
    ``n`` ≥ 1, at incidence cosines ``cos_i`` (array-like, in [0, 1]); no total internal reflection."""
    c = np.clip(np.asarray(cos_i, float), 0.0, 1.0)
    s2 = 1.0 - c * c
    ct = np.sqrt(np.maximum(0.0, 1.0 - s2 / (n * n)))
    rs = ((c - n * ct) / (c + n * ct)) ** 2
    rp = ((n * c - ct) / (n * c + ct)) ** 2
    return rs, rp


def slab_rt(cos_i, n: float, tau0: float = 1.0):
    """Unpolarised reflectance and transmittance ``(R, T)`` of a plane-parallel slab of index ``n``
    at incidence cosines ``cos_i``, internal transmittance ``tau0`` per normal pass (module docstring)."""
    c = np.clip(np.asarray(cos_i, float), 0.0, 1.0)
    ct = np.sqrt(np.maximum(0.0, 1.0 - (1.0 - c * c) / (n * n)))
    tau = tau0 ** (1.0 / np.maximum(ct, 1e-12)) if tau0 < 1.0 else np.ones_like(c)
    R = np.zeros_like(c)
    T = np.zeros_like(c)
    for r in fresnel_sp(c, n):
        den = 1.0 - r * r * tau * tau
        T = T + 0.5 * (1.0 - r) ** 2 * tau / den
        R = R + 0.5 * (r + (1.0 - r) ** 2 * r * tau * tau / den)
    return R, T


def clear_slab_transmittance(n: float) -> float:
    """Normal-incidence transmittance of a clear slab of index ``n``: 2n/(n² + 1)."""
    return 2.0 * n / (n * n + 1.0)


def internal_transmittance(t0: float, n: float) -> float:
    """τ₀ in (0, 1] for which a slab of index ``n`` transmits ``t0`` at normal incidence.

    Solves t0 = (1 − r)² τ / (1 − r² τ²), r = ((n − 1)/(n + 1))², for τ:
    t0·r²·τ² + (1 − r)²·τ − t0 = 0, the positive root.

    Raises
    ------
    ValueError
        ``t0`` is not in (0, the clear slab's transmittance].
    """
    clear = clear_slab_transmittance(n)
    if not (0.0 < t0 <= clear + 1e-12):
        raise ValueError(f"{t0:g} is above the {clear:.4f} a clear slab of ior {n:g} transmits")
    r = ((n - 1.0) / (n + 1.0)) ** 2
    a, b = t0 * r * r, (1.0 - r) ** 2
    if a == 0.0:
        return min(1.0, t0 / b)
    tau = (-b + math.sqrt(b * b + 4.0 * a * t0)) / (2.0 * a)
    return min(1.0, tau)


def solid_sides(points: np.ndarray, triangles: np.ndarray, prim: np.ndarray, pane: np.ndarray) -> np.ndarray:
    """Per triangle: 0 for an open pane face (a thin slab), +1 for a face of a closed pane mesh whose front
    faces outward, −1 for one whose back does; 0 where ``pane`` is False.

    The pane faces of each prim are welded by position, split into connected
    components, and a component is closed when every edge is shared by an
    even number of its triangles (as :mod:`simulator.scene.enclosures`
    finds enclosures); its orientation is the sign of its signed volume
    Σ p0·(p1 × p2)/6.
    """
    from simulator.scene.enclosures import _closed_components, _components, _welded

    side = np.zeros(len(triangles), np.int8)
    faces = np.flatnonzero(pane)
    for pid in np.unique(prim[faces]):
        mine = faces[prim[faces] == pid]
        tris = _welded(points, triangles[mine])
        label = _components(tris)
        for comp in _closed_components(tris, label):
            members = mine[label == comp]
            p = points[triangles[members]]
            vol = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0
            side[members] = 1 if vol > 0 else -1
    return side


#: most flat mirror planes the image-source connection of delta lights looks at (the rest: named in the plan)
MAX_MIRROR_PLANES = 16


def _flat_planes(points: np.ndarray, triangles: np.ndarray, faces: np.ndarray, keep: int):
    """Group ``faces`` by their plane: ``(planes (K, 4) as (n, d) with n·x = d, group per face (−1 past
    the kept ones), area per kept plane, groups found)``, the ``keep`` largest by area first.

    Triangles are grouped by their unit normal (sign made canonical: the first non-zero component
    positive) and offset, rounded to 1e-6 (of a metre, or of the scene's extent when larger).
    """
    p = points[triangles[faces]]
    cr = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area = 0.5 * np.linalg.norm(cr, axis=1)
    n = cr / np.maximum(2 * area, 1e-300)[:, None]
    lead = np.take_along_axis(n, np.argmax(np.abs(n) > 1e-9, axis=1)[:, None], axis=1)[:, 0]
    n = n * np.where(lead < 0, -1.0, 1.0)[:, None]
    d = np.einsum("ij,ij->i", n, p[:, 0])
    scale = max(1.0, float(np.abs(points).max()))
    key = np.round(np.column_stack([n, d / scale]) * 1e6).astype(np.int64)
    uniq, inv = np.unique(key, axis=0, return_inverse=True)
    inv = inv.ravel()
    size = np.bincount(inv, weights=area)
    order = np.argsort(-size, kind="stable")[:keep]
    planes = np.zeros((len(order), 4))
    group = np.full(len(faces), -1, np.int64)
    for k, u in enumerate(order):
        mine = inv == u
        nn = n[mine].mean(axis=0)
        nn /= np.linalg.norm(nn)
        planes[k] = [*nn, float(np.mean(p[mine][:, 0] @ nn))]
        group[mine] = k
    return planes, group, size[order], len(uniq)


def mirror_planes(points: np.ndarray, triangles: np.ndarray, surface_id: np.ndarray | None,
                  surfaces: list, shaded: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, int]:
    """The flat planes of the mirror faces (a delta specular lobe) and of panes: ``(planes (K, 4) as (n, d) with
    n·x = d, per triangle its plane or -1, planes left out beyond MAX_MIRROR_PLANES)``, grouped by
    :func:`_flat_planes`, the largest (by area) kept first. Faces ``shaded`` by normals of their own
    (:func:`shaded_faces`) are curved, not flat: :func:`curved_mirrors` holds them.
    """
    face_plane = np.full(len(triangles), -1, np.int32)
    if surface_id is None:
        return np.zeros((0, 4)), face_plane, 0
    # a pane's slab reflects as a mirror does (its R(θ)): its faces are image-source planes too
    delta = np.array([getattr(s, "delta", False) or getattr(s, "pane", False) for s in surfaces] + [False],
                     bool)[surface_id]
    if shaded is not None:
        delta = delta & ~shaded
    faces = np.flatnonzero(delta)
    if not len(faces):
        return np.zeros((0, 4)), face_plane, 0
    planes, group, _, found = _flat_planes(points, triangles, faces, MAX_MIRROR_PLANES)
    face_plane[faces] = group
    return planes, face_plane, max(0, found - len(planes))


#: most glint pairs (a flat glossy plane × a distant light) the glint strategy draws among
MAX_GLINTS = 4


def glint_planes(points: np.ndarray, triangles: np.ndarray, surface_id: np.ndarray | None,
                 surfaces: list, shaded: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The flat planes of glossy, non-mirror faces, for the glint strategy (:mod:`simulator.kernels.
    glints`): ``(planes (K, 4) as (n, d), GGX α per plane)``, the :data:`MAX_GLINTS` largest first; faces
    ``shaded`` by normals of their own (a curved surface's facets) are not flat planes.

    A plane's α is roughness² of the material covering most of its area.
    """
    if surface_id is None:
        return np.zeros((0, 4)), np.zeros(0)
    rows = [k for k, s in enumerate(surfaces) if s.glossy and not s.delta_base and not s.pane]
    if not rows:
        return np.zeros((0, 4)), np.zeros(0)
    mine = np.isin(surface_id, rows)
    if shaded is not None:
        mine = mine & ~shaded
    faces = np.flatnonzero(mine)
    if not len(faces):
        return np.zeros((0, 4)), np.zeros(0)
    planes, group, _, _ = _flat_planes(points, triangles, faces, MAX_GLINTS)
    p = points[triangles[faces]]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    alpha = np.zeros(len(planes))
    for k in range(len(planes)):
        mine = group == k
        sid = surface_id[faces[mine]]
        by_row = np.bincount(sid, weights=area[mine])
        alpha[k] = float(surfaces[int(np.argmax(by_row))].roughness) ** 2
    return planes, alpha


def glint_pairs(geometry, lights: list) -> list[tuple[np.ndarray, float, int]]:
    """The glint strategy's pairs (:mod:`simulator.kernels.glints`): ``(plane (n, d), α, light index)``
    for the :func:`glint_planes` × the distant lights, at most :data:`MAX_GLINTS`, largest plane first."""
    from simulator.scene.model import LightKind

    g = geometry
    if not g.has_surfaces:
        return []
    planes, alpha = glint_planes(g.points, g.triangles, g.surface_id, g.surfaces, shaded_faces(g))
    suns = [k for k, l in enumerate(lights) if l.kind == LightKind.DISTANT]
    return [(planes[k], float(alpha[k]), li) for k in range(len(planes)) for li in suns][:MAX_GLINTS]


def mirror_limits(points: np.ndarray, triangles: np.ndarray, surface_id: np.ndarray | None,
                  surfaces: list, delta_lights: list[str], shaded: np.ndarray | None = None,
                  curves: int = 0) -> list[str]:
    """What the image-source connection of delta lights (:mod:`simulator.kernels.mirrors`) leaves out,
    one note each: empty without delta lights or without mirror faces.

    A point light or an angle-0 distant light reaches a receiver off a mirror
    along one direction only; the kernels connect its image in each of the
    :data:`MAX_MIRROR_PLANES` largest mirror planes, one reflection deep.
    Light reflected by two mirrors in turn (a delta meets a delta: no
    sampled direction finds it) and mirror planes past the largest are not
    connected, so their share of a reading is missing: the summary says so.
    Area, sphere and dome lights are found through any number of mirrors
    by the paths' own reflections. ``curves`` curved mirrors
    (:func:`curved_mirrors`) count as mirrors beside the planes.
    """
    if not delta_lights:
        return []
    planes, _, left_out = mirror_planes(points, triangles, surface_id, surfaces, shaded)
    notes = []
    lights = ", ".join(delta_lights[:3]) + (" ..." if len(delta_lights) > 3 else "")
    mirrors = len(planes) + left_out + curves
    if mirrors >= 2:
        notes.append(f"light of point or angle-0 distant light(s) {lights} reflected by two mirrors in turn "
                     f"is not read ({mirrors} mirror planes or curved mirrors; one reflection is read)")
    if left_out:
        notes.append(f"light of {lights} off the {left_out} mirror plane(s) past the {MAX_MIRROR_PLANES} "
                     "largest is not read")
    return notes


def shaded_faces(geometry) -> np.ndarray | None:
    """Per triangle: whether the kernels shade it by normals of its own (``Geometry.shading_normals``): a
    glossy or mirror face (not a pane: panes keep their face normal) whose corners carry a normal; None
    where no face is (the kernels then read no shading normal)."""
    g = geometry
    if g.shading_normals is None or g.surface_id is None or not g.surfaces:
        return None
    glossy = np.array([bool(s.glossy) and not s.pane for s in g.surfaces] + [False], bool)[g.surface_id]
    has = np.any(g.shading_normals != 0, axis=(1, 2))
    out = glossy & has
    return out if out.any() else None


#: most curved mirrors (pieces of shaded mirror faces) the kernels solve for a delta light's reflection
MAX_CURVES = 16


@dataclass(frozen=True)
class CurvedMirrors:
    """The curved mirrors of a stage (:func:`curved_mirrors`).

    Attributes
    ----------
    face_curve : ndarray, shape (T,), int32
        Per triangle: its curved mirror, -1 for none (or one past :data:`MAX_CURVES`).
    spheres : ndarray, shape (K, 4)
        Per curved mirror: the centre and radius of its vertices' bounding sphere (the kernels' seed).
    left_out : int
        Pieces past the :data:`MAX_CURVES` largest.
    not_convex : list of str
        The prims of pieces that are not closed and convex (a point light may show at several points of
        them; the kernels read one).
    """

    face_curve: np.ndarray
    spheres: np.ndarray
    left_out: int = 0
    not_convex: list = field(default_factory=list)

    @property
    def n(self) -> int:
        return len(self.spheres)


def _locally_convex(points: np.ndarray, tris: np.ndarray, welded: np.ndarray, normals: np.ndarray) -> bool:
    """Whether every edge two triangles share bends away from their shading normals' side: the vertex of
    each across the edge lies on the inner side of the other's plane (within 1e-9 of an edge's length)."""
    edges = np.concatenate([welded[:, [0, 1]], welded[:, [1, 2]], welded[:, [2, 0]]])
    opposite = np.concatenate([tris[:, 2], tris[:, 0], tris[:, 1]])
    owner = np.tile(np.arange(len(tris)), 3)
    key = np.sort(edges, axis=1).astype(np.int64)
    key = key[:, 0] * (int(key.max()) + 1) + key[:, 1]
    order = np.argsort(key, kind="stable")
    shared = np.flatnonzero(key[order][1:] == key[order][:-1])
    i, j = order[shared], order[shared + 1]  # two entries of one edge
    p = points[tris]
    fn = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    fn = fn * np.where(np.einsum("ij,ij->i", fn, normals.sum(axis=1)) < 0, -1.0, 1.0)[:, None]  # the normals' side
    fn = fn / np.maximum(np.linalg.norm(fn, axis=1), 1e-300)[:, None]
    tol = 1e-9 * np.linalg.norm(p[:, 1] - p[:, 0], axis=1)
    for a, b in ((i, j), (j, i)):
        t = owner[a]
        if np.any(np.einsum("ij,ij->i", fn[t], points[opposite[b]] - p[t, 0]) > tol[t]):
            return False
    return True


#: the last :func:`curved_mirrors` answer and the arrays it was found from (the reader's summary and the
#: device upload ask for the same stage in turn; a million-triangle ball takes seconds)
_LAST_CURVES: list = []


def curved_mirrors(geometry, shaded: np.ndarray | None) -> CurvedMirrors:
    """The curved mirrors of a stage: its ``shaded`` faces (:func:`shaded_faces`) whose surface has a mirror
    part (:attr:`Surface.delta`), welded by position into connected pieces, the :data:`MAX_CURVES` largest
    (by area) kept, each with its vertices' bounding sphere (centre of their box, mean distance from it)."""
    g = geometry
    if _LAST_CURVES:
        arrays, last_shaded, found = _LAST_CURVES
        if (all(a is b for a, b in zip(arrays, (g.points, g.triangles, g.surface_id, g.shading_normals)))
                and (shaded is None) == (last_shaded is None)
                and (shaded is None or np.array_equal(shaded, last_shaded))):
            return found
    found = _curved_mirrors(g, shaded)
    _LAST_CURVES[:] = [(g.points, g.triangles, g.surface_id, g.shading_normals), shaded, found]
    return found


def _curved_mirrors(g, shaded: np.ndarray | None) -> CurvedMirrors:
    """:func:`curved_mirrors`, found afresh."""
    from simulator.scene.enclosures import _closed_components, _components, _welded

    face_curve = np.full(g.n_triangles, -1, np.int32)
    if shaded is None:
        return CurvedMirrors(face_curve, np.zeros((0, 4)))
    delta = np.array([bool(s.delta) for s in g.surfaces] + [False], bool)[g.surface_id]
    faces = np.flatnonzero(shaded & delta)
    if not len(faces):
        return CurvedMirrors(face_curve, np.zeros((0, 4)))
    tris = g.triangles[faces].astype(np.int64)
    welded = _welded(g.points, tris)
    label = _components(welded)
    closed = set(_closed_components(welded, label))
    p = g.points[tris]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    labels = np.unique(label)
    size = np.array([area[label == c].sum() for c in labels])
    order = labels[np.argsort(-size, kind="stable")]
    spheres, not_convex = [], []
    for k, c in enumerate(order[:MAX_CURVES]):
        mine = label == c
        face_curve[faces[mine]] = k
        v = g.points[np.unique(tris[mine])]
        centre = 0.5 * (v.min(axis=0) + v.max(axis=0))
        spheres.append([*centre, float(np.mean(np.linalg.norm(v - centre, axis=1)))])
        if int(c) not in closed or not _locally_convex(g.points, tris[mine], welded[mine],
                                                       g.shading_normals[faces[mine]].astype(np.float64)):
            names = sorted({g.prim_names[i] for i in np.unique(g.prim[faces[mine]])})
            not_convex.extend(n for n in names if n not in not_convex)
    return CurvedMirrors(face_curve, np.array(spheres, float).reshape(-1, 4), max(0, len(order) - MAX_CURVES),
                         not_convex)


def curved_notes(curves: CurvedMirrors, delta_lights: list[str]) -> list[str]:
    """What the curved mirrors' connection of delta lights leaves out (:mod:`simulator.kernels.curved`), one
    note each; empty without delta lights."""
    if not delta_lights or curves.n + curves.left_out == 0:
        return []
    lights = ", ".join(delta_lights[:3]) + (" ..." if len(delta_lights) > 3 else "")
    notes = []
    if curves.not_convex:
        shown = ", ".join(curves.not_convex[:3]) + (" ..." if len(curves.not_convex) > 3 else "")
        notes.append(f"curved mirror(s) {shown} are not closed and convex: light of {lights} is read at one "
                     "reflection point in each (Newton's solution); a concave side may show it at more")
    if curves.left_out:
        notes.append(f"light of {lights} off the {curves.left_out} curved mirror(s) past the {MAX_CURVES} "
                     "largest is not read")
    return notes
