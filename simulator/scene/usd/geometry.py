"""Geometry: Mesh and the implicit gprims as one world-space triangle soup.

Each supported gprim is validated, tessellated (:mod:`.tessellation`),
wound so that ``cross(p1 - p0, p2 - p0)`` is its front face in world space
(``leftHanded`` and a mirroring transform each flip it; both cancel), given
its surface (:mod:`.materials`, or :mod:`.lights` for a geometry light) and
added to a :class:`_GeometryBuilder`, which concatenates everything once.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from pxr import Usd, UsdGeom, UsdShade

from simulator.scene.model import Geometry
from simulator.scene.usd.context import _Context, _get
from simulator.scene.usd.lights import _geometry_light_emission, _geometry_light_surface, _is_geometry_light
from simulator.scene.usd.materials import _surface
from simulator.scene.usd.normals import implicit_corner_normals, mesh_corner_normals, smooth_vertex_normals
from simulator.scene.usd.skinning import posed_points
from simulator.scene.usd.tessellation import (
    _capsule_polygons,
    _cone_polygons,
    _cube_polygons,
    _cylinder_polygons,
    _nonzero_area,
    _plane_polygons,
    _sphere_polygons,
    _triangulate_faces,
)
from simulator.scene.usd.transforms import _world_affine

#: UsdGeom.Sphere tessellation: (longitude segments, latitude rings)
SPHERE_SEGMENTS = (64, 32)
#: per-Sphere override of :data:`SPHERE_SEGMENTS`: ``int2 probesim:tessellation = (n_lon, n_lat)``
TESSELLATION_ATTR = "probesim:tessellation"
#: most faces (n_lon * n_lat) a tessellated Sphere may have
MAX_SPHERE_FACES = 1 << 22


class _GeometryBuilder:
    """Accumulates per-prim triangle lists, then concatenates them once."""

    def __init__(self) -> None:
        self._points: list[np.ndarray] = []
        self._tris: list[np.ndarray] = []
        self._albedo: list[np.ndarray] = []
        self._albedo_rgb: list[np.ndarray] = []
        self._reflectance_id: list[np.ndarray] = []
        self._emission_rgb: list[np.ndarray] = []
        self._emission: list[np.ndarray] = []
        self._two_sided: list[np.ndarray] = []
        self._surface_id: list[np.ndarray] = []
        self._prim: list[np.ndarray] = []
        self._names: list[str] = []
        self._texture: list = []
        self._normals: list = []
        self._n_points = 0

    def add(self, name: str, points: np.ndarray, tris: np.ndarray, albedo,
            emission, two_sided: bool, albedo_rgb=None, reflectance_id=None, emission_rgb=None,
            surface_id=None, texture=None, normals=None) -> None:
        """Add one prim's world triangles; ``albedo`` (T,) or scalar, ``emission`` (T, 2) or (2,),
        ``albedo_rgb`` (T, 3) or (3,), default grey ``(a, a, a)``; ``reflectance_id`` (T,) or scalar,
        default -1 (no measured reflectance); ``emission_rgb`` (T, 3) or (3,), default (1, 1, 1)
        (the emission's colour is the shared spectrum's); ``surface_id`` (T,) or scalar, default -1
        (matte); ``texture`` ``(texture id (T,), st (T, 3, 2))`` of faces whose opacity is read per texel;
        ``normals`` (T, 3, 3) the unit shading normal at each triangle corner, None for flat faces.
        """
        t = len(tris)
        if t == 0:
            return
        index = len(self._names)
        self._names.append(name)
        self._points.append(points)
        self._tris.append(tris.astype(np.int64) + self._n_points)
        self._n_points += len(points)
        self._albedo.append(np.broadcast_to(np.asarray(albedo, float), (t,)))
        rgb = np.asarray(albedo, float)[..., None] if albedo_rgb is None else np.asarray(albedo_rgb, float)
        self._albedo_rgb.append(np.broadcast_to(rgb, (t, 3)))
        rid = -1 if reflectance_id is None else reflectance_id
        self._reflectance_id.append(np.broadcast_to(np.asarray(rid, np.int32), (t,)))
        self._emission.append(np.broadcast_to(np.asarray(emission, float), (t, 2)))
        self._emission_rgb.append(np.broadcast_to(np.asarray(1.0 if emission_rgb is None else emission_rgb, float),
                                                  (t, 3)))
        self._two_sided.append(np.full(t, bool(two_sided)))
        self._surface_id.append(np.broadcast_to(np.asarray(-1 if surface_id is None else surface_id, np.int32), (t,)))
        self._prim.append(np.full(t, index, np.int32))
        self._texture.append(texture)
        self._normals.append(normals)

    def build(self, reflectances=(), emissive_spectra=(), surfaces=(), coverage_textures=()) -> Geometry:
        """The soup; ``reflectances`` the measured curves ``(name, ρ, grey)`` the ids index,
        ``emissive_spectra`` the ``(spectrum or None, authored)`` of the emitting prims, ``surfaces``
        the :class:`~simulator.scene.surfaces.Surface` rows the surface ids index, ``coverage_textures``
        the opacity textures the texture ids index."""
        if not self._tris:
            return Geometry()
        from simulator.scene.surfaces import solid_sides

        sid = np.concatenate(self._surface_id).astype(np.int32)
        points = np.concatenate(self._points).astype(np.float64)
        triangles = np.concatenate(self._tris).astype(np.int32)
        prim = np.concatenate(self._prim)
        # (a thin-walled pane is a sheet on every face: not a solid, whatever the mesh)
        pane = np.array([s.pane and not s.thin_walled for s in surfaces] + [False], bool)[sid]
        side = solid_sides(points, triangles, prim, pane) if pane.any() else None
        ids = np.concatenate(self._reflectance_id).astype(np.int32)
        emission_rgb = np.concatenate(self._emission_rgb)
        spectra = list(dict.fromkeys(emissive_spectra))
        one = spectra[0] if len(spectra) == 1 else (None, False)
        return Geometry(
            reflectance_id=ids if (ids >= 0).any() else None,
            reflectances=[(name, np.asarray(rho, float)) for name, rho, _ in reflectances],
            emissive_spectrum=one[0],
            emissive_spectrum_authored=bool(one[1]),
            points=points,
            triangles=triangles,
            albedo=np.concatenate(self._albedo),
            emission=np.concatenate(self._emission),
            two_sided=np.concatenate(self._two_sided),
            prim=prim,
            prim_names=list(self._names),
            albedo_rgb=np.concatenate(self._albedo_rgb),
            emission_rgb=emission_rgb if np.any(emission_rgb != 1.0) else None,
            surface_id=sid if (sid >= 0).any() else None,
            surfaces=list(surfaces),
            solid_side=side,
            shading_normals=self._shading_normals(sid, surfaces),
            **self._textures(coverage_textures),
        )

    def _shading_normals(self, sid: np.ndarray, surfaces) -> np.ndarray | None:
        """``Geometry.shading_normals``: (T, 3, 3) float32, kept on faces whose surface row is glossy or a
        pane (what the kernels shade by them, and what the summary names) and zero elsewhere; None when no
        such face has them (a stage exported with normals on matte faces keeps no array)."""
        if all(n is None for n in self._normals):
            return None
        out = np.concatenate([np.zeros((len(a), 3, 3), np.float32) if n is None else n.astype(np.float32)
                              for n, a in zip(self._normals, self._albedo)])
        keep = np.array([bool(s.glossy or s.pane) for s in surfaces] + [False], bool)[sid]
        out[~keep] = 0.0
        return out if np.any(out != 0) else None

    def _textures(self, coverage_textures) -> dict:
        """``Geometry`` fields of the faces whose opacity is read per texel (none: nothing)."""
        if all(t is None for t in self._texture):
            return {}
        ids = [np.full(len(a), -1, np.int32) if t is None else t[0] for t, a in zip(self._texture, self._albedo)]
        uv = [np.zeros((len(a), 3, 2)) if t is None else t[1] for t, a in zip(self._texture, self._albedo)]
        return dict(coverage_textures=list(coverage_textures), texture_id=np.concatenate(ids).astype(np.int32),
                    texture_uv=np.concatenate(uv))


@dataclass
class _Part:
    """One gprim tessellated in its own frame, with the surface of every triangle.

    ``points`` (P, 3) and ``tris`` (T, 3) are local (stage units, the prim's
    own frame); ``tris`` already carries the ``leftHanded`` re-winding.
    ``albedo`` (T,), ``albedo_rgb`` (T, 3), ``emission`` (T, 2) and
    ``emission_rgb`` (T, 3) are per triangle (GeomSubsets may bind
    different materials to different faces).
    """

    name: str
    points: np.ndarray
    tris: np.ndarray
    albedo: np.ndarray
    emission: np.ndarray
    two_sided: bool
    is_light: bool
    albedo_rgb: np.ndarray | None = None
    reflectance_id: np.ndarray | None = None
    emission_rgb: np.ndarray | None = None
    surface_id: np.ndarray | None = None
    texture_id: np.ndarray | None = None
    texture_uv: np.ndarray | None = None
    normals: np.ndarray | None = None  # (T, 3, 3) shading normal at each triangle corner, local; None: flat faces


def _read_gprim(ctx: _Context, prim: Usd.Prim, geo: _GeometryBuilder) -> None:
    """Tessellate one gprim, resolve its material, and add it to the soup at its place in the world."""
    part = _gprim_part(ctx, prim)
    if part is None:
        return
    posed = posed_points(ctx, prim, part.points)  # a skinned prim: where its skeleton puts it at ctx.time
    if posed is None:
        a, t = _world_affine(ctx, prim)
    else:
        if part.normals is not None and not np.array_equal(posed[0], part.points):
            # skinned point by point: its authored normals stay in the bind pose, so the posed mesh is shaded
            # by its own area-weighted vertex normals
            part.normals = smooth_vertex_normals(posed[0], np.full(len(part.tris), 3), part.tris.ravel())[part.tris]
        part.points, a, t = posed
    _add_placed(ctx, prim, part, a[None], t[None], geo, part.name)


def _gprim_part(ctx: _Context, prim: Usd.Prim) -> _Part | None:
    """A gprim as a :class:`_Part` in its local frame, None when it adds nothing (unsupported, empty, opacity 0)."""
    local = _gprim_polygons(ctx, prim)
    if local is None:
        return None
    points, counts, indices = local
    is_light = _is_geometry_light(ctx, prim)
    n_faces = len(counts)
    if is_light:
        surface = _geometry_light_surface(ctx, prim)
        faces = (np.full(n_faces, surface[0]), np.zeros((n_faces, 2)), np.ones(n_faces, bool),
                 np.tile(surface[2], (n_faces, 1)), np.full(n_faces, surface[3], np.int32), np.ones((n_faces, 3)),
                 np.full(n_faces, -1, np.int32))
    else:
        faces = _face_surfaces(ctx, prim, n_faces)
    if faces is None:  # opacity 0 everywhere: it lets light through
        return None
    albedo, emission, keep, albedo_rgb, curve, emission_rgb, surface_id = faces
    tris, fanned, face_of = _triangulate_faces(points, counts, indices, convex=not prim.IsA(UsdGeom.Mesh))
    if fanned:
        ctx.warn(f"{prim.GetPath()}: {fanned} self-intersecting or non-planar face(s) fan-triangulated")
    if not keep.all():
        tris, face_of = tris[keep[face_of]], face_of[keep[face_of]]
    texture = _texture_corners(ctx, prim, points, counts, indices, keep, surface_id[face_of], face_of)
    normals = _triangle_normals(ctx, prim, points, counts, indices, keep)
    gprim = UsdGeom.Gprim(prim)
    if gprim.GetOrientationAttr().Get(ctx.time) == UsdGeom.Tokens.leftHanded:
        tris = tris[:, [0, 2, 1]]
        if texture is not None:
            texture = (texture[0], texture[1][:, [0, 2, 1]])
        if normals is not None:
            normals = normals[:, [0, 2, 1]]
    return _Part(name=str(prim.GetPath()), points=points, tris=tris, albedo=albedo[face_of],
                 emission=emission[face_of], two_sided=bool(gprim.GetDoubleSidedAttr().Get(ctx.time)),
                 is_light=is_light, albedo_rgb=albedo_rgb[face_of], reflectance_id=curve[face_of],
                 emission_rgb=emission_rgb[face_of], surface_id=surface_id[face_of],
                 texture_id=None if texture is None else texture[0], texture_uv=None if texture is None else texture[1],
                 normals=normals)


def _corner_triangles(points, counts, indices, keep, convex: bool) -> np.ndarray:
    """The triangulation of :func:`_gprim_part` over face corners (T, 3): each triangle's corners as
    indices into ``faceVertexIndices`` order (points[indices] triangulates as the points do)."""
    corner_tris, _, corner_face = _triangulate_faces(points[indices], counts, np.arange(len(indices)), convex=convex)
    return corner_tris[keep[corner_face]]


def _triangle_normals(ctx: _Context, prim: Usd.Prim, points, counts, indices, keep) -> np.ndarray | None:
    """The shading normal at each kept triangle's corners (T, 3, 3), in the prim's frame
    (:mod:`.normals`), or None where its faces are flat."""
    corner = _gprim_normals(ctx, prim, points, counts, indices)
    if corner is None:
        return None
    return corner[_corner_triangles(points, counts, indices, keep, convex=not prim.IsA(UsdGeom.Mesh))]


def _gprim_normals(ctx: _Context, prim: Usd.Prim, points, counts, indices) -> np.ndarray | None:
    """A gprim's normal at each polygon corner (C, 3), or None for flat faces (:mod:`.normals`)."""
    if prim.IsA(UsdGeom.Mesh):
        return mesh_corner_normals(ctx, prim, points, counts, indices)
    if prim.IsA(UsdGeom.Sphere):
        return implicit_corner_normals("Sphere", points, counts, indices)
    size = lambda attr: float(_get(ctx, attr))  # noqa: E731  (validated when the shape was tessellated)
    for schema, kind in ((UsdGeom.Cylinder_1, "Cylinder"), (UsdGeom.Cylinder, "Cylinder"), (UsdGeom.Cone, "Cone"),
                         (UsdGeom.Capsule_1, "Capsule"), (UsdGeom.Capsule, "Capsule")):
        if not prim.IsA(schema):
            continue
        shape = schema(prim)
        axis = str(shape.GetAxisAttr().Get(ctx.time))
        if schema is UsdGeom.Cylinder_1:
            dims = (size(shape.GetRadiusTopAttr()), size(shape.GetRadiusBottomAttr()), size(shape.GetHeightAttr()))
        elif schema is UsdGeom.Cylinder:
            r = size(shape.GetRadiusAttr())
            dims = (r, r, size(shape.GetHeightAttr()))
        elif schema is UsdGeom.Capsule_1:
            dims = (size(shape.GetRadiusTopAttr()), size(shape.GetHeightAttr()))
        else:
            dims = (size(shape.GetRadiusAttr()), size(shape.GetHeightAttr()))
        return implicit_corner_normals(kind, points, counts, indices, axis, dims)
    return None  # Cube, Plane: flat faces


