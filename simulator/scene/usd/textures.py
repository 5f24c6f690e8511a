"""Textures a stage points at: bytes through the asset resolver, a UsdUVTexture's mean value, and
the per-texel opacity of a texture that drives ``inputs:opacity`` (:func:`_coverage_texture`).

probesim's surfaces are uniform, so a ``diffuseColor`` connected to a
``UsdUVTexture`` is read as the texture's *mean* value (the mean over its
texels, i.e. over texture space, not weighted by the surface area each texel
covers), after the texture's own decoding:

``value = scale * mean(decode(texel)) + bias``

per channel, with ``decode`` the sRGB transfer function for an 8-bit
texture whose ``sourceColorSpace`` is ``auto`` or ``sRGB`` (UsdUVTexture:
"auto" treats 8-bit images as sRGB), identity for ``raw`` and for float
(EXR, HDR) or 16-bit images. The output used (``rgb``, ``r``, ``g``, ``b``,
``a``) picks the channels: a grey image feeds ``r = g = b``, and an image
without alpha has ``a = 1``.

References
----------
OpenUSD, "UsdPreviewSurface Specification", UsdUVTexture (inputs file, scale,
bias, sourceColorSpace; outputs rgb, r, g, b, a).
"""

from __future__ import annotations

import numpy as np
from pxr import Ar, Usd, UsdShade

from simulator.errors import UserError
from simulator.io.images import read_image, srgb_to_linear
from simulator.scene.usd.context import _Context, _get

#: UsdUVTexture outputs and the channels of an RGBA texel each one reads
_OUTPUT_CHANNELS = {"rgb": [0, 1, 2], "r": [0], "g": [1], "b": [2], "a": [3]}


def _asset_data(resolved: str) -> bytes | None:
    """The bytes of a resolved asset (a file, or a file inside a ``.usdz``: ``pkg.usdz[tex.png]``)."""
    if not resolved:
        return None
    asset = Ar.GetResolver().OpenAsset(Ar.ResolvedPath(resolved))
    return bytes(asset.GetBuffer()) if asset else None


def _texture_mean(ctx: _Context, output: Usd.Attribute) -> tuple[tuple[float, ...] | None, str]:
    """Mean value of the UsdUVTexture output ``output`` (a tuple of 1 or 3 floats), or ``(None, why)``."""
    shader = UsdShade.Shader(output.GetPrim())
    out_name = UsdShade.Output(output).GetBaseName()
    if not shader or shader.GetShaderId() != "UsdUVTexture" or out_name not in _OUTPUT_CHANNELS:
        source = shader.GetShaderId() if shader else output.GetPrim().GetTypeName()
        return None, f"connected to {source or 'a shader'}.{out_name}"
    file_input = shader.GetInput("file")
    asset = _get(ctx, file_input.GetAttr()) if file_input else None
    if asset is None or not asset.path:
        return None, "a UsdUVTexture without a file"
    rgba = _mean_rgba(ctx, asset.resolvedPath, _source_colour_space(ctx, shader))
    if rgba is None:
        return None, "its texture file not found or unreadable"
    scale = _float4(ctx, shader, "scale", (1.0, 1.0, 1.0, 1.0))
    bias = _float4(ctx, shader, "bias", (0.0, 0.0, 0.0, 0.0))
    chans = _OUTPUT_CHANNELS[out_name]
    return tuple(float(scale[c] * rgba[c] + bias[c]) for c in chans), ""


def _source_colour_space(ctx: _Context, shader: UsdShade.Shader) -> str:
    inp = shader.GetInput("sourceColorSpace")
    value = _get(ctx, inp.GetAttr()) if inp else None
    return str(value or "auto")


def _float4(ctx: _Context, shader: UsdShade.Shader, name: str, default) -> tuple[float, ...]:
    inp = shader.GetInput(name)
    value = _get(ctx, inp.GetAttr()) if inp else None
    return tuple(float(v) for v in value) if value is not None and len(value) == 4 else default


def _mean_rgba(ctx: _Context, resolved: str, colour_space: str) -> np.ndarray | None:
    """Mean decoded RGBA (4,) of a texture file, cached per (file, colour space); None if unreadable."""
    key = f"{resolved}|{colour_space}"
    if key not in ctx.textures:
        ctx.textures[key] = _read_mean_rgba(resolved, colour_space)
    return ctx.textures[key]


def _read_mean_rgba(resolved: str, colour_space: str) -> np.ndarray | None:
    rgba = _read_rgba(resolved, colour_space)
    return None if rgba is None else rgba.reshape(-1, 4).mean(axis=0)


def _read_rgba(resolved: str, colour_space: str) -> np.ndarray | None:
    """Decoded RGBA texels (H, W, 4) of a texture file, row 0 at the top; None if unreadable."""
    data = _asset_data(resolved)
    if data is None:
        return None
    try:
        image = read_image(resolved, data)
    except UserError:
        return None
    px = image.pixels
    c = px.shape[-1]
    rgb = px[..., :3] if c >= 3 else np.repeat(px[..., :1], 3, axis=-1)
    alpha = px[..., 3] if c == 4 else (px[..., 1] if c == 2 else np.ones(px.shape[:2]))
    if colour_space == "sRGB" or (colour_space == "auto" and image.integer_bits == 8):
        rgb = srgb_to_linear(rgb)
    return np.concatenate([rgb, alpha[..., None]], axis=-1)


