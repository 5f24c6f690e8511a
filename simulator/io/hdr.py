"""Radiance ``.hdr`` (RGBE) images in plain numpy: :func:`decode_rgbe` and :func:`encode_rgbe`.

The installed image libraries do not read Radiance pictures (Pillow has no
RGBE codec; imageio needs a FreeImage binary), so this is a small reader of
the format as Radiance defines it:

* a text header starting ``#?RADIANCE`` (or ``#?RGBE``), ``NAME=value``
  lines (``FORMAT=32-bit_rle_rgbe``; ``EXPOSURE=`` multipliers), a blank line;
* a resolution line ``-Y H +X W`` (rows top to bottom) or ``+Y H +X W``
  (bottom to top); the transposed orders (``+X``/``-X`` first) are refused;
* ``H`` scanlines of ``W`` pixels of 4 bytes ``(r, g, b, e)``, each either
  flat or in the "new" run-length encoding (a scanline of 8 <= W < 32768
  starts with ``2, 2, W >> 8, W & 255``, then the four channels one after the
  other, each as runs: a count byte > 128 repeats the next byte
  ``count - 128`` times, a count <= 128 is followed by that many literal bytes).

A pixel decodes as ``(m + 1/2) * 2**(e - 136)`` per channel ``m`` (0 when
``e == 0``), Radiance's ``colr_color``: the encoder truncates, so the half
step is the centre of each mantissa interval. The decoded values are divided
by the product of the ``EXPOSURE=`` lines (Radiance: "a multiplier that has
been applied to all the pixels"), giving back the radiance written.

References
----------
G. Ward, "Real Pixels", Graphics Gems II (1991), 80-83 (the RGBE encoding).
G. Ward Larson, R. Shakespeare, "Rendering with Radiance" (1998), ch. 10
(the picture file format, header and run-length encoding).
"""

from __future__ import annotations

import re

import numpy as np

__all__ = ["decode_rgbe", "encode_rgbe", "is_rgbe"]

_MAGIC = (b"#?RADIANCE", b"#?RGBE")
_RESOLUTION = re.compile(rb"([-+])Y\s+(\d+)\s+\+X\s+(\d+)")


class RGBEError(ValueError):
    """The bytes are not a Radiance picture this reader understands (the message says why)."""


def is_rgbe(data: bytes) -> bool:
    """True when ``data`` starts like a Radiance picture."""
    return data.startswith(_MAGIC)


def decode_rgbe(data: bytes) -> np.ndarray:
    """Decode a Radiance picture into linear RGB, shape ``(H, W, 3)``, float32, row 0 at the top.

    Raises
    ------
    RGBEError
        Not a Radiance picture, an unsupported FORMAT (XYZE) or resolution
        order, or truncated / corrupt pixel data.
    """
    if not is_rgbe(data):
        raise RGBEError("not a Radiance picture (no #?RADIANCE header)")
    end = data.find(b"\n\n")
    if end < 0:
        raise RGBEError("header has no end (blank line)")
    exposure = 1.0
    for line in data[:end].split(b"\n")[1:]:
        if line.startswith(b"FORMAT=") and line.strip() != b"FORMAT=32-bit_rle_rgbe":
            raise RGBEError(f"FORMAT {line[7:].strip().decode(errors='replace')} is not supported (only RGBE)")
        if line.startswith(b"EXPOSURE="):
            try:
                exposure *= float(line[9:])
            except ValueError:
                raise RGBEError(f"bad EXPOSURE line {line.decode(errors='replace')!r}") from None
    nl = data.find(b"\n", end + 2)
    match = _RESOLUTION.fullmatch(data[end + 2:nl].strip()) if nl > 0 else None
    if match is None:
        raise RGBEError("resolution line is not '-Y H +X W' or '+Y H +X W'")
    height, width = int(match.group(2)), int(match.group(3))
    if not (exposure > 0 and np.isfinite(exposure)):
        raise RGBEError(f"EXPOSURE {exposure:g} must be a positive number")
    pixels = _scanlines(memoryview(data)[nl + 1:], width, height)
    if match.group(1) == b"+":  # rows bottom to top
        pixels = pixels[::-1]
    return _rgbe_to_float(pixels) / np.float32(exposure)


def _rgbe_to_float(rgbe: np.ndarray) -> np.ndarray:
    """(..., 4) uint8 RGBE -> (..., 3) float32, ``(m + 0.5) * 2**(e - 136)``, zero where e == 0."""
    e = rgbe[..., 3].astype(np.int32)
    scale = np.where(e > 0, np.ldexp(1.0, e - 136), 0.0).astype(np.float32)
    return ((rgbe[..., :3].astype(np.float32) + 0.5) * scale[..., None]).astype(np.float32)