def _texture_corners(ctx: _Context, prim: Usd.Prim, points, counts, indices, keep, tri_surface, face_of):
    """``(texture id (T,), st (T, 3, 2))`` of a gprim's kept triangles whose surface reads its opacity per
    texel (:mod:`.texcoords`), None when none does. A face whose prim lacks the texture's primvar gets
    -1 (its surface's coverage, from the texture's mean), counted in the summary warning."""
    tex_of = np.array([s.opacity_texture for s in ctx.surfaces] + [-1], np.int64)[tri_surface]
    if not (tex_of >= 0).any():
        return None
    from simulator.scene.usd.texcoords import _corner_st

    # the same triangulation over face corners (points[indices] in corner order), so each corner is known
    corner_tris, _, corner_face = _triangulate_faces(points[indices], counts, np.arange(len(indices)))
    corner_tris = corner_tris[keep[corner_face]]
    uv = np.zeros((len(face_of), 3, 2))
    out = np.full(len(face_of), -1, np.int32)
    for k in np.unique(tex_of[tex_of >= 0]):
        tex = ctx.coverage_textures[int(k)]
        mine = tex_of == k
        st = _corner_st(ctx, prim, tex.primvar, face_of[mine], corner_tris[mine], indices)
        if st is None:
            ctx.ignored[f"inputs:opacity texture on a prim without primvars:{tex.primvar} (its mean used)"] += 1
            continue
        uv[mine] = st @ tex.st_affine[:, :2].T + tex.st_affine[:, 2]
        out[mine] = k
    return (out, uv) if (out >= 0).any() else None


