"""Geometry: Mesh, Cube and Sphere gprims as one world-space triangle soup.

Each supported gprim is validated, tessellated (:mod:`.tessellation`),
wound so that ``cross(p1 - p0, p2 - p0)`` is its front face in world space
(``leftHanded`` and a mirroring transform each flip it; both cancel), given
its surface (:mod:`.materials`, or :mod:`.lights` for a geometry light) and
added to a :class:`_GeometryBuilder`, which concatenates everything once.
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd, UsdGeom

from simulator.scene.model import Geometry
from simulator.scene.usd.context import _Context, _get
from simulator.scene.usd.lights import _geometry_light_emission, _geometry_light_surface, _is_geometry_light
from simulator.scene.usd.materials import _surface
from simulator.scene.usd.tessellation import _cube_polygons, _drop_zero_area, _sphere_polygons, _triangulate
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
        self._emission: list[np.ndarray] = []
        self._two_sided: list[np.ndarray] = []
        self._prim: list[np.ndarray] = []
        self._names: list[str] = []
        self._n_points = 0

    def add(self, name: str, points: np.ndarray, tris: np.ndarray, albedo: float,
            emission: tuple[float, float], two_sided: bool) -> None:
        t = len(tris)
        if t == 0:
            return
        index = len(self._names)
        self._names.append(name)
        self._points.append(points)
        self._tris.append(tris.astype(np.int64) + self._n_points)
        self._n_points += len(points)
        self._albedo.append(np.full(t, albedo))
        self._emission.append(np.tile(np.asarray(emission, float), (t, 1)))
        self._two_sided.append(np.full(t, bool(two_sided)))
        self._prim.append(np.full(t, index, np.int32))

    def build(self) -> Geometry:
        if not self._tris:
            return Geometry()
        return Geometry(
            points=np.concatenate(self._points).astype(np.float64),
            triangles=np.concatenate(self._tris).astype(np.int32),
            albedo=np.concatenate(self._albedo),
            emission=np.concatenate(self._emission),
            two_sided=np.concatenate(self._two_sided),
            prim=np.concatenate(self._prim),
            prim_names=list(self._names),
        )


def _read_gprim(ctx: _Context, prim: Usd.Prim, geo: _GeometryBuilder) -> None:
    """Tessellate one gprim, resolve its material, and add it to the soup."""
    local = _gprim_polygons(ctx, prim)
    if local is None:
        return
    points, counts, indices = local
    is_light = _is_geometry_light(ctx, prim)
    surface = _geometry_light_surface(ctx, prim) if is_light else _surface(ctx, prim)
    if surface is None:  # opacity 0: it lets light through
        return
    a, t = _world_affine(ctx, prim)
    tris, fanned = _triangulate(points, counts, indices)
    if fanned:
        ctx.warn(f"{prim.GetPath()}: {fanned} self-intersecting or non-planar face(s) fan-triangulated")
    gprim = UsdGeom.Gprim(prim)
    left = gprim.GetOrientationAttr().Get(ctx.time) == UsdGeom.Tokens.leftHanded
    mirrored = np.linalg.det(a) < 0
    if left != mirrored:  # either one flips which side is the front; both cancel
        tris = tris[:, [0, 2, 1]]
    world = points @ a.T + t
    tris = _drop_zero_area(world, tris)
    albedo, emission = surface
    if is_light:
        emission = _geometry_light_emission(ctx, prim, world, tris)
    geo.add(str(prim.GetPath()), world, tris, albedo, emission, bool(gprim.GetDoubleSidedAttr().Get(ctx.time)))


def _gprim_polygons(ctx: _Context, prim: Usd.Prim):
    """Local ``(points, faceVertexCounts, faceVertexIndices)`` of a supported gprim, else None."""
    if prim.IsA(UsdGeom.Mesh):
        return _mesh_polygons(ctx, prim)
    if prim.IsA(UsdGeom.Cube):
        size = _gprim_size(ctx, prim, UsdGeom.Cube(prim).GetSizeAttr(), "Cube size")
        return _cube_polygons(size) if size > 0 else None
    if prim.IsA(UsdGeom.Sphere):
        radius = _gprim_size(ctx, prim, UsdGeom.Sphere(prim).GetRadiusAttr(), "Sphere radius")
        return _sphere_polygons(radius, *_sphere_segments(ctx, prim)) if radius > 0 else None
    ctx.warn(f"{prim.GetPath()}: {prim.GetTypeName()} is not supported (only Mesh, Cube, Sphere); ignored")
    return None


def _gprim_size(ctx: _Context, prim: Usd.Prim, attr: Usd.Attribute, what: str) -> float:
    """A Cube's size or a Sphere's radius in stage units: a non-negative number (0: nothing to add)."""
    value = float(_get(ctx, attr))
    if not math.isfinite(value) or value < 0:
        raise ctx.error(prim, f"{what} must be a non-negative number, not {value}")
    return value


def _sphere_segments(ctx: _Context, prim: Usd.Prim) -> tuple[int, int]:
    """``(longitude segments, latitude rings)`` of a Sphere: ``probesim:tessellation`` if authored,
    else :data:`SPHERE_SEGMENTS`."""
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
        ctx.warn(f"{prim.GetPath()}: holeIndices ignored (hole faces are kept)")
    if np.any(counts < 3):
        ctx.warn(f"{prim.GetPath()}: {int(np.sum(counts < 3))} face(s) with fewer than 3 vertices skipped")
    return points, counts, indices