def _scanlines(buf: memoryview, width: int, height: int) -> np.ndarray:
    """(H, W, 4) uint8 from flat or new-RLE scanlines."""
    out = np.empty((height, width, 4), np.uint8)
    raw = np.frombuffer(buf, np.uint8)
    pos = 0
    for row in range(height):
        head = raw[pos:pos + 4]
        if 8 <= width < 32768 and len(head) == 4 and head[0] == 2 and head[1] == 2 and not head[2] & 0x80:
            if (int(head[2]) << 8) | int(head[3]) != width:
                raise RGBEError(f"scanline {row}: run-length width {(int(head[2]) << 8) | int(head[3])} "
                                f"is not the picture's {width}")
            pos += 4
            for c in range(4):
                pos = _decode_runs(raw, pos, out[row, :, c], row)
        else:  # flat pixels (old run-length encoding is not supported)
            n = 4 * width
            if pos + n > len(raw):
                raise RGBEError(f"pixel data ends in scanline {row} of {height}")
            out[row] = raw[pos:pos + n].reshape(width, 4)
            if np.any((out[row, :, 0] == 1) & (out[row, :, 1] == 1) & (out[row, :, 2] == 1)):
                raise RGBEError("old-style run-length encoding is not supported")
            pos += n
    return out


def _decode_runs(raw: np.ndarray, pos: int, dest: np.ndarray, row: int) -> int:
    """Fill one channel of one scanline from runs starting at ``raw[pos]``; return the new position."""
    i, width = 0, len(dest)
    while i < width:
        if pos >= len(raw):
            raise RGBEError(f"pixel data ends in scanline {row}")
        count = int(raw[pos])
        if count > 128:  # a run
            count -= 128
            if i + count > width or pos + 1 >= len(raw):
                raise RGBEError(f"scanline {row}: run overruns the line")
            dest[i:i + count] = raw[pos + 1]
            pos += 2
        else:  # literal bytes
            if count == 0 or i + count > width or pos + 1 + count > len(raw):
                raise RGBEError(f"scanline {row}: bad literal run")
            dest[i:i + count] = raw[pos + 1:pos + 1 + count]
            pos += 1 + count
        i += count
    return pos


def encode_rgbe(rgb: np.ndarray, rle: bool = True) -> bytes:
    """Encode linear RGB (H, W, 3) as a Radiance picture (``-Y H +X W``).

    Each pixel's largest channel ``v = f * 2**e`` (``f`` in [0.5, 1),
    ``numpy.frexp``) sets the shared exponent byte ``e + 128``; mantissas are
    ``floor(channel * 256 / 2**e)`` (truncation, as Radiance's ``setcolr``).
    With ``rle`` each channel of each scanline is written as literal runs
    of up to 128 bytes and repeat runs of 4 or more equal bytes.
    """
    rgb = np.asarray(rgb, np.float64)
    height, width = rgb.shape[:2]
    peak = rgb.max(axis=-1)
    frac, exp = np.frexp(peak)
    scale = np.where(peak > 1e-32, frac * 256.0 / np.where(peak > 0, peak, 1.0), 0.0)
    pix = np.zeros((height, width, 4), np.uint8)
    pix[..., :3] = np.clip(np.floor(rgb * scale[..., None]), 0, 255).astype(np.uint8)
    pix[..., 3] = np.where(peak > 1e-32, exp + 128, 0).astype(np.uint8)
    out = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + f"-Y {height} +X {width}\n".encode())
    use_rle = rle and 8 <= width < 32768
    for row in pix:
        if not use_rle:
            out += row.tobytes()
            continue
        out += bytes([2, 2, width >> 8, width & 255])
        for c in range(4):
            out += _encode_runs(row[:, c])
    return bytes(out)


def _encode_runs(line: np.ndarray) -> bytes:
    out = bytearray()
    i, n = 0, len(line)
    while i < n:
        j = i
        while j < n and j - i < 127 and line[j] == line[i]:
            j += 1
        if j - i >= 4:
            out += bytes([128 + j - i, int(line[i])])
            i = j
            continue
        start = i  # literal bytes up to the next run of 4 (or 128 bytes)
        while i < n and i - start < 128:
            if i + 4 <= n and np.all(line[i:i + 4] == line[i]):
                break
            i += 1
        out += bytes([i - start]) + line[start:i].tobytes()
    return bytes(out)