def _face_surfaces(ctx: _Context, prim: Usd.Prim, n_faces: int):
    """Per-face ``(albedo (F,), emission (F, 2), kept (F,), albedo colour (F, 3), reflectance id (F,),
    emission colour (F, 3), surface id (F,))`` of a gprim; None when nothing is kept.

    The prim's own bound material (or displayColor) covers every face; each
    ``GeomSubset`` of the ``materialBind`` family with a material bound to
    it (``UsdShadeMaterialBindingAPI.GetMaterialBindSubsets``) then covers
    its faces. A face with opacity 0 is dropped (it blocks nothing).
    """
    base = _surface(ctx, prim)
    subsets = [] if not prim.IsA(UsdGeom.Mesh) else UsdShade.MaterialBindingAPI(prim).GetMaterialBindSubsets()
    if not subsets:
        if base is None:
            return None
        return (np.full(n_faces, base[0]), np.tile(np.asarray(base[1], float), (n_faces, 1)), np.ones(n_faces, bool),
                np.tile(base[2], (n_faces, 1)), np.full(n_faces, base[3], np.int32), np.tile(base[4], (n_faces, 1)),
                np.full(n_faces, base[5], np.int32))
    albedo = np.full(n_faces, base[0] if base else 0.0)
    albedo_rgb = np.tile(base[2] if base else np.zeros(3), (n_faces, 1))
    curve = np.full(n_faces, base[3] if base else -1, np.int32)
    emission_rgb = np.tile(base[4] if base else np.ones(3), (n_faces, 1))
    surface_id = np.full(n_faces, base[5] if base else -1, np.int32)
    emission = np.tile(np.asarray(base[1] if base else (0.0, 0.0), float), (n_faces, 1))
    keep = np.full(n_faces, base is not None)
    for subset in subsets:
        sub = subset.GetPrim()
        element = str(subset.GetElementTypeAttr().Get(ctx.time))
        if element != "face":
            ctx.ignored[f"materialBind GeomSubset of elementType {element}"] += 1
            continue
        faces = np.asarray(subset.GetIndicesAttr().Get(ctx.time) or [], np.int64)
        if len(faces) and (faces.min() < 0 or faces.max() >= n_faces):
            raise ctx.error(sub, f"indices out of range for a mesh of {n_faces} faces")
        surface = _surface(ctx, prim, bind_prim=sub)
        if surface is None:
            keep[faces] = False
            continue
        albedo[faces], emission[faces], keep[faces], albedo_rgb[faces] = surface[0], surface[1], True, surface[2]
        curve[faces], emission_rgb[faces], surface_id[faces] = surface[3], surface[4], surface[5]
    return (albedo, emission, keep, albedo_rgb, curve, emission_rgb, surface_id) if keep.any() else None


