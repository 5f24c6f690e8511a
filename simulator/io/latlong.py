"""The lat-long (equirectangular) map convention, in one place (pure numpy).

probesim reads and writes lat-long maps (a textured DomeLight's
``texture:file``, probe output) in the OpenEXR orientation, which is also
the one UsdLux DomeLight documents for its texture ("The dome's default
orientation ... adheres to the OpenEXR specification for latitude-longitude
maps").

Convention
----------
Directions are given in a map frame ``F`` (3 x 3, columns ``x, y, z``, unit,
right-handed; the identity for the map's own frame). In that frame, with
latitude ``lat`` in [-pi/2, pi/2] and longitude ``lon`` in [-pi, pi]::

    d_local = (cos(lat) sin(lon), sin(lat), cos(lat) cos(lon))
    d_world = F @ d_local

so the north pole (lat +pi/2) is ``F[:, 1]``, (lat 0, lon 0) is ``F[:, 2]`` and
(lat 0, lon +pi/2) is ``F[:, 0]`` (OpenEXR ``ImfEnvmap``: "latitudes -pi/2
and +pi/2 correspond to the negative and positive y direction. Latitude 0,
longitude 0 points into positive z direction; and latitude 0, longitude pi/2
points into positive x direction").

Texture coordinates ``(u, v)`` in [0, 1]^2 cover the image; the image is
indexed ``[row, column]`` with row 0 at the top (OpenEXR's ``dataWindow.min.y``)::

    lon = pi * (1 - 2 u)          u = 0: lon +pi (left edge), u = 1: lon -pi
    lat = pi * (1/2 - v)          v = 0: lat +pi/2 (top edge), v = 1: lat -pi/2
    theta = pi * v                polar angle from the pole F[:, 1]

A ``W x H`` image has texel ``(row j, column i)`` covering
``u in [i/W, (i+1)/W]``, ``v in [j/H, (j+1)/H]``; its centre is at
``((i + 1/2)/W, (j + 1/2)/H)``, and its solid angle is exactly
``(2 pi / W) * (cos(pi j / H) - cos(pi (j + 1) / H))``. Texels are
piecewise constant (nearest lookup), which is what the importance sampler in
``simulator.kernels.distributions`` assumes.

This is the continuous texture convention (pixel centres at half-integers)
that renderers use to look a lat-long map up. OpenEXR's own
``LatLongMap::direction`` instead puts pixel *centres* at the edges
(column 0 at lon +pi exactly, column W-1 at -pi); the two agree at the
centre column and differ by at most half a texel at the borders.

The Jacobian of the map is ``d omega = 2 pi^2 sin(theta) du dv``, so a
density ``pdf_uv`` over the unit square is ``pdf_uv / (2 pi^2 sin(theta))``
per steradian.

References
----------
OpenEXR, "Environment maps", ``ImfEnvmap.h`` / ``ImfEnvmap.cpp``;
OpenUSD, UsdLux ``DomeLight`` schema documentation.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "latlong_uv_to_direction",
    "direction_to_latlong_uv",
    "uv_to_texel",
    "texel_centre_directions",
    "texel_solid_angles",
    "sampling_weights",
    "build_distribution",
    "texel_probabilities",
]


def _frame(frame) -> np.ndarray:
    return np.eye(3) if frame is None else np.asarray(frame, float).reshape(3, 3)


def latlong_uv_to_direction(uv, frame=None) -> np.ndarray:
    """Unit direction of texture coordinates ``uv``.

    Parameters
    ----------
    uv : array_like, shape (..., 2)
        ``(u, v)`` in [0, 1] (see the module convention).
    frame : array_like, shape (3, 3), optional
        Map frame, columns x, y (pole), z (lat 0, lon 0); identity if None.

    Returns
    -------
    ndarray, shape (..., 3)
        Unit directions in the frame's parent (world) coordinates.
    """
    uv = np.asarray(uv, float)
    lon = np.pi * (1.0 - 2.0 * uv[..., 0])
    theta = np.pi * uv[..., 1]
    st = np.sin(theta)
    local = np.stack([st * np.sin(lon), np.cos(theta), st * np.cos(lon)], axis=-1)
    return local @ _frame(frame).T


def direction_to_latlong_uv(d, frame=None) -> np.ndarray:
    """Texture coordinates ``(u, v)`` of directions (inverse of :func:`latlong_uv_to_direction`).

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Directions (need not be unit length; must not be zero).
    frame : array_like, shape (3, 3), optional
        Map frame; identity if None.

    Returns
    -------
    ndarray, shape (..., 2)
        ``u`` in [0, 1] (``u = 0`` and ``u = 1`` are the same meridian,
        lon = +-pi; ``atan2`` gives u = 0 there), ``v`` in [0, 1].
    """
    d = np.asarray(d, float)
    local = d @ _frame(frame)  # components along the frame's columns
    lon = np.arctan2(local[..., 0], local[..., 2])
    theta = np.arctan2(np.hypot(local[..., 0], local[..., 2]), local[..., 1])
    return np.stack([0.5 - lon / (2.0 * np.pi), theta / np.pi], axis=-1)


def uv_to_texel(uv, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """``(row, column)`` integer indices of the texel holding ``uv`` (nearest lookup).

    ``u = 1`` and ``v = 1`` fall in the last column/row.
    """
    uv = np.asarray(uv, float)
    col = np.clip(np.floor(uv[..., 0] * width), 0, width - 1).astype(np.int64)
    row = np.clip(np.floor(uv[..., 1] * height), 0, height - 1).astype(np.int64)
    return row, col


def texel_centre_directions(width: int, height: int, frame=None) -> np.ndarray:
    """Directions of every texel centre, shape ``(height, width, 3)`` (row 0 = top)."""
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    uv = np.stack(np.meshgrid(u, v, indexing="xy"), axis=-1)
    return latlong_uv_to_direction(uv, frame)


def texel_solid_angles(width: int, height: int) -> np.ndarray:
    """Exact solid angle (sr) of one texel in each row, shape ``(height,)``.

    ``(2 pi / W) (cos theta_0 - cos theta_1)`` with ``theta_k`` the row's
    edges, written as ``2 sin((theta_0 + theta_1)/2) sin((theta_1 - theta_0)/2)``
    so that thin rows do not cancel. They sum to 4 pi over the map.
    """
    t0 = np.pi * np.arange(height) / height
    t1 = np.pi * (np.arange(height) + 1) / height
    return (2.0 * np.pi / width) * 2.0 * np.sin(0.5 * (t0 + t1)) * np.sin(0.5 * (t1 - t0))


def sampling_weights(values) -> np.ndarray:
    """Importance weights of a map: value x sin(theta), float64, shape ``(H, W)``.

    sin(theta) is its mean over each texel's row, i.e. the texel's solid angle
    over its (u, v) area, so the weight of a texel is proportional to the
    power it sends to a receiver that sees all of it head on.
    """
    values = np.asarray(values, float)
    h, w = values.shape
    mean_sin = texel_solid_angles(w, h) * (w * h) / (2.0 * np.pi**2)
    return values * mean_sin[:, None]


def build_distribution(weights) -> tuple[np.ndarray, np.ndarray]:
    """CDFs of the 2-D piecewise-constant distribution with density ∝ ``weights``.

    Parameters
    ----------
    weights : array_like, shape (H, W)
        Non-negative texel weights (row 0 = top, v = 0).

    Returns
    -------
    marginal_cdf : ndarray, shape (H + 1,), float64
        ``P(row < j)``: 0 first, exactly 1 last.
    conditional_cdf : ndarray, shape (H, W + 1), float64
        Per row ``P(column < i | row)``: 0 first, exactly 1 last. A row of
        zero weight gets a uniform conditional (it is never picked).

    Notes
    -----
    All-zero weights give the uniform distribution over (u, v). The kernel
    samples and evaluates from these CDFs (as float32) only, so its pdf is
    the one its sampler draws from: ``H (M[j+1] - M[j]) * W (C[j, i+1] - C[j, i])``
    over the unit square (Pharr, Jakob, Humphreys, PBRT 4th ed., A.5.6).
    """
    w = np.asarray(weights, float)
    if w.ndim != 2 or min(w.shape) < 1:
        raise ValueError(f"weights must be a non-empty 2-D array, not shape {w.shape}")
    if not np.all(np.isfinite(w)) or np.any(w < 0):
        raise ValueError("weights must be finite and non-negative")
    h, n = w.shape
    if w.sum() <= 0:
        w = np.ones_like(w)
    row_sum = w.sum(axis=1)
    cond = np.zeros((h, n + 1))
    cond[:, 1:] = np.cumsum(w, axis=1)
    empty = row_sum <= 0
    cond[empty, 1:] = np.arange(1, n + 1)
    cond /= cond[:, -1:]
    cond[:, -1] = 1.0
    marg = np.zeros(h + 1)
    marg[1:] = np.cumsum(row_sum)
    marg /= marg[-1]
    marg[-1] = 1.0
    return marg, cond


def texel_probabilities(marginal_cdf, conditional_cdf) -> np.ndarray:
    """Probability of each texel, shape ``(H, W)``, from the CDFs of :func:`build_distribution`."""
    m = np.diff(np.asarray(marginal_cdf, float))
    c = np.diff(np.asarray(conditional_cdf, float), axis=1)
    return m[:, None] * c
