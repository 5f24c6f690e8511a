"""Tregenza's 145 sky patches, and the CIE skies as patch luminances (daylight coefficients).

The sky hemisphere is cut into 7 altitude bands 12° wide, starting at the
horizon, of 30, 30, 24, 24, 18, 12 and 6 patches, and a polar cap above
84° (one patch): 145 patches (Tregenza 1987). Patches are numbered band by
band from the horizon up, and within a band by azimuth, patch j of a band
of n centred on azimuth 360°·j/n measured from north toward east (the
study's convention, :mod:`simulator.study.inputs.sun`: +Y north, +X east, +Z up in
the world frame). Directions below the horizon are patch 145, the
*ground* slot.

A dome light traced with its sky split into patches (a ``[[group]]`` with
``sky = "tregenza"``, :mod:`simulator.study.trace.groups`) reads one daylight
coefficient c_p per patch: the sensor's reading with only patch p of the
dome lit at the dome's authored radiance L_dome. Light transport is linear,
so a sky of patch luminances L_p reads

.. math:: E = \\sum_p c_p\\, L_p / L_{dome}, \\qquad \\sigma^2 = d^\\top C\\, d,
          \\quad d_p = L_p / L_{dome}.

Notes
-----
Patch solid angle and projected solid angle, for a band from altitude a₀
to a₁ of n patches (the cap: a₀ = 84°, a₁ = 90°, n = 1):

.. math:: \\Omega = \\frac{2\\pi}{n}(\\sin a_1 - \\sin a_0), \\qquad
          \\int \\cos\\theta\\, d\\omega = \\frac{\\pi}{n}(\\sin^2 a_1 - \\sin^2 a_0),

summing to 2π and π over the hemisphere (θ the zenith angle, cosθ = sin a).

CIE standard general sky (ISO 15469 / CIE S 011): the luminance relative to
the zenith's at zenith angle Z, at angular distance χ from the sun (sun at
zenith angle Z_s), is

.. math:: \\frac{L}{L_z} = \\frac{f(\\chi)\\,\\varphi(Z)}{f(Z_s)\\,\\varphi(0)},\\quad
          \\varphi(Z) = 1 + a\\,e^{b/\\cos Z},\\quad
          f(\\chi) = 1 + c\\,(e^{d\\chi} - e^{d\\pi/2}) + e\\cos^2\\chi,

with φ(90°) = 1, and (a, b, c, d, e) per type in :data:`CIE_TYPES`. Type 1
is the standard's overcast sky with steep gradation (zenith/horizon ratio
φ(0) = 1 + 4e^{−0.7} = 2.99); the traditional CIE overcast sky (Moon and
Spencer, L ∝ (1 + 2 sin γ)/3, ratio exactly 3) is :func:`overcast_luminance`.
A patch's luminance is its mean over the patch (a midpoint rule on a grid
uniform in solid angle, :func:`patch_means`).

References
----------
Tregenza, P. R. (1987). Subdivision of the sky hemisphere for luminance
measurements. Lighting Research and Technology 19(1), 13–14.
docs/REFERENCES.md §Tregenza sky patches, §CIE standard general sky and
§CIE standard overcast sky.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "BAND_COUNTS", "N_PATCHES", "GROUND", "CIE_TYPES", "band_edges_deg", "patch_index", "patch_direction",
    "patch_solid_angle", "patch_projected_solid_angle", "general_sky_luminance", "overcast_luminance",
    "patch_means", "sky_weights",
]  # fmt: skip

#: patches per 12° altitude band from the horizon up, the last entry the polar cap (Tregenza 1987)
BAND_COUNTS = (30, 30, 24, 24, 18, 12, 6, 1)
#: 145 sky patches
N_PATCHES = sum(BAND_COUNTS)
#: slot of directions below the horizon (patch index 145)
GROUND = N_PATCHES
#: first patch index of each band
BAND_START = tuple(int(x) for x in np.cumsum((0,) + BAND_COUNTS[:-1]))
BAND_DEG = 12.0

#: CIE standard general sky: type -> (a, b, c, d, e), ISO 15469:2004 / CIE S 011/E:2003 Table 1
CIE_TYPES = {
    1: (4.0, -0.70, 0.0, -1.0, 0.00),
    2: (4.0, -0.70, 2.0, -1.5, 0.15),
    3: (1.1, -0.80, 0.0, -1.0, 0.00),
    4: (1.1, -0.80, 2.0, -1.5, 0.15),
    5: (0.0, -1.00, 0.0, -1.0, 0.00),
    6: (0.0, -1.00, 2.0, -1.5, 0.15),
    7: (0.0, -1.00, 5.0, -2.5, 0.30),
    8: (0.0, -1.00, 10.0, -3.0, 0.45),
    9: (-1.0, -0.55, 2.0, -1.5, 0.15),
    10: (-1.0, -0.55, 5.0, -2.5, 0.30),
    11: (-1.0, -0.55, 10.0, -3.0, 0.45),
    12: (-1.0, -0.32, 10.0, -3.0, 0.45),
    13: (-1.0, -0.32, 16.0, -3.0, 0.30),
    14: (-1.0, -0.15, 16.0, -3.0, 0.30),
    15: (-1.0, -0.15, 24.0, -2.8, 0.15),
}


def band_edges_deg(band: int) -> tuple[float, float]:
    """Altitude range ``(a0, a1)`` in degrees of band 0…7 (7: the cap, 84°–90°)."""
    return BAND_DEG * band, min(BAND_DEG * (band + 1), 90.0)


def _band_of(p: int) -> int:
    return int(np.searchsorted(np.asarray(BAND_START), p, side="right") - 1)


def patch_index(d: np.ndarray) -> np.ndarray:
    """Patch of each direction: 0…144 above the horizon, ``GROUND`` (145) at or below it.

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Directions in the world frame (+X east, +Y north, +Z up); need not be unit.

    Returns
    -------
    ndarray of int64, shape (...)
    """
    d = np.asarray(d, np.float64)
    r = np.linalg.norm(d, axis=-1)
    sin_alt = np.clip(d[..., 2] / np.where(r > 0, r, 1.0), -1.0, 1.0)
    alt = np.degrees(np.arcsin(sin_alt))
    band = np.minimum((alt / BAND_DEG).astype(np.int64), len(BAND_COUNTS) - 1)
    n = np.asarray(BAND_COUNTS)[np.clip(band, 0, None)]
    az = np.mod(np.arctan2(d[..., 0], d[..., 1]), 2 * math.pi)  # from north (+Y) toward east (+X)
    j = np.mod(np.floor(az / (2 * math.pi / n) + 0.5).astype(np.int64), n)
    out = np.asarray(BAND_START)[np.clip(band, 0, None)] + j
    return np.where(d[..., 2] > 0.0, out, GROUND)


def patch_direction(p: int) -> np.ndarray:
    """Unit direction toward patch ``p``'s centre (mid altitude of its band, its centre azimuth); shape (3,)."""
    b = _band_of(p)
    a0, a1 = band_edges_deg(b)
    alt = math.radians(90.0 if b == len(BAND_COUNTS) - 1 else 0.5 * (a0 + a1))
    az = 2 * math.pi * (p - BAND_START[b]) / BAND_COUNTS[b]
    return np.array([math.sin(az) * math.cos(alt), math.cos(az) * math.cos(alt), math.sin(alt)])