def _add_placed(ctx: _Context, prim: Usd.Prim, part: _Part, a: np.ndarray, t: np.ndarray,
                geo: _GeometryBuilder, name: str) -> None:
    """Add ``part`` at N places: world points ``a[k] @ p + t[k]``, a (N, 3, 3) and t (N, 3), metres.

    A place whose linear map mirrors (negative determinant) re-winds its
    triangles, so the front face stays the front face; zero-area triangles
    (a collapsed axis, fan slivers) are dropped.
    """
    n = len(a)
    if n == 0 or len(part.tris) == 0:
        return
    if n == 1:
        world = (part.points @ a[0].T + t[0])[None]
    else:
        world = np.matmul(part.points[None], a.transpose(0, 2, 1)) + t[:, None, :]  # (N, P, 3)
    mirrored = np.linalg.det(a) < 0
    tris = np.broadcast_to(part.tris, (n,) + part.tris.shape).copy()
    tris[mirrored] = tris[mirrored][:, :, [0, 2, 1]]
    tris += (np.arange(n) * len(part.points))[:, None, None]
    world = world.reshape(-1, 3)
    tris = tris.reshape(-1, 3)
    keep = _nonzero_area(world, tris)
    per_tri = np.tile(np.arange(len(part.tris)), n)[keep]
    tris = tris[keep]
    emission = part.emission[per_tri]
    if part.is_light:  # each place's own world area (normalize divides by it)
        place = np.repeat(np.arange(n), len(part.tris))[keep]
        emission = np.zeros((len(tris), 2))
        for k in range(n):
            mine = place == k
            emission[mine] = _geometry_light_emission(ctx, prim, world, tris[mine])
    rgb = None if part.albedo_rgb is None else part.albedo_rgb[per_tri]
    rid = None if part.reflectance_id is None else part.reflectance_id[per_tri]
    e_rgb = None if part.emission_rgb is None or part.is_light else part.emission_rgb[per_tri]
    sid = None if part.surface_id is None else part.surface_id[per_tri]
    texture = None if part.texture_id is None else (part.texture_id[per_tri], part.texture_uv[per_tri])
    flip = mirrored[np.repeat(np.arange(n), len(part.tris))[keep]]
    if texture is not None:  # the corners follow a mirrored place's re-winding
        texture[1][flip] = texture[1][flip][:, [0, 2, 1]]
    normals = None
    if part.normals is not None:  # normals map by the inverse transpose: n' = n @ inv(a) for row vectors
        place = np.repeat(np.arange(n), len(part.tris))[keep]
        inv = np.linalg.inv(a)
        normals = np.einsum("tcj,tjk->tck", part.normals[per_tri], inv[place])
        length = np.linalg.norm(normals, axis=2, keepdims=True)
        normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
        normals[flip] = normals[flip][:, [0, 2, 1]]
    geo.add(name, world, tris, part.albedo[per_tri], emission, part.two_sided, rgb, rid, e_rgb, sid, texture,
            normals)


