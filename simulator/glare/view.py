"""A glare view's geometry: its frame, the half lat-long map the probe kernel traces, the fisheye it is shown as.

Frame
-----
A view is an eye position, a unit view direction ``v`` and an up vector
made orthogonal to it, ``u``; ``left = u × v`` completes a right-handed
frame (``left × u = v``). The viewer's right is ``v × u``.

The traced map
--------------
The probe kernel (:mod:`simulator.kernels.probe`) estimates the mean
radiance over lat-long cells of any layout: pixel (i, j) spans longitudes
``[lon0 + i·dlon, lon0 + (i+1)·dlon]`` and latitudes ``[lat0 + j·dlat, …]``
in a map frame (ex, ey, ez), direction ``(sin lon·cos lat)·ex + sin lat·ey +
(cos lon·cos lat)·ez``. A view traces only the hemisphere in front of the
eye: ``ex = left``, ``ey = u``, ``ez = v``, longitudes from +90° (left
edge, column 0) to −90° (right edge), latitudes from +90° (top row) to −90°
(bottom row). A W × H map has pixels of ``π/W`` by ``π/H`` radians; a
pixel's solid angle is ``|Δlon|·|sin lat_b − sin lat_a|`` and the pixels tile
the hemisphere (Σ = 2π). No pixel lies behind the eye, so no trace is spent
there.

The fisheye
-----------
Images for people and for evalglare are 180° angular fisheyes (Radiance
``-vta -vh 180 -vv 180``): an N × N image, pixel (x, y) (row 0 on top) at
normalised coordinates ``a = 2(x + ½)/N − 1`` (right positive),
``b = 1 − 2(y + ½)/N`` (up positive), ``r = √(a² + b²)``; it looks at the
angle θ = r·90° from ``v``, toward ``a·right + b·u``; pixels with r > 1 see
nothing. (Radiance's ``viewray`` for ``VT_ANG``: the distance from the
centre is proportional to the angle, 90° at the edge for a 180° view.)
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "view_frame", "hemisphere_layout", "pixel_edges", "pixel_solid_angles", "pixel_centre_directions",
    "pixel_of_directions", "fisheye_directions", "fisheye_solid_angles",
]  # fmt: skip

#: below this sine of the angle between view direction and up they count as parallel
PARALLEL_SIN = 1e-6


def view_frame(direction, up) -> np.ndarray:
    """The view's frame: columns ``(left, u, v)`` (the map frame ex, ey, ez), right-handed.

    Parameters
    ----------
    direction, up : array_like, shape (3,)
        View direction and up vector (any length > 0; up is made orthogonal).

    Raises
    ------
    ValueError
        A zero-length direction or up, or an up parallel to the direction.
    """
    v = np.asarray(direction, np.float64).reshape(3)
    n = float(np.linalg.norm(v))
    if not n > 0.0 or not math.isfinite(n):
        raise ValueError("view direction has zero length")
    v = v / n
    w = np.asarray(up, np.float64).reshape(3)
    m = float(np.linalg.norm(w))
    if not m > 0.0 or not math.isfinite(m):
        raise ValueError("up vector has zero length")
    w = w / m
    ortho = w - float(w @ v) * v
    length = float(np.linalg.norm(ortho))
    if length < PARALLEL_SIN:
        raise ValueError("up vector is parallel to the view direction")
    u = ortho / length
    left = np.cross(u, v)
    return np.column_stack([left / np.linalg.norm(left), u, v])


def hemisphere_layout(width: int, height: int) -> tuple[float, float, float, float]:
    """``(lon0, dlon, lat0, dlat)`` of the front-hemisphere map (radians): +90° → −90° both ways."""
    return 0.5 * math.pi, -math.pi / width, 0.5 * math.pi, -math.pi / height


def pixel_edges(width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """Longitudes (W + 1,) and latitudes (H + 1,) of the pixel edges, radians, in map order."""
    lon0, dlon, lat0, dlat = hemisphere_layout(width, height)
    return lon0 + dlon * np.arange(width + 1), lat0 + dlat * np.arange(height + 1)


def pixel_solid_angles(width: int, height: int) -> np.ndarray:
    """Solid angle of every pixel, sr, shape (H, W): |Δlon|·|sin lat_b − sin lat_a|; they sum to 2π."""
    lon, lat = pixel_edges(width, height)
    band = np.abs(np.diff(np.sin(lat)))
    return np.repeat(band[:, None] * abs(lon[1] - lon[0]), width, axis=1)


def pixel_centre_directions(width: int, height: int, frame: np.ndarray) -> np.ndarray:
    """World direction of each pixel's solid-angle centre, shape (H, W, 3): longitude at the middle,
    sine of latitude at the middle (the centre of the cell's area on the sphere)."""
    lon, lat = pixel_edges(width, height)
    lc = 0.5 * (lon[:-1] + lon[1:])
    s = np.clip(0.5 * (np.sin(lat[:-1]) + np.sin(lat[1:])), -1.0, 1.0)
    c = np.sqrt(1.0 - s * s)
    local = np.stack(np.broadcast_arrays(np.sin(lc)[None, :] * c[:, None], s[:, None], np.cos(lc)[None, :] * c[:, None]), axis=-1)
    return local @ np.asarray(frame, np.float64).T


def pixel_of_directions(d: np.ndarray, width: int, height: int, frame: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The map pixel each world direction falls in: ``(row, column, in_front)``, each shape (...).

    Directions behind the eye (d·v ≤ 0) have ``in_front`` False (their row and column are clipped)."""
    local = np.asarray(d, np.float64) @ np.asarray(frame, np.float64)
    lon = np.arctan2(local[..., 0], local[..., 2])
    lat = np.arcsin(np.clip(local[..., 1], -1.0, 1.0))
    col = np.clip(np.floor((0.5 * math.pi - lon) / (math.pi / width)).astype(np.int64), 0, width - 1)
    row = np.clip(np.floor((0.5 * math.pi - lat) / (math.pi / height)).astype(np.int64), 0, height - 1)
    return row, col, local[..., 2] > 0.0


def fisheye_directions(n: int, frame: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """World direction of each pixel centre of an N × N 180° angular fisheye, and where one is seen.

    Returns
    -------
    d : ndarray, shape (N, N, 3)
        Unit directions (the view direction where r > 1).
    inside : ndarray of bool, shape (N, N)
        r ≤ 1: the pixel sees something.
    """
    frame = np.asarray(frame, np.float64)
    left, up, view = frame[:, 0], frame[:, 1], frame[:, 2]
    c = (np.arange(n) + 0.5) / n
    a = (2.0 * c - 1.0)[None, :].repeat(n, axis=0)
    b = (1.0 - 2.0 * c)[:, None].repeat(n, axis=1)
    r = np.hypot(a, b)
    inside = r <= 1.0
    theta = 0.5 * math.pi * np.minimum(r, 1.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        ca = np.where(r > 0, a / np.where(r > 0, r, 1.0), 0.0)
        cb = np.where(r > 0, b / np.where(r > 0, r, 1.0), 0.0)
    st = np.sin(theta)[..., None]
    d = np.cos(theta)[..., None] * view + st * (ca[..., None] * (-left) + cb[..., None] * up)
    return d, inside


def fisheye_solid_angles(n: int, oversample: int = 4) -> np.ndarray:
    """Solid angle of each pixel of an N × N 180° angular fisheye, sr, shape (N, N) (0 outside the circle).

    The angular fisheye's Jacobian: with ρ = r·π/2 the angle from the view, dω = sin ρ/ρ · (π/2)² da db
    (a, b the normalised coordinates, each pixel 2/N wide), integrated by an ``oversample`` ×
    ``oversample`` midpoint rule that also clips the pixel to the circle."""
    k = oversample
    sub = (np.arange(n * k) + 0.5) / (n * k)
    a = 2.0 * sub - 1.0
    aa, bb = np.meshgrid(a, -a)
    r = np.hypot(aa, bb)
    rho = 0.5 * math.pi * r
    with np.errstate(invalid="ignore", divide="ignore"):
        jac = np.where(r > 0, np.sin(rho) / np.where(r > 0, rho, 1.0), 1.0) * (0.5 * math.pi) ** 2
    jac = np.where(r <= 1.0, jac, 0.0) * (2.0 / (n * k)) ** 2
    return jac.reshape(n, k, n, k).sum(axis=(1, 3))