def patch_solid_angle(p: int) -> float:
    """Solid angle of patch ``p`` (sr): (2π/n)(sin a₁ − sin a₀)."""
    b = _band_of(p)
    a0, a1 = (math.radians(x) for x in band_edges_deg(b))
    return 2 * math.pi / BAND_COUNTS[b] * (math.sin(a1) - math.sin(a0))


def patch_projected_solid_angle(p: int) -> float:
    """∫cosθ dω over patch ``p`` (sr), a horizontal receiver's view of it: (π/n)(sin²a₁ − sin²a₀)."""
    b = _band_of(p)
    a0, a1 = (math.radians(x) for x in band_edges_deg(b))
    return math.pi / BAND_COUNTS[b] * (math.sin(a1) ** 2 - math.sin(a0) ** 2)


def general_sky_luminance(sky_type: int, d: np.ndarray, sun: np.ndarray | None) -> np.ndarray:
    """Luminance relative to the zenith's, L/L_z, of CIE general sky ``sky_type`` (1…15), shape (...).

    ``d`` (..., 3) unit directions above the horizon; ``sun`` (3,) unit
    direction toward the sun (not needed by types 1, 3, 5, whose indicatrix is 1)."""
    a, b, c, dd, e = CIE_TYPES[int(sky_type)]
    d = np.asarray(d, np.float64)
    cos_z = np.clip(d[..., 2], 1e-9, 1.0)
    phi = 1.0 + a * np.exp(b / cos_z)
    phi0 = 1.0 + a * math.exp(b)
    if c == 0.0 and e == 0.0:
        return phi / phi0
    if sun is None:
        raise ValueError(f"CIE sky type {sky_type} depends on the sun's position")
    s = np.asarray(sun, np.float64) / np.linalg.norm(sun)
    chi = np.arccos(np.clip(d @ s, -1.0, 1.0))
    zs = math.acos(min(max(float(s[2]), -1.0), 1.0))

    def f(x):
        return 1.0 + c * (np.exp(dd * x) - math.exp(dd * math.pi / 2)) + e * np.cos(x) ** 2

    return f(chi) * phi / (f(zs) * phi0)