def _gprim_polygons(ctx: _Context, prim: Usd.Prim):
    """Local ``(points, faceVertexCounts, faceVertexIndices)`` of a supported gprim, else None.

    Unsupported gprims (curves, points, NURBS, volumes) are counted for the
    summary warning.
    """
    if prim.IsA(UsdGeom.Mesh):
        return _mesh_polygons(ctx, prim)
    if prim.IsA(UsdGeom.Cube):
        size = _gprim_size(ctx, prim, UsdGeom.Cube(prim).GetSizeAttr(), "Cube size")
        return _cube_polygons(size) if size > 0 else None
    if prim.IsA(UsdGeom.Sphere):
        radius = _gprim_size(ctx, prim, UsdGeom.Sphere(prim).GetRadiusAttr(), "Sphere radius")
        return _sphere_polygons(radius, *_sphere_segments(ctx, prim)) if radius > 0 else None
    for schema, build in _QUADRICS:
        if prim.IsA(schema):
            return build(ctx, prim, schema(prim))
    ctx.not_read[prim.GetTypeName() or "untyped gprim"] += 1
    return None


def _axis(ctx: _Context, prim: Usd.Prim, shape) -> str:
    axis = str(shape.GetAxisAttr().Get(ctx.time))
    if axis not in ("X", "Y", "Z"):
        raise ctx.error(prim, f"axis must be 'X', 'Y' or 'Z', not {axis!r}")
    return axis


