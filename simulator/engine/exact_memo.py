"""The exact estimator's geometric factors, kept for a Python process's later runs.

For one RectLight, the irradiance :func:`simulator.engine.exact.visible_polygon_irradiance`
returns at radiance 1 — ∫_{Ω_vis} cos θ dω per receiver, sr — depends on
geometry only: the light's corners and facing, the occluder triangles and the
receivers' positions and normals. A run multiplies it by the light's
emission. It is kept under a BLAKE2b digest of exactly those float64 arrays,
so the same geometry reads the same factor however the scene was obtained,
while a light that moved, resized or turned, an occluder that moved or a
sensor that moved is computed afresh; a change of intensity or colour alone
reuses the factor. The :data:`MAX_ENTRIES` most recently used factors are
kept (each S float64).
"""

from __future__ import annotations

import hashlib

import numpy as np

from simulator.memo import Kept

__all__ = ["MAX_ENTRIES", "digest", "factor", "clear"]

#: factors kept (one per light and receiver chunk; least recently used dropped first)
MAX_ENTRIES = 64

_entries = Kept(MAX_ENTRIES)


def digest(*arrays) -> bytes:
    """BLAKE2b of the arrays' float64 bytes, each preceded by its shape."""
    h = hashlib.blake2b(digest_size=32)
    for a in arrays:
        a = np.ascontiguousarray(a, np.float64)
        h.update(repr(a.shape).encode())
        h.update(a.tobytes())
    return h.digest()


def factor(key: bytes, compute) -> np.ndarray:
    """The kept factor under ``key``, else ``compute()`` (an (S,) array), kept. A copy either way."""
    e = _entries.get(key)
    if e is not None:
        return e.copy()
    e = np.array(compute(), np.float64)
    _entries.put(key, e.copy())
    return e


def clear() -> None:
    """Forget every kept factor."""
    _entries.clear()
