"""Curved reflectors read as flat facets: the warning that says so.

Every gprim is traced as the triangles it is tessellated into, each shaded by
its face normal. For a matte surface that is a small error in where light
lands; for a mirror or a glossy lobe it is not: a mirror ball cut into
facets shows a light's reflection only where a facet happens to face it
(under the sun a radiance meter aimed at the ball's highlight reads 0, or
the sun's full F·L where a facet is exactly aligned), and a glossy highlight
is spread over the facet's fixed normal instead of the surface's turning
one. Smooth shading normals (an authored ``normals`` primvar, an implicit
Sphere's own normal) are not modelled, so such a surface is named in the
summary rather than read silently.

A prim is named when faces of it carry a glossy or mirror surface row and
it is curved: an implicit round gprim (Sphere, Cylinder, Cone, Capsule), or
a Mesh whose authored normals (vertex, varying or faceVarying) turn by more
than :data:`TURN_DEG` from the face normals they sit on.
"""

from __future__ import annotations

import numpy as np
from pxr import Usd, UsdGeom

#: an authored normal this far (degrees) from its face's normal marks the mesh as smooth-shaded
TURN_DEG = 1.0
_ROUND = ("Sphere", "Cylinder", "Cone", "Capsule")


def _smooth_mesh(prim: Usd.Prim) -> bool:
    """Whether a Mesh's authored normals turn away from its faces' normals (a smooth-shaded mesh)."""
    mesh = UsdGeom.Mesh(prim)
    pv = UsdGeom.PrimvarsAPI(prim).GetPrimvar("normals")
    if pv and pv.HasAuthoredValue():
        normals, interp = pv.ComputeFlattened(), pv.GetInterpolation()
    elif mesh.GetNormalsAttr().HasAuthoredValue():
        normals, interp = mesh.GetNormalsAttr().Get(), mesh.GetNormalsInterpolation()
    else:
        return False
    points = mesh.GetPointsAttr().Get()
    counts = mesh.GetFaceVertexCountsAttr().Get()
    indices = mesh.GetFaceVertexIndicesAttr().Get()
    if normals is None or points is None or counts is None or indices is None:
        return False
    if interp not in (UsdGeom.Tokens.vertex, UsdGeom.Tokens.varying, UsdGeom.Tokens.faceVarying):
        return False
    normals, points, indices = np.asarray(normals, float), np.asarray(points, float), np.asarray(indices, int)
    counts = np.asarray(counts, int)
    per_corner = normals if interp == UsdGeom.Tokens.faceVarying else normals[np.minimum(indices, len(normals) - 1)]
    if len(per_corner) < len(indices):
        return False
    cos_turn = np.cos(np.radians(TURN_DEG))
    start = 0
    for c in counts:
        if c >= 3:
            poly = points[indices[start:start + c]]
            fn = np.cross(poly[1] - poly[0], poly[2] - poly[0])
            ln = np.linalg.norm(fn)
            if ln > 0:
                nn = per_corner[start:start + c]
                nn = nn / np.maximum(np.linalg.norm(nn, axis=1), 1e-300)[:, None]
                if np.any(np.abs(nn @ (fn / ln)) < cos_turn):
                    return True
        start += c
    return False


def faceted_reflectors(stage: Usd.Stage, geometry) -> list[str]:
    """The paths of curved prims whose faces reflect by a glossy or mirror lobe (module docstring)."""
    if geometry.surface_id is None or not geometry.surfaces:
        return []
    glossy = np.array([bool(getattr(s, "glossy", False)) for s in geometry.surfaces] + [False], bool)
    prims = np.unique(geometry.prim[glossy[geometry.surface_id]])
    out = []
    for i in prims:
        name = geometry.prim_names[int(i)]
        prim = stage.GetPrimAtPath(name) if name.startswith("/") else Usd.Prim()
        if not prim or not prim.IsValid():
            continue
        kind = prim.GetTypeName()
        if kind in _ROUND or (kind == "Mesh" and _smooth_mesh(prim)):
            out.append(name)
    return out


def faceted_note(names: list[str]) -> str:
    """The summary line for :func:`faceted_reflectors`' prims."""
    shown = ", ".join(names[:3]) + (" ..." if len(names) > 3 else "")
    return (f"curved mirror or glossy surface(s) {shown} are traced as flat facets with face normals "
            "(smooth normals are not modelled): their reflections of small lights and the sun are wrong, "
            "a mirror facet shows a light only where it happens to face it; model such a reflector flat, "
            "or raise probesim:tessellation on a Sphere")
