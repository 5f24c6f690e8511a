"""Textures a stage points at: bytes through the asset resolver, and a UsdUVTexture's mean value.

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
    return np.concatenate([rgb.reshape(-1, 3).mean(axis=0), [float(alpha.mean())]])
