"""An opacity texture's filtered value at st, in float64, for the reference cases.

Written from UsdUVTexture's definition, apart from the kernels'
(:mod:`simulator.kernels.coverage`): bilinear between texel centres at
((i + ½)/w, 1 − (j + ½)/h), j counted from the image's top row, each axis
wrapped by its mode (docs/REFERENCES.md §Coverage).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["bilinear_at"]


def _wrapped(i: int, n: int, mode: str) -> int | None:
    """Index i on an axis of n texels after the wrap ``mode``; None outside the image for ``black``."""
    if 0 <= i < n:
        return i
    if mode == "clamp":
        return min(max(i, 0), n - 1)
    if mode == "repeat":
        return i % n
    if mode == "mirror":
        m = i % (2 * n)
        return m if m < n else 2 * n - 1 - m
    return None


def bilinear_at(opacity: np.ndarray, st, wrap=("black", "black"), border: float = 0.0) -> float:
    """The bilinear value of texels ``opacity`` (H, W), row 0 at the top, at ``st`` (s, t)."""
    h, w = opacity.shape
    x = float(st[0]) * w - 0.5
    y = (1.0 - float(st[1])) * h - 0.5
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j

    def tex(a: int, b: int) -> float:
        ia, jb = _wrapped(a, w, wrap[0]), _wrapped(b, h, wrap[1])
        return border if ia is None or jb is None else float(opacity[jb, ia])

    return ((1 - fx) * (1 - fy) * tex(i, j) + fx * (1 - fy) * tex(i + 1, j)
            + (1 - fx) * fy * tex(i, j + 1) + fx * fy * tex(i + 1, j + 1))
