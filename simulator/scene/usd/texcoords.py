"""Texture coordinates: where a UsdUVTexture reads its ``st``, and a mesh's st per triangle corner.

A texture read per texel (an opacity texture, :func:`.textures._coverage_texture`)
needs the surface point's ``st``. UsdPreviewSurface networks give it as

``UsdPrimvarReader_float2 (varname) -> [UsdTransform2d] -> UsdUVTexture.inputs:st``

and the mesh authors the primvar (``primvars:st`` by convention) with
``constant``, ``uniform``, ``vertex``, ``varying`` or ``faceVarying``
interpolation, indexed or not. The st of a triangle corner is the primvar's
value at the face corner it came from (``faceVarying``), at its point
(``vertex``, ``varying``), at its face (``uniform``) or everywhere
(``constant``); over a triangle st is interpolated linearly (the kernels use
the hit's barycentric coordinates).

``UsdTransform2d`` (UsdPreviewSurface specification): ``in`` scaled by
``scale``, rotated by ``rotation`` degrees counter-clockwise, then offset by
``translation``: ``st' = R(θ)·(scale ⊙ st) + translation``.

Wrap modes (``wrapS``, ``wrapT``): ``black``, ``clamp``, ``repeat`` and
``mirror`` as the specification defines them; ``useMetadata`` (the
fallback) asks the image file, whose wrap metadata probesim does not read,
and is taken as the specification's fallback for a file that says nothing,
``black``.
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd, UsdGeom, UsdShade

from simulator.scene.usd.context import _Context, _get

#: most UsdTransform2d nodes followed between a primvar reader and a texture
_MAX_TRANSFORMS = 8


def _wrap_mode(ctx: _Context, shader: UsdShade.Shader, name: str) -> str:
    """``wrapS`` / ``wrapT`` of a UsdUVTexture as one of :data:`simulator.scene.surfaces.WRAP_MODES`."""
    from simulator.scene.surfaces import WRAP_MODES

    inp = shader.GetInput(name)
    value = str(_get(ctx, inp.GetAttr()) or "useMetadata") if inp else "useMetadata"
    if value == "useMetadata":
        return "black"
    if value not in WRAP_MODES:
        raise ctx.error(shader.GetPrim(), f"inputs:{name} {value!r} must be one of "
                                          f"{', '.join(WRAP_MODES + ('useMetadata',))}")
    return value


def _source_of(inp: UsdShade.Input) -> tuple[UsdShade.Shader | None, str]:
    """The shader and output name an input is connected to (through NodeGraph interfaces)."""
    for attr in inp.GetValueProducingAttributes():
        if UsdShade.Output.IsOutput(attr):
            return UsdShade.Shader(attr.GetPrim()), UsdShade.Output(attr).GetBaseName()
    return None, ""


def _st_source(ctx: _Context, texture: UsdShade.Shader):
    """``(primvar name, st affine (2, 3))`` a UsdUVTexture reads its st from, or a string saying why not."""
    inp = texture.GetInput("st")
    node, _ = _source_of(inp) if inp else (None, "")
    affine = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    for _ in range(_MAX_TRANSFORMS):
        if node is None:
            return "its inputs:st not connected to a UsdPrimvarReader_float2"
        ident = node.GetShaderId()
        if ident != "UsdTransform2d":
            break
        affine = affine @ np.vstack([_transform2d(ctx, node), [0.0, 0.0, 1.0]])
        src = node.GetInput("in")
        node, _ = _source_of(src) if src else (None, "")
    if node is None or node.GetShaderId() != "UsdPrimvarReader_float2":
        return f"its inputs:st read from {node.GetShaderId() if node else 'nothing'}, not a UsdPrimvarReader_float2"
    var = node.GetInput("varname")
    name = None
    if var:
        for attr in var.GetValueProducingAttributes():
            if not UsdShade.Output.IsOutput(attr):
                name = _get(ctx, attr)
                if name is not None:
                    break
    if not name:
        return f"{node.GetPath()} has no varname"
    name = str(name)
    return (name[len("primvars:"):] if name.startswith("primvars:") else name), affine


def _transform2d(ctx: _Context, node: UsdShade.Shader) -> np.ndarray:
    """A UsdTransform2d node as the (2, 3) affine map ``st' = A @ (s, t, 1)`` (module docstring)."""
    def value(name, default):
        inp = node.GetInput(name)
        v = _get(ctx, inp.GetAttr()) if inp else None
        return default if v is None else v

    theta = math.radians(float(value("rotation", 0.0)))
    sx, sy = (float(v) for v in value("scale", (1.0, 1.0)))
    tx, ty = (float(v) for v in value("translation", (0.0, 0.0)))
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c * sx, -s * sy, tx], [s * sx, c * sy, ty]])


def _corner_st(ctx: _Context, prim: Usd.Prim, primvar: str, face_of: np.ndarray, corner_tris: np.ndarray,
               indices: np.ndarray) -> np.ndarray | None:
    """The primvar's st at each triangle corner, shape (T, 3, 2), or None when the prim does not author it
    (or it has the wrong size for its interpolation: named in the summary warning).

    ``corner_tris`` (T, 3) are face-vertex (corner) indices, ``face_of`` (T,) each triangle's face and
    ``indices`` the mesh's faceVertexIndices (a corner's point).
    """
    pv = UsdGeom.PrimvarsAPI(prim).GetPrimvar(primvar) if prim.IsA(UsdGeom.Imageable) else None
    if not pv or not pv.HasAuthoredValue():
        return None
    values = pv.ComputeFlattened(ctx.time)
    if values is None:
        return None
    st = np.asarray(values, float) if len(values) else np.zeros((0, 2))
    if st.ndim != 2 or st.shape[1] != 2:
        ctx.ignored[f"primvars:{primvar} not two numbers per value (an opacity texture's mean used)"] += 1
        return None
    interp = pv.GetInterpolation()
    if interp == UsdGeom.Tokens.faceVarying:
        at = corner_tris
    elif interp in (UsdGeom.Tokens.vertex, UsdGeom.Tokens.varying):
        at = indices[corner_tris]
    elif interp == UsdGeom.Tokens.uniform:
        at = np.repeat(face_of[:, None], 3, axis=1)
    else:  # constant
        at = np.zeros_like(corner_tris)
    if len(at) and (at.max() >= len(st) or not np.all(np.isfinite(st))):
        ctx.ignored[f"primvars:{primvar} of the wrong size or not finite (an opacity texture's mean used)"] += 1
        return None
    return st[at]
