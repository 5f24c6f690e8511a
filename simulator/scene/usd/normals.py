"""Shading normals: what a gprim says its surface's normal is, at each corner of each polygon.

A curved surface is traced as the flat triangles it is tessellated into;
its shading normal (interpolated over each triangle from its corners, in
the kernels) is the normal the surface's glossy and mirror lobes reflect
about (:mod:`simulator.kernels.glossy`). This module gives each polygon
corner its normal, in the prim's own frame, or None where the faces' own
normals are the surface's (a flat mesh, a Cube, a Plane):

- **a Mesh with ``subdivisionScheme = "none"``** (or no scheme authored,
  which the reader takes as polygons, as the bundled stages and most
  exporters mean it): its authored normals, ``primvars:normals`` before the
  ``normals`` attribute, indexed or not, at their interpolation: ``vertex``
  and ``varying`` per point, ``faceVarying`` per corner, ``uniform`` per
  face, ``constant`` one for all. Without authored normals its faces are
  flat (face normals);
- **a Mesh with an authored subdivision scheme** (``catmullClark``,
  ``loop``, ``bilinear``): UsdGeomMesh says authored normals apply only to
  ``none`` (a subdivision surface defines its own), so they are not read;
  the mesh is traced as its control cage shaded by the cage's area-weighted
  vertex normals (the smooth normals a viewer shows for an unrefined cage;
  creases and corners are not read). ``bilinear`` subdivides to the cage's
  own flat faces: face normals;
- **the implicit round gprims** (Sphere, Cylinder, Cone, Capsule): the
  shape's analytic normal at each tessellated vertex; a cap's corners take
  the cap's normal and a cone's apex the normal at its triangle's azimuth.

Corners whose normal equals their face's (within :data:`FLAT_COS`) say
nothing: a gprim all of whose corners do gets None, so flat meshes that
author their face normals read as they did.
"""

from __future__ import annotations

import numpy as np
from pxr import Usd, UsdGeom

from simulator.scene.usd.context import _Context
from simulator.scene.usd.tessellation import _AXIS_ROTATIONS, _newell_normal

#: a corner normal within this cosine of its face's normal is the face's (about 0.0026°)
FLAT_COS = 1.0 - 1.0e-9

#: subdivision schemes whose surface is smooth (``bilinear`` keeps the cage's flat faces)
SMOOTH_SCHEMES = ("catmullClark", "loop")


def _unit_rows(v: np.ndarray) -> np.ndarray:
    """Rows of ``v`` scaled to unit length (zero rows stay zero)."""
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)