#: MDL ``base::mono_mode`` (base.mdl, in its order): how ``base::file_texture(...).mono`` makes one number
#: of a texel: 0 its alpha, 1 the mean of R, G, B, 2 their luminance (BT.709 weights), 3 their maximum
MONO_MODES = ("mono_alpha", "mono_average", "mono_luminance", "mono_maximum")


def mono_texels(rgba: np.ndarray, mode: int) -> np.ndarray:
    """One number per texel of decoded RGBA texels (H, W, 4) as ``base::mono_mode`` ``mode`` (0–3,
    :data:`MONO_MODES`) makes it, shape (H, W)."""
    if mode == 0:
        return rgba[..., 3]
    if mode == 1:
        return rgba[..., :3].mean(axis=-1)
    if mode == 2:
        return rgba[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    return rgba[..., :3].max(axis=-1)


def _file_coverage(ctx: _Context, resolved: str, colour_space: str, mode: int, name: str,
                   wrap: tuple = ("repeat", "repeat"), primvar: str = "st") -> int:
    """Index into ``ctx.coverage_textures`` of a texture file's per-texel opacity read by ``base::mono_mode``
    ``mode`` (an MDL ``texture_2d``: no scale or bias, repeat wrap, the first uv set ``st``), -1 when the
    file cannot be read (the caller has named it)."""
    from simulator.scene.surfaces import CoverageTexture

    key = ("mdl", resolved, colour_space, mode, wrap, primvar)
    if key not in ctx.coverage_texture_index:
        rgba = _read_rgba(resolved, colour_space)
        if rgba is None:
            return -1
        opacity = np.clip(mono_texels(rgba, mode), 0.0, 1.0).astype(np.float32)
        ctx.coverage_texture_index[key] = len(ctx.coverage_textures)
        ctx.coverage_textures.append(CoverageTexture(name=name, opacity=opacity, wrap=wrap, border=0.0,
                                                     primvar=primvar))
    return ctx.coverage_texture_index[key]


def _coverage_texture(ctx: _Context, output: Usd.Attribute, where: str):
    """The per-texel opacity of the UsdUVTexture output ``output`` (a float output: ``r``, ``g``, ``b``
    or ``a``), as ``(index into ctx.coverage_textures, "")``, or ``(-1, why)`` when it is not read per
    texel (``why`` names what is missing; the mean is used).

    Raises
    ------
    UserError
        ``<stage>: <shader>: inputs:file @<path>@ (feeding <where>): not found or unreadable``: an
        opacity texture decides what blocks light, so a file that cannot be read is an error.
    """
    from simulator.scene.surfaces import CoverageTexture
    from simulator.scene.usd.texcoords import _st_source, _wrap_mode

    shader = UsdShade.Shader(output.GetPrim())
    out_name = UsdShade.Output(output).GetBaseName()
    chans = _OUTPUT_CHANNELS.get(out_name, [])
    if not shader or shader.GetShaderId() != "UsdUVTexture" or len(chans) != 1:
        return -1, "not a one-channel UsdUVTexture output"
    asset = _get(ctx, shader.GetInput("file").GetAttr()) if shader.GetInput("file") else None
    if asset is None or not asset.path:
        return -1, "a UsdUVTexture without a file"
    space = _source_colour_space(ctx, shader)
    if _mean_rgba(ctx, asset.resolvedPath, space) is None:
        raise ctx.error(shader.GetPrim(), f"inputs:file @{asset.path}@ (feeding {where}): not found or unreadable")
    st = _st_source(ctx, shader)
    if isinstance(st, str):
        return -1, st
    primvar, affine = st
    c = chans[0]
    scale = _float4(ctx, shader, "scale", (1.0, 1.0, 1.0, 1.0))[c]
    bias = _float4(ctx, shader, "bias", (0.0, 0.0, 0.0, 0.0))[c]
    wrap = (_wrap_mode(ctx, shader, "wrapS"), _wrap_mode(ctx, shader, "wrapT"))
    key = (asset.resolvedPath, space, c, scale, bias, wrap, primvar, tuple(affine.ravel()))
    if key not in ctx.coverage_texture_index:
        rgba = _read_rgba(asset.resolvedPath, space)
        opacity = np.clip(scale * rgba[..., c] + bias, 0.0, 1.0).astype(np.float32)
        ctx.coverage_texture_index[key] = len(ctx.coverage_textures)
        ctx.coverage_textures.append(CoverageTexture(
            name=f"{shader.GetPath()} ({asset.path})", opacity=opacity, wrap=wrap,
            border=float(np.clip(bias, 0.0, 1.0)), primvar=primvar, st_affine=affine))
    return ctx.coverage_texture_index[key], ""
