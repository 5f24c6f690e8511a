"""Texture images as float arrays: OpenEXR, Radiance .hdr, and 8/16-bit PNG, JPEG, TIFF, ...

:func:`read_image` reads a file (or bytes, e.g. from inside a ``.usdz``
package) into float values as the file stores them, with how they are
encoded; :func:`srgb_to_linear` undoes the sRGB transfer function. OpenEXR
goes through :mod:`simulator.io.exr`, Radiance pictures through
:mod:`simulator.io.hdr`, everything else through ``imageio`` (installed with
scikit-image), integer samples scaled to [0, 1] by their type's maximum.

Problems with a file are :class:`~simulator.errors.UserError` naming it.
"""

from __future__ import annotations

import io
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from simulator.errors import UserError

__all__ = ["Image", "read_image", "srgb_to_linear"]


@dataclass
class Image:
    """Decoded samples, shape (H, W, C), float64, row 0 at the top.

    ``integer_bits`` is 8 or 16 for integer files (samples scaled to
    [0, 1]; usually sRGB-encoded), 0 for float files (linear: EXR, HDR).
    """

    pixels: np.ndarray
    integer_bits: int

    @property
    def rgb(self) -> np.ndarray:
        """(H, W, 3): grey images repeated, alpha dropped."""
        c = self.pixels.shape[-1]
        if c >= 3:
            return self.pixels[..., :3]
        return np.repeat(self.pixels[..., :1], 3, axis=-1)


def srgb_to_linear(v) -> np.ndarray:
    """Linear values of sRGB-encoded ones in [0, 1].

    Notes
    -----
    IEC 61966-2-1 decoding: ``v / 12.92`` for ``v <= 0.04045``, else
    ``((v + 0.055) / 1.055) ** 2.4``.

    References
    ----------
    IEC 61966-2-1:1999, "Multimedia systems and equipment - Colour
    measurement and management - Part 2-1: Default RGB colour space - sRGB", §5.2.
    """
    v = np.asarray(v, np.float64)
    return np.where(v <= 0.04045, v / 12.92, ((np.maximum(v, 0.04045) + 0.055) / 1.055) ** 2.4)


def read_image(path: str | os.PathLike, data: bytes | None = None) -> Image:
    """Read an image file (or its bytes ``data``, named ``path`` for the format and messages).

    Raises
    ------
    UserError
        The file is missing, or no reader understands it.
    """
    name = str(path)
    suffix = Path(name.split("[")[-1].rstrip("]")).suffix.lower()
    if data is None:
        p = Path(name)
        if not p.is_file():
            raise UserError(f"{name}: file not found")
        data = p.read_bytes()
    from simulator.io import hdr

    if suffix == ".hdr" or hdr.is_rgbe(data):
        try:
            return Image(hdr.decode_rgbe(data).astype(np.float64), 0)
        except hdr.RGBEError as err:
            raise UserError(f"{name}: not a readable Radiance picture ({err})") from None
    if suffix == ".exr" or data[:4] == b"\x76\x2f\x31\x01":
        return Image(_read_exr(name, data), 0)
    return _read_integer(name, data, suffix)


def _read_exr(name: str, data: bytes) -> np.ndarray:
    from simulator.io import exr

    if Path(name).is_file():
        return exr.read_rgb(name).astype(np.float64)
    with tempfile.TemporaryDirectory() as tmp:  # bytes from a package: OpenEXR reads files
        p = Path(tmp) / "texture.exr"
        p.write_bytes(data)
        try:
            return exr.read_rgb(p).astype(np.float64)
        except UserError as err:
            raise UserError(f"{name}: {str(err).split(': ', 1)[-1]}") from None


def _read_integer(name: str, data: bytes, suffix: str) -> Image:
    import imageio.v3 as iio

    try:
        arr = np.asarray(iio.imread(io.BytesIO(data), extension=suffix or None))
    except Exception as exc:  # the plugin's own errors: unknown format, truncated file
        raise UserError(f"{name}: not a readable image ({' '.join(str(exc).split())[:200]})") from None
    if arr.ndim == 2:
        arr = arr[..., None]
    if arr.ndim != 3:
        raise UserError(f"{name}: image of shape {arr.shape} is not a single picture")
    if np.issubdtype(arr.dtype, np.integer):
        bits = 8 if arr.dtype.itemsize == 1 else 16
        return Image(arr.astype(np.float64) / np.iinfo(arr.dtype).max, bits)
    return Image(arr.astype(np.float64), 0)