def _cylinder(ctx: _Context, prim: Usd.Prim, shape):
    """UsdGeom.Cylinder / Cylinder_1 (radiusTop, radiusBottom): a capped cylinder or frustum."""
    h = _gprim_size(ctx, prim, shape.GetHeightAttr(), "Cylinder height")
    if isinstance(shape, UsdGeom.Cylinder_1):
        r_top = _gprim_size(ctx, prim, shape.GetRadiusTopAttr(), "Cylinder radiusTop")
        r_bottom = _gprim_size(ctx, prim, shape.GetRadiusBottomAttr(), "Cylinder radiusBottom")
    else:
        r_top = r_bottom = _gprim_size(ctx, prim, shape.GetRadiusAttr(), "Cylinder radius")
    if max(r_top, r_bottom) == 0:
        return None
    return _cylinder_polygons(r_top, r_bottom, h, _sphere_segments(ctx, prim)[0], _axis(ctx, prim, shape))


def _cone(ctx: _Context, prim: Usd.Prim, shape):
    """UsdGeom.Cone: apex up the axis, capped base."""
    h = _gprim_size(ctx, prim, shape.GetHeightAttr(), "Cone height")
    r = _gprim_size(ctx, prim, shape.GetRadiusAttr(), "Cone radius")
    return _cone_polygons(r, h, _sphere_segments(ctx, prim)[0], _axis(ctx, prim, shape)) if r > 0 else None


def _capsule(ctx: _Context, prim: Usd.Prim, shape):
    """UsdGeom.Capsule (and Capsule_1 when its two radii are equal): cylinder plus hemispheres."""
    h = _gprim_size(ctx, prim, shape.GetHeightAttr(), "Capsule height")
    if isinstance(shape, UsdGeom.Capsule_1):
        r = _gprim_size(ctx, prim, shape.GetRadiusTopAttr(), "Capsule radiusTop")
        if _gprim_size(ctx, prim, shape.GetRadiusBottomAttr(), "Capsule radiusBottom") != r:
            ctx.not_read["Capsule_1 with two radii"] += 1
            return None
    else:
        r = _gprim_size(ctx, prim, shape.GetRadiusAttr(), "Capsule radius")
    return _capsule_polygons(r, h, *_sphere_segments(ctx, prim), _axis(ctx, prim, shape)) if r > 0 else None