def _face_areas(points: np.ndarray, counts: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Newell area vector of each polygon (F, 3), along its winding (zero for fewer than three corners)."""
    out = np.zeros((len(counts), 3))
    starts = np.cumsum(counts) - counts
    for n in np.unique(counts):
        n = int(n)
        if n < 3:
            continue
        faces = np.flatnonzero(counts == n)
        out[faces] = _newell_normal(points[indices[starts[faces][:, None] + np.arange(n)]])
    return out


def _face_normals(points: np.ndarray, counts: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Unit Newell normal of each polygon (F, 3), along its winding (zero for a degenerate face)."""
    return _unit_rows(_face_areas(points, counts, indices))


def _per_face_corners(values: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """A per-face array (F, 3) repeated at each face's corners (C, 3)."""
    return np.repeat(values, counts, axis=0)


def _is_flat(corner: np.ndarray, face_normal: np.ndarray, counts: np.ndarray) -> bool:
    """Whether every corner normal is its face's (within :data:`FLAT_COS`), up to sign."""
    dots = np.einsum("ij,ij->i", _unit_rows(corner), _per_face_corners(face_normal, counts))
    keep = np.linalg.norm(corner, axis=1) > 0
    return bool(np.all(np.abs(dots[keep]) >= FLAT_COS))


def smooth_vertex_normals(points: np.ndarray, counts: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Area-weighted vertex normals (P, 3): at each point the sum of its faces' Newell area vectors, unit."""
    acc = np.zeros((len(points), 3))
    np.add.at(acc, indices, _per_face_corners(_face_areas(points, counts, indices), counts))
    return _unit_rows(acc)


def _authored_normals(ctx: _Context, prim: Usd.Prim):
    """``(values (N, 3), interpolation)`` of a Mesh's authored normals, or None (primvars:normals wins)."""
    mesh = UsdGeom.Mesh(prim)
    pv = UsdGeom.PrimvarsAPI(prim).GetPrimvar("normals")
    if pv and pv.HasAuthoredValue():
        values, interp = pv.ComputeFlattened(ctx.time), pv.GetInterpolation()
    elif mesh.GetNormalsAttr().HasAuthoredValue():
        values, interp = mesh.GetNormalsAttr().Get(ctx.time), mesh.GetNormalsInterpolation()
    else:
        return None
    if values is None:
        return None
    return np.asarray(values, float).reshape(-1, 3), str(interp)


def mesh_corner_normals(ctx: _Context, prim: Usd.Prim, points: np.ndarray, counts: np.ndarray,
                        indices: np.ndarray) -> np.ndarray | None:
    """A Mesh's normal at each corner (C, 3), in its own frame, or None where its faces are flat
    (module docstring). Normals of the wrong count are named in the summary and not read."""
    scheme = UsdGeom.Mesh(prim).GetSubdivisionSchemeAttr()
    scheme = str(scheme.Get(ctx.time)) if scheme.HasAuthoredValue() else UsdGeom.Tokens.none
    face_n = _face_normals(points, counts, indices)
    if scheme != UsdGeom.Tokens.none:
        if scheme not in SMOOTH_SCHEMES:
            return None
        corner = smooth_vertex_normals(points, counts, indices)[indices]
    else:
        authored = _authored_normals(ctx, prim)
        if authored is None:
            return None
        values, interp = authored
        expected = {UsdGeom.Tokens.vertex: len(points), UsdGeom.Tokens.varying: len(points),
                    UsdGeom.Tokens.faceVarying: len(indices), UsdGeom.Tokens.uniform: len(counts),
                    UsdGeom.Tokens.constant: 1}.get(interp)
        if expected is None or len(values) != expected or not np.all(np.isfinite(values)):
            ctx.ignored[f"normals of the wrong count or interpolation {interp!r} (face normals used)"] += 1
            return None
        if interp in (UsdGeom.Tokens.vertex, UsdGeom.Tokens.varying):
            corner = values[indices]
        elif interp == UsdGeom.Tokens.faceVarying:
            corner = values
        elif interp == UsdGeom.Tokens.uniform:
            corner = _per_face_corners(values, counts)
        else:
            corner = np.broadcast_to(values[0], (len(indices), 3)).copy()
        corner = _unit_rows(corner)
    if _is_flat(corner, face_n, counts):
        return None
    return corner


def implicit_corner_normals(kind: str, points: np.ndarray, counts: np.ndarray, indices: np.ndarray,
                            axis: str = "Z", shape: tuple = ()) -> np.ndarray | None:
    """The analytic normal of an implicit round gprim at each tessellated corner (C, 3), in its own frame.

    Parameters
    ----------
    kind : {"Sphere", "Cylinder", "Cone", "Capsule"}
    points, counts, indices
        The polygons :mod:`.tessellation` made of it.
    axis : {"X", "Y", "Z"}
    shape : tuple
        Cylinder ``(radius_top, radius_bottom, height)``, Cone ``(radius, height)``, Capsule
        ``(radius, height)``; nothing for a Sphere.
    """
    rot = _AXIS_ROTATIONS[axis]
    local = points @ rot  # back in the frame whose axis is +Z
    corner_p = local[indices]
    face_n = _face_normals(local, counts, indices)
    corner_face_n = _per_face_corners(face_n, counts)
    if kind == "Sphere":
        out = _unit_rows(corner_p)
    elif kind == "Capsule":
        half = 0.5 * float(shape[1])
        centre = np.zeros_like(corner_p)
        centre[:, 2] = np.clip(corner_p[:, 2], -half, half)  # the axis point nearest: a cap's centre or the side's
        out = _unit_rows(corner_p - centre)
    else:
        if kind == "Cylinder":
            r_top, r_bottom, height = (float(v) for v in shape)
        else:  # Cone: apex up the axis
            r_top, r_bottom, height = 0.0, float(shape[0]), float(shape[1])
        # the side's outward normal in the (ρ, z) plane is (h, r_bottom − r_top), turned to the azimuth
        cap = np.abs(corner_face_n[:, 2]) > 1.0 - 1e-9
        centroid = np.repeat(np.add.reduceat(corner_p, np.cumsum(counts) - counts) / counts[:, None], counts, axis=0)
        rho = np.hypot(corner_p[:, 0], corner_p[:, 1])
        at = np.where(rho[:, None] > 1e-12 * max(1.0, r_bottom, r_top), corner_p, centroid)  # an apex: its face's azimuth
        phi = np.arctan2(at[:, 1], at[:, 0])
        side = _unit_rows(np.stack([height * np.cos(phi), height * np.sin(phi),
                                    np.full_like(phi, r_bottom - r_top)], axis=1))
        out = np.where(cap[:, None], corner_face_n, side)
    if _is_flat(out, face_n, counts):
        return None
    return out @ rot.T