def overcast_luminance(d: np.ndarray) -> np.ndarray:
    """Traditional CIE overcast sky (Moon and Spencer), L/L_z = (1 + 2 sin γ)/3 at altitude γ, shape (...)."""
    return (1.0 + 2.0 * np.clip(np.asarray(d, np.float64)[..., 2], 0.0, 1.0)) / 3.0


def patch_means(luminance, n_sub: int = 12) -> np.ndarray:
    """Mean of a sky luminance function over each of the 145 patches, shape (145,).

    ``luminance(d)`` maps unit directions (..., 3) to luminance (...). Each
    patch is cut into n_sub × n_sub cells equal in solid angle (uniform in
    sin(altitude) and azimuth) and the function is read at their centres."""
    out = np.zeros(N_PATCHES)
    u = (np.arange(n_sub) + 0.5) / n_sub
    for p in range(N_PATCHES):
        b = _band_of(p)
        a0, a1 = (math.radians(x) for x in band_edges_deg(b))
        n = BAND_COUNTS[b]
        s = math.sin(a0) + u * (math.sin(a1) - math.sin(a0))
        w = 2 * math.pi / n
        az = w * (p - BAND_START[b]) + (u - 0.5) * w
        ss, aa = np.meshgrid(s, az, indexing="ij")
        cc = np.sqrt(np.maximum(1.0 - ss**2, 0.0))
        dirs = np.stack([np.sin(aa) * cc, np.cos(aa) * cc, ss], axis=-1)
        out[p] = float(np.mean(luminance(dirs)))
    return out


def sky_weights(model: str | int, sun: np.ndarray | None, scale_to_horizontal: float = math.pi) -> np.ndarray:
    """Patch levels d_p = L_p / L_dome of a sky, shape (145,).

    Parameters
    ----------
    model : "uniform", "overcast" or int 1…15
        The uniform sky, the traditional CIE overcast sky, or a CIE general sky type.
    sun : ndarray, shape (3,), or None
        Direction toward the sun (types that depend on it).
    scale_to_horizontal : float
        The sky's unobstructed horizontal illuminance over L_dome (sr):
        Σ_p d_p ∫_p cosθ dω. π (the default) gives the sky as much
        horizontal illuminance as the authored uniform dome.
    """
    if model == "uniform":
        rel = np.ones(N_PATCHES)
    elif model == "overcast":
        rel = patch_means(overcast_luminance)
    else:
        rel = patch_means(lambda d: general_sky_luminance(int(model), d, sun))
    proj = np.array([patch_projected_solid_angle(p) for p in range(N_PATCHES)])
    return rel * (scale_to_horizontal / float(np.dot(rel, proj)))