def _plane(ctx: _Context, prim: Usd.Prim, shape):
    """UsdGeom.Plane: one quad facing +axis (double-sided by the schema's fallback)."""
    w = _gprim_size(ctx, prim, shape.GetWidthAttr(), "Plane width")
    length = _gprim_size(ctx, prim, shape.GetLengthAttr(), "Plane length")
    return _plane_polygons(w, length, _axis(ctx, prim, shape)) if w > 0 and length > 0 else None


# the implicit shapes beyond Cube and Sphere: schema and builder (Cylinder_1 before Cylinder: IsA is exact)
_QUADRICS = (
    (UsdGeom.Cylinder_1, _cylinder),
    (UsdGeom.Cylinder, _cylinder),
    (UsdGeom.Cone, _cone),
    (UsdGeom.Capsule_1, _capsule),
    (UsdGeom.Capsule, _capsule),
    (UsdGeom.Plane, _plane),
)


def _gprim_size(ctx: _Context, prim: Usd.Prim, attr: Usd.Attribute, what: str) -> float:
    """A shape's size (Cube size, a radius, height, width, ...) in stage units: a non-negative number."""
    value = float(_get(ctx, attr))
    if not math.isfinite(value) or value < 0:
        raise ctx.error(prim, f"{what} must be a non-negative number, not {value}")
    return value


def _sphere_segments(ctx: _Context, prim: Usd.Prim) -> tuple[int, int]:
    """``(longitude segments, latitude rings)`` of a round shape: ``probesim:tessellation`` if authored,
    else :data:`SPHERE_SEGMENTS` (Cylinder and Cone use the first number, Capsule both)."""
    attr = prim.GetAttribute(TESSELLATION_ATTR)
    value = attr.Get(ctx.time) if attr and attr.HasAuthoredValue() else None
    if value is None:
        return SPHERE_SEGMENTS
    try:
        n_lon, n_lat = (int(v) for v in value)
    except (TypeError, ValueError):
        raise ctx.error(prim, f"{TESSELLATION_ATTR} must be two integers (int2), not {value!r}") from None
    if n_lon < 3 or n_lat < 2 or n_lon * n_lat > MAX_SPHERE_FACES:
        raise ctx.error(prim, f"{TESSELLATION_ATTR} {(n_lon, n_lat)} must have longitude segments >= 3, "
                              f"latitude rings >= 2 and at most {MAX_SPHERE_FACES} faces in all")
    return n_lon, n_lat


def _mesh_polygons(ctx: _Context, prim: Usd.Prim):
    """A Mesh's points and face lists, validated (indices in range, counts sum up)."""
    mesh = UsdGeom.Mesh(prim)
    points = np.asarray(mesh.GetPointsAttr().Get(ctx.time) or [], dtype=float).reshape(-1, 3)
    counts = np.asarray(mesh.GetFaceVertexCountsAttr().Get(ctx.time) or [], dtype=np.int64)
    indices = np.asarray(mesh.GetFaceVertexIndicesAttr().Get(ctx.time) or [], dtype=np.int64)
    if not np.all(np.isfinite(points)):
        raise ctx.error(prim, "points contain NaN or Inf")
    if np.any(counts < 0):
        raise ctx.error(prim, "faceVertexCounts has a negative count")
    if int(counts.sum()) != len(indices):
        raise ctx.error(
            prim, f"faceVertexCounts sum to {int(counts.sum())} but there are {len(indices)} faceVertexIndices"
        )
    if len(indices) and (indices.min() < 0 or indices.max() >= len(points)):
        raise ctx.error(prim, f"faceVertexIndices out of range for {len(points)} points")
    if mesh.GetHoleIndicesAttr().Get(ctx.time):
        ctx.ignored["holeIndices (hole faces kept)"] += 1
    scheme = mesh.GetSubdivisionSchemeAttr()
    if scheme.HasAuthoredValue() and str(scheme.Get(ctx.time)) != UsdGeom.Tokens.none:
        ctx.subdivided[str(scheme.Get(ctx.time))] += 1
    if np.any(counts < 3):
        ctx.warn(f"{prim.GetPath()}: {int(np.sum(counts < 3))} face(s) with fewer than 3 vertices skipped")
    return points, counts, indices
