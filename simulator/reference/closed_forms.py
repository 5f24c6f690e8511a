"""Closed-form irradiance, solid angles and published test cases.

These are the reference answers the test-suite (and ``probesim verify``)
compare the Monte Carlo engine against, so they are written in plain numpy,
share no code with the engine, and are exact up to floating-point rounding.

Conventions follow :mod:`simulator.scene.model`: metres, right-handed, Z up.
A receiver is a point ``p`` with unit normal ``n`` (normals are normalised
here anyway); it reads the irradiance arriving on the side ``n`` points to.
A :class:`~simulator.scene.model.LightKind` ``RECT`` or ``DISK`` light emits
one-sided along its local −Z.

Every formula is linear in the emitter's radiance (W m⁻² sr⁻¹) or intensity
(W/sr) and otherwise purely geometric, so the same functions give
illuminance in lux from luminance in cd/m² or luminous intensity in cd.

Functions broadcast over leading axes where that is natural: positions and
normals are arrays of shape ``(..., 3)``, scalars may be arrays. Results are
numpy arrays, or numpy scalars for scalar input.

References
----------
.. [1] J. H. Lambert, *Photometria*, 1760 (the contour integral for the
       irradiance from a uniform polygon); in modern form J. Arvo, "Applications
       of irradiance tensors to the simulation of non-Lambertian phenomena",
       SIGGRAPH 1995.
.. [2] J. R. Howell, M. P. Mengüç, K. Daun, R. Siegel, *Thermal Radiation Heat
       Transfer*, and J. R. Howell, *A Catalog of Radiation Heat Transfer
       Configuration Factors* (thermalradiation.net), section B: differential
       element to finite areas (sphere, tilted element; parallel disk, offset;
       parallel rectangle, normal through a corner).
.. [3] A. Van Oosterom, J. Strackee, "The solid angle of a plane triangle",
       IEEE Trans. Biomed. Eng. BME-30(2), 125–126, 1983.
.. [4] I. E. Sutherland, G. W. Hodgman, "Reentrant polygon clipping",
       Comm. ACM 17(1), 32–42, 1974.
.. [5] CIE 171:2006, *Test cases to assess the accuracy of lighting computer
       programs*, sections 5.2 and 5.8.
.. [6] J. R. Howell, M. P. Mengüç, K. Daun, R. Siegel, *Thermal Radiation
       Heat Transfer*, 7th ed., CRC Press, 2021 (configuration factors).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = [
    "cie_overcast_luminance",
    "cie_overcast_row_means",
    "cie_overcast_illuminance",
    "latlong_rows_illuminance",
    "point_irradiance",
    "sphere_irradiance",
    "polygon_irradiance",
    "rect_light_vertices",
    "disk_irradiance_on_axis",
    "disk_irradiance_parallel",
    "disk_factor_parallel",
    "rect_corner_factor",
    "rect_irradiance_parallel",
    "rect_solid_angle_centred",
    "polygon_solid_angle",
    "point_flux_through_polygon",
    "dome_irradiance",
    "cylindrical_point_irradiance",
    "semicylindrical_point_irradiance",
    "dome_cylindrical_irradiance",
    "lambertian_radiance",
    "cos_power_dome_reading",
    "half_power_exponent",
    "cos_power_f2",
    "furnace_radiance",
    "furnace_irradiance",
    "integrating_sphere_irradiance",
    "integrating_sphere_first_bounce",
    "integrating_sphere_reflected",
    "CIE171PointSourceGrid",
    "cie171_point_source_grid",
    "cie171_indirect_illuminance",
    "CIE171_5_2_PUBLISHED_LX",
    "CIE171_5_8_TABLE_LX",
    "CIE171_5_8_FLUX_LM",
    "CIE171_5_8_TOTAL_AREA_M2",
    "CIE171_5_8_DIRECT_MEAN_LX",
]


# --------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------

def _vec(a, name: str) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    if a.shape[-1:] != (3,):
        raise ValueError(f"{name}: expected shape (..., 3), got {a.shape}")
    return a


def _unit(a, name: str) -> np.ndarray:
    a = _vec(a, name)
    norm = np.linalg.norm(a, axis=-1, keepdims=True)
    if np.any(norm == 0.0) or not np.all(np.isfinite(norm)):
        raise ValueError(f"{name}: zero-length or non-finite vector")
    return a / norm


def _out(a):
    """ndarray for array results, numpy scalar for 0-d ones."""
    return np.asarray(a, dtype=float)[()]


def _vertices(vertices) -> np.ndarray:
    v = np.asarray(vertices, dtype=float)
    if v.ndim != 2 or v.shape[1] != 3 or v.shape[0] < 3:
        raise ValueError(f"vertices: expected shape (V, 3) with V >= 3, got {v.shape}")
    return v


# --------------------------------------------------------------------------
# point and sphere
# --------------------------------------------------------------------------

def point_irradiance(intensity, source, p, n):
    """Irradiance from an isotropic-in-the-direction point source.

    Parameters
    ----------
    intensity : float or array_like
        Intensity of the source toward the receiver, W/sr (or cd). Broadcast
        against the receivers.
    source : array_like, shape (..., 3)
        Source position, metres.
    p : array_like, shape (..., 3)
        Receiver position, metres.
    n : array_like, shape (..., 3)
        Receiver normal (normalised here).

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx), shape broadcast from the inputs.

    Raises
    ------
    ValueError
        If a receiver coincides with the source.

    Notes
    -----
    Inverse-square cosine law: with ``d`` the distance and ``ξ`` the angle
    between ``n`` and the direction to the source,

        E = I·cos ξ / d²,   and E = 0 where cos ξ ≤ 0.

    For a direction-dependent source pass ``I`` already evaluated toward the
    receiver.

    References
    ----------
    .. [1] docs/REFERENCES.md §Point source.
    """
    to_src = _vec(source, "source") - _vec(p, "p")
    n = _unit(n, "n")
    d2 = np.sum(to_src * to_src, axis=-1)
    if np.any(d2 == 0.0):
        raise ValueError("point_irradiance: receiver coincides with the source")
    cos_xi = np.sum(to_src * n, axis=-1) / np.sqrt(d2)
    return _out(np.asarray(intensity, float) * np.maximum(cos_xi, 0.0) / d2)


def sphere_irradiance(radiance, centre, radius, p, n):
    """Irradiance from a uniform spherical emitter, in every horizon regime.

    Parameters
    ----------
    radiance : float or array_like
        Radiance of the sphere's surface, W m⁻² sr⁻¹ (or cd/m²).
    centre : array_like, shape (..., 3)
        Sphere centre, metres.
    radius : float or array_like
        Sphere radius ``r``, metres (> 0).
    p : array_like, shape (..., 3)
        Receiver position, metres, outside the sphere (on its surface is
        allowed).
    n : array_like, shape (..., 3)
        Receiver normal (normalised here).

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx).

    Raises
    ------
    ValueError
        If a receiver is inside the sphere or the radius is not positive.

    Notes
    -----
    With ``d`` the distance to the centre, ``sin σ = r/d`` and ``θ`` the angle
    between ``n`` and the direction to the centre:

    * sphere wholly above the horizon (cos θ ≥ sin σ):
      E = π·L·sin²σ·cos θ — exactly the field of a point source of intensity
      π·r²·L at the centre;
    * straddling the horizon (|cos θ| < sin σ): with x = √(1/sin²σ − 1) and
      y = −x·cot θ,
      E/L = (cos θ·acos y − x·sin θ·√(1−y²))·sin²σ + atan(sin θ·√(1−y²)/x);
    * wholly below (cos θ ≤ −sin σ): E = 0.

    The three pieces join continuously (y = −1 at cos θ = sin σ, y = +1 at
    cos θ = −sin σ). On the surface (x = 0) the straddling form becomes
    π·L·(1 + cos θ)/2.

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors*, "differential planar
           element to sphere; element tilted, part of the sphere below the
           element's plane" (E = π·L·F).
    .. [2] docs/REFERENCES.md §Uniform sphere.
    """
    radius = np.asarray(radius, float)
    if np.any(radius <= 0.0):
        raise ValueError("sphere_irradiance: radius must be > 0")
    to_c = _vec(centre, "centre") - _vec(p, "p")
    n = _unit(n, "n")
    d = np.linalg.norm(to_c, axis=-1)
    if np.any(d < radius * (1.0 - 1e-12)):
        raise ValueError("sphere_irradiance: receiver is inside the sphere")
    with np.errstate(divide="ignore", invalid="ignore"):
        sin_s = np.minimum(radius / d, 1.0)
        sin2 = sin_s * sin_s
        cos_t = np.clip(np.sum(to_c * n, axis=-1) / d, -1.0, 1.0)
        sin_t = np.sqrt(np.maximum(1.0 - cos_t * cos_t, 0.0))
        above = cos_t >= sin_s
        below = cos_t <= -sin_s
        strad = ~(above | below)
        # straddling: sin θ > cos σ ≥ 0 there, so the divisions are safe
        x = np.sqrt(np.maximum(1.0 / sin2 - 1.0, 0.0))
        st = np.where(strad, sin_t, 1.0)
        y = np.clip(-x * cos_t / st, -1.0, 1.0)
        sy = np.sqrt(1.0 - y * y)
        e_strad = (cos_t * np.arccos(y) - x * st * sy) * sin2 + np.arctan2(st * sy, x)
        e = np.where(above, np.pi * sin2 * cos_t, np.where(strad, e_strad, 0.0))
    return _out(np.asarray(radiance, float) * e)


# --------------------------------------------------------------------------
# polygons
# --------------------------------------------------------------------------

def _clip_to_hemisphere(v: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Sutherland–Hodgman: keep the part of polygon ``v`` (relative to the
    receiver) with ``v·n ≥ 0``. Returns shape (k, 3), possibly k < 3."""
    s = v @ n
    if np.all(s <= 0.0):  # below, or edge-on in the horizon plane: cos θ = 0
        return v[:0]
    if np.all(s >= 0.0):
        return v
    out = []
    k = len(v)
    for i in range(k):
        a, b = v[i - 1], v[i]
        sa, sb = s[i - 1], s[i]
        if (sa >= 0.0) != (sb >= 0.0):
            q = a + (b - a) * (sa / (sa - sb))
            out.append(q - (q @ n) * n)  # exactly on the horizon plane
        if sb >= 0.0:
            out.append(b)
    return np.asarray(out).reshape(-1, 3)


def _lambert_contour(v: np.ndarray, n: np.ndarray) -> float:
    """Σ_i γ_i · n·û_i over the edges of polygon ``v`` (receiver at 0); the
    cosine-weighted solid angle is |Σ|/2."""
    r = np.linalg.norm(v, axis=1)
    keep = r > 0.0
    if not np.all(keep):  # a vertex at the receiver: drop it (zero-length arcs)
        v, r = v[keep], r[keep]
        if len(v) < 3:
            return 0.0
    u = v / r[:, None]
    w = np.roll(u, -1, axis=0)
    c = np.cross(u, w)
    sin_g = np.linalg.norm(c, axis=1)
    gamma = np.arctan2(sin_g, np.sum(u * w, axis=1))
    with np.errstate(divide="ignore", invalid="ignore"):
        proj = np.where(sin_g > 0.0, (c @ n) / sin_g, 0.0)
    return float(np.sum(gamma * proj))


def polygon_irradiance(radiance, vertices, p, n, one_sided_normal=None):
    """Irradiance from a uniform planar polygon (Lambert's contour formula).

    Parameters
    ----------
    radiance : float or array_like
        Radiance of the polygon, W m⁻² sr⁻¹ (or cd/m²); broadcast against the
        receivers.
    vertices : array_like, shape (V, 3)
        Vertices of a simple planar polygon (convex or not), in order,
        metres.
    p : array_like, shape (..., 3)
        Receiver positions, metres.
    n : array_like, shape (..., 3)
        Receiver normals (normalised here); broadcast against ``p``.
    one_sided_normal : array_like, shape (3,), optional
        If given, the polygon emits only into the half-space this vector
        (a normal of the polygon's plane) points into; a receiver on the
        other side, or in the plane, reads 0. For a RectLight wound by
        :func:`rect_light_vertices` pass ``-cross(x_axis, y_axis)``.
        ``None`` (default): the polygon emits from both faces.

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx), of the broadcast shape of ``p[..., 0]`` and
        ``n[..., 0]``.

    Notes
    -----
    The polygon is first clipped to the receiver's upper hemisphere — the
    half-space ``(x − p)·n ≥ 0`` — with the Sutherland–Hodgman algorithm.
    Then, with v_i the unit vectors from the receiver to the clipped
    vertices, γ_i = ∠(v_i, v_{i+1}) and û_i = normalize(v_i × v_{i+1}),

        E = (L/2)·|Σ_i γ_i · n·û_i|.

    This is Stokes' theorem applied to ∫ n·ω dω over the polygon's spherical
    image, which is why the clipping is needed: the integrand must be
    cos θ ≥ 0 everywhere. Edges lying in the horizon plane count fully
    (û = ±n there). Receivers in the polygon's own plane are degenerate
    (the polygon is seen edge-on) and read 0 when outside it.

    References
    ----------
    .. [1] Lambert, *Photometria* (1760); Arvo (SIGGRAPH 1995), eq. for the
           irradiance from a polygonal luminaire.
    .. [2] Sutherland & Hodgman, Comm. ACM 17(1), 1974.
    .. [3] docs/REFERENCES.md §Lambert's polygon formula.
    """
    v = _vertices(vertices)
    p = _vec(p, "p")
    n = _unit(n, "n")
    shape = np.broadcast_shapes(p.shape, n.shape)
    pb = np.broadcast_to(p, shape).reshape(-1, 3)
    nb = np.broadcast_to(n, shape).reshape(-1, 3)
    front = np.ones(len(pb), bool)
    if one_sided_normal is not None:
        m = _unit(one_sided_normal, "one_sided_normal")
        if m.shape != (3,):
            raise ValueError("one_sided_normal: expected shape (3,)")
        front = (pb - v.mean(axis=0)) @ m > 0.0
    e = np.zeros(len(pb))
    for i in range(len(pb)):
        if not front[i]:
            continue
        vc = _clip_to_hemisphere(v - pb[i], nb[i])
        if len(vc) >= 3:
            e[i] = 0.5 * abs(_lambert_contour(vc, nb[i]))
    e = e.reshape(shape[:-1])
    return _out(np.asarray(radiance, float) * e)


def rect_light_vertices(centre, x_axis, y_axis, width, height):
    """Corners of a rectangle (a RectLight) in world space.

    Parameters
    ----------
    centre : array_like, shape (3,)
        Rectangle centre, metres.
    x_axis, y_axis : array_like, shape (3,)
        Directions of the width and height sides (normalised here; they should
        be orthogonal, e.g. columns 0 and 1 of ``Light.frame``).
    width, height : float
        Side lengths along ``x_axis`` and ``y_axis``, metres.

    Returns
    -------
    vertices : ndarray, shape (4, 3)
        Corners at local (−w/2, −h/2), (+w/2, −h/2), (+w/2, +h/2),
        (−w/2, +h/2): counter-clockwise about ``z = x_axis × y_axis``.

    Notes
    -----
    A UsdLux RectLight emits along its local −Z, i.e. toward
    ``-cross(x_axis, y_axis)``; pass that as ``one_sided_normal`` to
    :func:`polygon_irradiance`. With this winding,
    :func:`polygon_solid_angle` with ``signed=True`` is positive for receivers
    on the lit side.

    References
    ----------
    .. [1] OpenUSD UsdLux ``RectLight`` schema (emission along local −Z);
           :class:`simulator.scene.model.LightKind`.
    """
    c = np.asarray(centre, float)
    x = _unit(x_axis, "x_axis")
    y = _unit(y_axis, "y_axis")
    hw, hh = 0.5 * float(width), 0.5 * float(height)
    return np.stack([c - hw * x - hh * y, c + hw * x - hh * y, c + hw * x + hh * y, c - hw * x + hh * y])


# --------------------------------------------------------------------------
# disks
# --------------------------------------------------------------------------

def disk_irradiance_on_axis(radiance, R, h, tilt=0.0):
    """Irradiance on the axis of a uniform disk, receiver tilted from the axis.

    Parameters
    ----------
    radiance : float or array_like
        Disk radiance, W m⁻² sr⁻¹ (or cd/m²).
    R : float or array_like
        Disk radius, metres.
    h : float or array_like
        Distance from the disk centre to the receiver along the axis, metres
        (> 0).
    tilt : float or array_like, optional
        Angle ω between the receiver normal and the direction to the disk
        centre, radians. Default 0 (facing the disk).

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx).

    Raises
    ------
    ValueError
        If part of the disk is below the receiver's horizon, i.e.
        ω > π/2 − atan(R/h), where the formula no longer holds.

    Notes
    -----
    E = π·L·R²/(R² + h²)·cos ω. The disk's vector irradiance on its axis
    points along the axis with magnitude π·L·sin²α, tan α = R/h; the
    projection onto n is exact while every direction to the disk has
    cos θ ≥ 0, i.e. ω + α ≤ π/2.

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors*, "differential planar
           element to coaxial disk, element tilted".
    .. [2] docs/REFERENCES.md §Uniform disk.
    """
    R = np.asarray(R, float)
    h = np.asarray(h, float)
    tilt = np.asarray(tilt, float)
    if np.any(h <= 0.0) or np.any(R < 0.0):
        raise ValueError("disk_irradiance_on_axis: need h > 0 and R >= 0")
    limit = 0.5 * np.pi - np.arctan2(R, h)
    if np.any(np.abs(tilt) > limit + 1e-12):
        raise ValueError(
            "disk_irradiance_on_axis: part of the disk is below the receiver's horizon "
            "(|tilt| > pi/2 - atan(R/h)); use polygon_irradiance on a fine polygon instead"
        )
    return _out(np.asarray(radiance, float) * np.pi * R * R / (R * R + h * h) * np.cos(tilt))


def disk_factor_parallel(R, h, a):
    """Configuration factor from a small element to a parallel disk, offset.

    Parameters
    ----------
    R : float or array_like
        Disk radius, metres.
    h : float or array_like
        Distance between the receiver's plane and the disk's plane, metres
        (> 0).
    a : float or array_like
        Distance of the receiver from the disk's axis, metres (any value ≥ 0;
        inside or outside the disk's footprint).

    Returns
    -------
    F : ndarray or float
        Configuration factor (dimensionless, 0 ≤ F < 1).

    Notes
    -----
    With H = a/h and Rr = R/h,

        F = ½·[1 − (1 + H² − Rr²) / √((1 + H² + Rr²)² − 4·Rr²·H²)].

    At a = 0 this is R²/(R² + h²), the on-axis value.

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors*, "differential planar
           element to parallel disk, element offset from the axis".
    .. [2] docs/REFERENCES.md §Parallel disk.
    """
    R = np.asarray(R, float)
    h = np.asarray(h, float)
    a = np.abs(np.asarray(a, float))
    if np.any(h <= 0.0) or np.any(R < 0.0):
        raise ValueError("disk_factor_parallel: need h > 0 and R >= 0")
    H2 = (a / h) ** 2
    Rr2 = (R / h) ** 2
    return _out(0.5 * (1.0 - (1.0 + H2 - Rr2) / np.sqrt((1.0 + H2 + Rr2) ** 2 - 4.0 * Rr2 * H2)))


def disk_irradiance_parallel(radiance, R, h, a):
    """Irradiance from a uniform disk on a parallel receiver offset ``a``.

    Parameters
    ----------
    radiance : float or array_like
        Disk radiance, W m⁻² sr⁻¹ (or cd/m²).
    R, h, a : float or array_like
        Disk radius, plane separation (> 0) and offset from the axis, metres.
        The receiver faces the disk.

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx): E = π·L·F with F from
        :func:`disk_factor_parallel`.

    Notes
    -----
    A parallel receiver never has any part of the disk below its horizon,
    so the formula holds for every offset.

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors*, "differential planar
           element to parallel disk, element offset from the axis".
    """
    return _out(np.asarray(radiance, float) * np.pi * disk_factor_parallel(R, h, a))


# --------------------------------------------------------------------------
# rectangles
# --------------------------------------------------------------------------

def rect_corner_factor(W, H, S):
    """Configuration factor to a parallel rectangle from above one corner.

    Parameters
    ----------
    W, H : float or array_like
        Rectangle side lengths, metres (≥ 0).
    S : float or array_like
        Distance from the receiver to the rectangle's plane, metres (> 0).
        The receiver lies on the normal through one corner and faces the
        rectangle.

    Returns
    -------
    F : ndarray or float
        Configuration factor (dimensionless, 0 ≤ F < 1/4).

    Notes
    -----
    With X = W/S, Y = H/S,

        F = (1/2π)·[X/√(1+X²)·atan(Y/√(1+X²)) + Y/√(1+Y²)·atan(X/√(1+Y²))].

    F → 1/4 as W, H → ∞ (a quarter of the plane).

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors*, "differential planar
           element to parallel rectangle; normal to the element passes
           through a corner of the rectangle".
    .. [2] docs/REFERENCES.md §Parallel rectangle.
    """
    W = np.asarray(W, float)
    H = np.asarray(H, float)
    S = np.asarray(S, float)
    if np.any(S <= 0.0) or np.any(W < 0.0) or np.any(H < 0.0):
        raise ValueError("rect_corner_factor: need S > 0 and W, H >= 0")
    X, Y = W / S, H / S
    a, b = np.sqrt(1.0 + X * X), np.sqrt(1.0 + Y * Y)
    return _out((X / a * np.arctan(Y / a) + Y / b * np.arctan(X / b)) / (2.0 * np.pi))


def _signed_corner(x, y, S):
    return np.sign(x) * np.sign(y) * rect_corner_factor(np.abs(x), np.abs(y), S)


def rect_irradiance_parallel(radiance, x0, x1, y0, y1, S):
    """Irradiance from a uniform rectangle parallel to the receiver, anywhere.

    Parameters
    ----------
    radiance : float or array_like
        Rectangle radiance, W m⁻² sr⁻¹ (or cd/m²).
    x0, x1, y0, y1 : float or array_like
        The rectangle spans [x0, x1] × [y0, y1] (x0 ≤ x1, y0 ≤ y1) in the
        plane z = S, metres, in a frame with the receiver at the origin
        facing +z. The receiver may lie outside the rectangle's footprint.
    S : float or array_like
        Height of the rectangle above the receiver, metres (> 0).

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx).

    Notes
    -----
    With F_c the corner factor (:func:`rect_corner_factor`) extended as an
    odd function in each side, G(x, y) = sgn x · sgn y · F_c(|x|, |y|, S),
    the rectangle's factor is the inclusion–exclusion sum of the corner
    rectangles [0, x]×[0, y]:

        F = G(x1, y1) − G(x0, y1) − G(x1, y0) + G(x0, y0),   E = π·L·F.

    Corner rectangles on the far side of the origin come in with a minus
    sign, which handles receivers outside the footprint.

    References
    ----------
    .. [1] Howell, *Catalog of Configuration Factors* (factor algebra for
           parallel rectangles built from corner cases).
    .. [2] docs/REFERENCES.md §Parallel rectangle.
    """
    x0, x1, y0, y1 = (np.asarray(t, float) for t in (x0, x1, y0, y1))
    if np.any(x1 < x0) or np.any(y1 < y0):
        raise ValueError("rect_irradiance_parallel: need x0 <= x1 and y0 <= y1")
    F = _signed_corner(x1, y1, S) - _signed_corner(x0, y1, S) - _signed_corner(x1, y0, S) + _signed_corner(x0, y0, S)
    return _out(np.asarray(radiance, float) * np.pi * F)


# --------------------------------------------------------------------------
# solid angles
# --------------------------------------------------------------------------

def rect_solid_angle_centred(a, b, d):
    """Solid angle of an a×b rectangle seen from a point on its central normal.

    Parameters
    ----------
    a, b : float or array_like
        Side lengths, metres.
    d : float or array_like
        Distance from the point to the rectangle's centre, metres (> 0).

    Returns
    -------
    omega : ndarray or float
        Solid angle, sr.

    Notes
    -----
    Ω = 4·asin(a·b / √((a² + 4d²)(b² + 4d²))).

    References
    ----------
    .. [1] docs/REFERENCES.md §Solid angle of a rectangle.
    """
    a, b, d = (np.asarray(t, float) for t in (a, b, d))
    if np.any(d <= 0.0):
        raise ValueError("rect_solid_angle_centred: need d > 0")
    return _out(4.0 * np.arcsin(a * b / np.sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d))))


def polygon_solid_angle(vertices, p, signed=False):
    """Solid angle of a planar polygon seen from one or more points.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        Vertices of a simple planar polygon (convex or not), in order, metres.
    p : array_like, shape (..., 3)
        Viewpoints, metres.
    signed : bool, optional
        If True, return the signed solid angle: positive when ``p`` is on the
        side opposite the winding normal ``(v1 − v0) × (v2 − v0)`` (the lit
        side of a RectLight from :func:`rect_light_vertices`). Default False:
        the magnitude.

    Returns
    -------
    omega : ndarray or float
        Solid angle, sr, shape ``p.shape[:-1]``.

    Notes
    -----
    The polygon is fanned into triangles (v0, v_i, v_{i+1}); each triangle's
    signed solid angle, with r_k = v_k − p, is (Van Oosterom & Strackee)

        tan(Ω/2) = r0·(r1 × r2) /
                   (|r0||r1||r2| + (r0·r1)|r2| + (r0·r2)|r1| + (r1·r2)|r0|),

    evaluated with ``atan2`` so that |Ω| up to 2π is right. Signed triangle
    solid angles are additive like signed areas, so the fan is exact for
    non-convex polygons too.

    References
    ----------
    .. [1] Van Oosterom & Strackee, IEEE Trans. Biomed. Eng. BME-30, 1983.
    """
    v = _vertices(vertices)
    p = _vec(p, "p")
    r = v - p[..., None, :]  # (..., V, 3)
    r0 = r[..., :1, :]
    r1 = r[..., 1:-1, :]
    r2 = r[..., 2:, :]
    l0 = np.linalg.norm(r0, axis=-1)
    l1 = np.linalg.norm(r1, axis=-1)
    l2 = np.linalg.norm(r2, axis=-1)
    num = np.sum(r0 * np.cross(r1, r2), axis=-1)
    den = (
        l0 * l1 * l2
        + np.sum(r0 * r1, axis=-1) * l2
        + np.sum(r0 * r2, axis=-1) * l1
        + np.sum(r1 * r2, axis=-1) * l0
    )
    omega = np.sum(2.0 * np.arctan2(num, den), axis=-1)
    return _out(omega if signed else np.abs(omega))


def point_flux_through_polygon(intensity, source, vertices):
    """Flux from an isotropic point source through a polygon.

    Parameters
    ----------
    intensity : float or array_like
        Source intensity, W/sr (or cd).
    source : array_like, shape (..., 3)
        Source position, metres.
    vertices : array_like, shape (V, 3)
        Planar polygon, metres.

    Returns
    -------
    flux : ndarray or float
        Flux, W (or lm): Φ = I·Ω, Ω from :func:`polygon_solid_angle`.

    Notes
    -----
    Intensity is flux per solid angle, so for an isotropic source the flux
    into any solid angle is I·Ω (equivalently ∫_A I·cos θ/d² dA).

    References
    ----------
    .. [1] docs/REFERENCES.md §Solid angle of a rectangle.
    """
    return _out(np.asarray(intensity, float) * polygon_solid_angle(vertices, source))


# --------------------------------------------------------------------------
# environments and enclosures
# --------------------------------------------------------------------------

def dome_irradiance(radiance, tilt):
    """Irradiance from a uniform sky over a black ground.

    Parameters
    ----------
    radiance : float or array_like
        Sky radiance, W m⁻² sr⁻¹ (or cd/m²).
    tilt : float or array_like
        Angle β between the receiver normal and the zenith (+Z), radians,
        in [0, π].

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx): π·L·(1 + cos β)/2.

    Notes
    -----
    The sky is the upper hemisphere; the ground (lower hemisphere) is black.
    The receiver's view of the sky is a lune bounded by two great half
    circles; integrating cos θ over it gives π·(1 + cos β)/2. At β = 0 this
    is π·L, the reading of any receiver that sees only radiance L; a
    receiver facing straight down reads 0.

    References
    ----------
    .. [1] docs/REFERENCES.md §Uniform environment.
    """
    return _out(np.asarray(radiance, float) * np.pi * 0.5 * (1.0 + np.cos(np.asarray(tilt, float))))


def cos_power_dome_reading(radiance, n):
    """What a head of angular response r = cosⁿ θ reads under a uniform sky filling its hemisphere.

    Parameters
    ----------
    radiance : float or array_like
        Sky radiance, W m⁻² sr⁻¹ (or cd/m²).
    n : float or array_like
        The exponent, > 0 (1: an ideal cosine head).

    Returns
    -------
    ndarray or float
        ∫ L cosⁿθ dω = 2π·L/(n + 1): L·π at n = 1, the irradiance.

    Notes
    -----
    With dω = sinθ dθ dφ over the hemisphere, ∫₀^{2π}∫₀^{π/2} cosⁿθ sinθ dθ dφ
    = 2π·[−cos^{n+1}θ/(n + 1)]₀^{π/2} = 2π/(n + 1).

    References
    ----------
    .. [1] docs/REFERENCES.md §Sensor models.
    """
    return _out(2.0 * np.pi * np.asarray(radiance, float) / (np.asarray(n, float) + 1.0))


def half_power_exponent(half_angle_deg):
    """The n of cosⁿ θ whose response is ½ at ``half_angle_deg``.

    Parameters
    ----------
    half_angle_deg : float or array_like
        The half-power angle θ½, degrees, 0 < θ½ < 90.

    Returns
    -------
    ndarray or float
        n = ln ½ / ln cos θ½ (60° → 1, the cosine).

    Notes
    -----
    cosⁿ θ½ = ½ solved for n.

    References
    ----------
    .. [1] docs/REFERENCES.md §Sensor models.
    """
    return _out(np.log(0.5) / np.log(np.cos(np.radians(np.asarray(half_angle_deg, float)))))


def cos_power_f2(n, limit_deg: float = 85.0):
    """ISO/CIE 19476's directional response index f2 of a head r = cosⁿ θ, in closed form.

    Parameters
    ----------
    n : float or array_like
        The exponent, > 0.
    limit_deg : float
        The largest angle of incidence integrated, degrees (the standard's 85°).

    Returns
    -------
    ndarray or float
        f2, a fraction (0 for the cosine).

    Notes
    -----
    f2 = ∫₀^{ε_max} |cos^{n−1} ε − 1| sin 2ε dε; with u = cos ε, sin 2ε dε = −2u du, so for n ≥ 1
    f2 = ∫_c^1 2u (1 − u^{n−1}) du = 1 − c² − 2(1 − c^{n+1})/(n + 1), c = cos ε_max, and for n < 1
    (a head reading high at a slant) its negative.

    References
    ----------
    .. [1] docs/REFERENCES.md §Sensor models.
    """
    n = np.asarray(n, float)
    c = np.cos(np.radians(limit_deg))
    v = 1.0 - c * c - 2.0 * (1.0 - c ** (n + 1.0)) / (n + 1.0)
    return _out(np.abs(v))


def _across(source, p, axis):
    """(d², unit direction across the axis toward the source, sinθ) for a point source."""
    w = np.asarray(source, float) - np.asarray(p, float)
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a, axis=-1, keepdims=True)
    d2 = np.sum(w * w, axis=-1)
    if np.any(d2 <= 0.0):
        raise ValueError("cylindrical: receiver coincides with the source")
    across = w - np.sum(w * a, axis=-1, keepdims=True) * a
    la = np.linalg.norm(across, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        u = np.where(la[..., None] > 0, across / np.where(la > 0, la, 1.0)[..., None], 0.0)
    return d2, u, la / np.sqrt(d2)


def cylindrical_point_irradiance(intensity, source, p, axis=(0.0, 0.0, 1.0)):
    """Cylindrical irradiance (illuminance) from a point source: the mean over a small cylinder's curved surface.

    Parameters
    ----------
    intensity : float or array_like
        Intensity toward the receiver, W/sr (or cd).
    source, p : array_like, shape (..., 3)
        Source and receiver positions, metres.
    axis : array_like, shape (3,)
        The cylinder's axis (normalised here); EN 12464-1's E_z: vertical.

    Returns
    -------
    E : ndarray or float
        E_z = I·sinθ/(π·d²), W/m² (or lx); θ between the axis and the direction to the source.

    Notes
    -----
    The surface's outward normals n(φ) = cos φ·u + sin φ·v (u, v across the
    axis) see the source with cos ψ = sinθ·cos(φ − φ_s); the mean of
    E(n) = I·max(0, cos ψ)/d² over φ is (I/d²)·sinθ·(1/2π)∫max(0, cos φ)dφ
    = I·sinθ/(π·d²). For any radiance field the same averaging gives
    E_z = (1/π)∫L(ω)·sinθ dω over the sphere.

    References
    ----------
    .. [1] docs/REFERENCES.md §Cylindrical illuminance.
    """
    d2, _, sin_t = _across(source, p, axis)
    return _out(np.asarray(intensity, float) * sin_t / (np.pi * d2))


def semicylindrical_point_irradiance(intensity, source, p, facing, axis=(0.0, 0.0, 1.0)):
    """Semi-cylindrical irradiance from a point source: the mean over the half cylinder facing ``facing``.

    Parameters
    ----------
    intensity : float or array_like
        Intensity toward the receiver, W/sr (or cd).
    source, p : array_like, shape (..., 3)
        Source and receiver positions, metres.
    facing : array_like, shape (3,)
        Where the half cylinder faces (made orthogonal to the axis here).
    axis : array_like, shape (3,)
        The cylinder's axis.

    Returns
    -------
    E : ndarray or float
        E_sc = I·sinθ·(1 + cos φ)/(π·d²), W/m² (or lx); φ the azimuth between
        the facing and the source across the axis.

    Notes
    -----
    Over the half's normals φ_n ∈ [−π/2, π/2] about the facing,
    (1/π)∫max(0, cos(φ − φ_n))dφ_n = (1 + cos φ)/π for |φ| ≤ π, so
    E_sc = (1/π)∫L(ω)·sinθ·(1 + cos φ_ω) dω over the sphere; a uniform field
    L gives πL, as a plane receiver would.

    References
    ----------
    .. [1] docs/REFERENCES.md §Cylindrical illuminance.
    """
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    f = np.asarray(facing, float)
    f = f - np.dot(f, a) * a
    f = f / np.linalg.norm(f)
    d2, u, sin_t = _across(source, p, a)
    cos_phi = np.sum(u * f, axis=-1)
    return _out(np.asarray(intensity, float) * sin_t * (1.0 + cos_phi) / (np.pi * d2))


def dome_cylindrical_irradiance(radiance):
    """Cylindrical (and semi-cylindrical) irradiance under a uniform sky over a black ground, vertical axis.

    Parameters
    ----------
    radiance : float or array_like
        Sky radiance, W m⁻² sr⁻¹ (or cd/m²).

    Returns
    -------
    E : ndarray or float
        πL/2, W/m² (or lx).

    Notes
    -----
    (1/π)·L·∫₀^{2π}∫₀^{π/2} sinθ·sinθ dθ dφ = (1/π)·L·2π·π/4 = πL/2. A
    semi-cylinder reads the same: ∫(1 + cos φ)dφ = 2π. Half the horizontal
    irradiance πL, so the modelling ratio E_z/E_h is 0.5.

    References
    ----------
    .. [1] docs/REFERENCES.md §Cylindrical illuminance.
    """
    return _out(np.asarray(radiance, float) * np.pi * 0.5)


def lambertian_radiance(albedo, irradiance):
    """Radiance leaving an ideal diffuse (Lambertian) surface lit by an irradiance.

    Parameters
    ----------
    albedo : float or array_like
        Diffuse reflectance ρ, in [0, 1] (1: a white surface that absorbs nothing).
    irradiance : float or array_like
        Irradiance E on the surface, W/m² (or lx).

    Returns
    -------
    L : ndarray or float
        Reflected radiance, the same in every direction: ρ·E/π, W m⁻² sr⁻¹ (or cd/m²).

    Notes
    -----
    A Lambertian BRDF is the constant f = ρ/π (its cosine-weighted integral
    over the hemisphere is ρ), so L_o = ∫ f L_i cos θ dω = (ρ/π)·E.

    References
    ----------
    .. [1] M. Pharr, W. Jakob, G. Humphreys, "Physically Based Rendering",
       4th ed. (2023), §9.2 "Diffuse Reflection".
    """
    albedo = np.asarray(albedo, float)
    if np.any(albedo < 0.0) or np.any(albedo > 1.0):
        raise ValueError("albedo must be in [0, 1]")
    return _out(albedo * np.asarray(irradiance, float) / np.pi)


def _check_albedo(albedo):
    albedo = np.asarray(albedo, float)
    if np.any(albedo < 0.0) or np.any(albedo >= 1.0):
        raise ValueError("albedo must be in [0, 1)")
    return albedo


def furnace_radiance(emitted_radiance, albedo):
    """Radiance inside a closed furnace: walls that emit and reflect uniformly.

    Parameters
    ----------
    emitted_radiance : float or array_like
        Radiance L_e each wall emits, W m⁻² sr⁻¹ (or cd/m²).
    albedo : float or array_like
        Diffuse reflectance ρ of every wall, in [0, 1).

    Returns
    -------
    L : ndarray or float
        Radiance everywhere in the enclosure: L_e/(1 − ρ).

    Notes
    -----
    If L is uniform, every wall receives E = π·L and reflects radiance
    ρ·E/π = ρ·L, so L = L_e + ρ·L — whatever the enclosure's shape. The
    Neumann series L_e·Σ ρ^k converges to the same value; truncating it after
    k bounces loses a fraction ρ^(k+1).

    References
    ----------
    .. [1] docs/REFERENCES.md §Furnace.
    """
    return _out(np.asarray(emitted_radiance, float) / (1.0 - _check_albedo(albedo)))


def furnace_irradiance(emitted_radiance, albedo):
    """Irradiance on any receiver inside a furnace: π·L_e/(1 − ρ).

    Parameters
    ----------
    emitted_radiance : float or array_like
        Radiance each wall emits, W m⁻² sr⁻¹ (or cd/m²).
    albedo : float or array_like
        Diffuse reflectance of every wall, in [0, 1).

    Returns
    -------
    E : ndarray or float
        Irradiance, W/m² (or lx).

    Notes
    -----
    π times :func:`furnace_radiance`: the receiver sees radiance
    L_e/(1 − ρ) over its whole hemisphere.

    References
    ----------
    .. [1] docs/REFERENCES.md §Furnace.
    """
    return _out(np.pi * furnace_radiance(emitted_radiance, albedo))


def _sphere_args(flux, R, albedo):
    R = np.asarray(R, float)
    if np.any(R <= 0.0):
        raise ValueError("integrating sphere: need R > 0")
    return np.asarray(flux, float), 4.0 * np.pi * R * R, _check_albedo(albedo)


def integrating_sphere_irradiance(flux, R, albedo):
    """Total wall irradiance of an ideal integrating sphere, source at centre.

    Parameters
    ----------
    flux : float or array_like
        Flux Φ of an isotropic point source at the centre, W (or lm).
    R : float or array_like
        Sphere radius, metres.
    albedo : float or array_like
        Diffuse reflectance ρ of the wall, in [0, 1).

    Returns
    -------
    E : ndarray or float
        Irradiance on the wall (direct + all reflected orders), W/m² (or lx):
        Φ/(4πR²(1 − ρ)).

    Notes
    -----
    Direct: Φ/(4πR²) everywhere. Reflected: see
    :func:`integrating_sphere_reflected`. Their sum is Φ/(4πR²(1 − ρ)).

    References
    ----------
    .. [1] docs/REFERENCES.md §Integrating sphere.
    """
    flux, area, rho = _sphere_args(flux, R, albedo)
    return _out(flux / (area * (1.0 - rho)))


def integrating_sphere_first_bounce(flux, R, albedo):
    """Wall irradiance of an ideal integrating sphere from one reflection.

    Parameters
    ----------
    flux : float or array_like
        Flux Φ of the source, W (or lm), all of which first strikes the wall
        (anywhere: the source need not be central or isotropic).
    R : float or array_like
        Sphere radius, metres.
    albedo : float or array_like
        Diffuse reflectance ρ, in [0, 1).

    Returns
    -------
    E1 : ndarray or float
        Irradiance due to light reflected exactly once, W/m² (or lx):
        ρΦ/(4πR²), the same at every wall point.

    Notes
    -----
    Two points of a sphere at chord length c see each other with
    cos θ₁ = cos θ₂ = c/(2R), so the point-to-area kernel
    cos θ₁ cos θ₂/(π c²) = 1/(4πR²) is constant: light reflected
    anywhere is spread uniformly over the wall. The reflected flux is ρΦ.

    References
    ----------
    .. [1] docs/REFERENCES.md §Integrating sphere.
    """
    flux, area, rho = _sphere_args(flux, R, albedo)
    return _out(rho * flux / area)


def integrating_sphere_reflected(flux, R, albedo):
    """Wall irradiance of an ideal integrating sphere from all reflections.

    Parameters
    ----------
    flux : float or array_like
        Source flux Φ, W (or lm), all of which first strikes the wall.
    R : float or array_like
        Sphere radius, metres.
    albedo : float or array_like
        Diffuse reflectance ρ, in [0, 1).

    Returns
    -------
    Er : ndarray or float
        Irradiance due to light reflected one or more times, W/m² (or lx):
        Φ/(4πR²)·ρ/(1 − ρ), uniform over the wall.

    Notes
    -----
    Each order is ρ times the previous, starting at ρΦ/(4πR²)
    (:func:`integrating_sphere_first_bounce`): Σ_{k≥1} ρ^k Φ/(4πR²).

    References
    ----------
    .. [1] docs/REFERENCES.md §Integrating sphere.
    """
    flux, area, rho = _sphere_args(flux, R, albedo)
    return _out(flux / area * rho / (1.0 - rho))


# --------------------------------------------------------------------------
# CIE 171:2006
# --------------------------------------------------------------------------

#: CIE 171:2006 case 5.2, published illuminance (lx) per receiver.
CIE171_5_2_PUBLISHED_LX: dict[str, float] = {
    "A": 111.11, "B": 105.21, "C": 90.02, "D": 71.11, "E": 99.73,
    "F": 85.64, "G": 68.06, "H": 74.36, "I": 59.98, "J": 49.39,
}

_CIE171_5_2_OFFSETS_M = {
    "A": (0.0, 0.0), "B": (0.5, 0.0), "C": (1.0, 0.0), "D": (1.5, 0.0), "E": (0.5, 0.5),
    "F": (1.0, 0.5), "G": (1.5, 0.5), "H": (1.0, 1.0), "I": (1.5, 1.0), "J": (1.5, 1.5),
}


class CIE171PointSourceGrid(NamedTuple):
    """CIE 171:2006 case 5.2: receivers under a Lambertian point source.

    Attributes
    ----------
    names : tuple of str
        Receiver names, ``"A"`` … ``"J"``.
    offsets : ndarray, shape (10, 2)
        Horizontal offsets (x, y) from the point below the source, metres.
    positions : ndarray, shape (10, 3)
        Receiver positions (x, y, 0), metres; every receiver faces +Z.
    source : ndarray, shape (3,)
        Source position (0, 0, h), metres.
    intensity_cd : float
        I₀, the intensity straight down, cd.
    height_m : float
        h, metres.
    exact_lx : ndarray, shape (10,)
        I₀·h²/d⁴, lx.
    published_lx : ndarray, shape (10,)
        The values printed in CIE 171:2006, lx.
    """

    names: tuple[str, ...]
    offsets: np.ndarray
    positions: np.ndarray
    source: np.ndarray
    intensity_cd: float
    height_m: float
    exact_lx: np.ndarray
    published_lx: np.ndarray


def cie171_point_source_grid() -> CIE171PointSourceGrid:
    """CIE 171:2006 test case 5.2 (point source), exact and published.

    Returns
    -------
    grid : CIE171PointSourceGrid
        Names, offsets and positions of the ten receivers A–J, the source,
        and the exact and published illuminance (lx).

    Notes
    -----
    A Lambertian point source, I(θ) = I₀·cos θ with I₀ = 1000 cd, hangs at
    h = 3 m pointing straight down over a 4 m × 4 m floor; receivers on the
    floor face up. For a receiver at horizontal offset ρ, d² = h² + ρ² and
    the angle θ from the source's axis equals the angle of incidence on the
    horizontal receiver, with cos θ = h/d. The inverse-square cosine law
    (:func:`point_irradiance`) gives

        E = I(θ)·cos θ/d² = I₀·cos²θ/d² = I₀·h²/d⁴.

    The published table differs from this exact value by at most 0.024 lx
    (receivers B, F and H; about 0.03 %), attributed to rounded intensities
    in the table's computation. Tests compare against ``exact_lx``.

    References
    ----------
    .. [1] CIE 171:2006, section 5.2.
    .. [2] docs/REFERENCES.md §CIE 171:2006 case 5.2.
    """
    names = tuple(_CIE171_5_2_OFFSETS_M)
    offsets = np.array([_CIE171_5_2_OFFSETS_M[k] for k in names], float)
    i0, h = 1000.0, 3.0
    positions = np.column_stack([offsets, np.zeros(len(names))])
    d2 = h * h + np.sum(offsets * offsets, axis=1)
    return CIE171PointSourceGrid(
        names=names,
        offsets=offsets,
        positions=positions,
        source=np.array([0.0, 0.0, h]),
        intensity_cd=i0,
        height_m=h,
        exact_lx=i0 * h * h / (d2 * d2),
        published_lx=np.array([CIE171_5_2_PUBLISHED_LX[k] for k in names]),
    )


#: CIE 171:2006 case 5.8: isotropic 10 000 lm source at the centre of a 4 m
#: cube (S_T = 96 m²); published mean indirect illuminance (lx) by reflectance.
CIE171_5_8_TABLE_LX: dict[float, float] = {
    0.05: 5.48, 0.1: 11.6, 0.2: 26.0, 0.3: 44.6, 0.4: 69.4, 0.5: 104.0,
    0.6: 156.0, 0.7: 243.0, 0.8: 417.0, 0.9: 937.0, 0.95: 1979.0,
}
CIE171_5_8_FLUX_LM = 10_000.0
CIE171_5_8_TOTAL_AREA_M2 = 96.0
#: published mean direct illuminance over the cube's surfaces, lx (= Φ/S_T)
CIE171_5_8_DIRECT_MEAN_LX = 104.17


def cie171_indirect_illuminance(flux_lm, reflectance, total_area):
    """Mean indirect illuminance in a closed room of uniform reflectance.

    Parameters
    ----------
    flux_lm : float or array_like
        Source flux Φ, lm (or W), all of which first lands on the surfaces.
    reflectance : float or array_like
        Diffuse reflectance ρ of every surface, in [0, 1).
    total_area : float or array_like
        Total surface area S_T of the enclosure, m².

    Returns
    -------
    E_ind : ndarray or float
        Area-mean indirect illuminance over all surfaces, lx (or W/m²):
        ρΦ/((1 − ρ)·S_T).

    Notes
    -----
    In a closed enclosure every reflected lumen lands on a surface again, so
    the k-th reflection delivers ρ^k·Φ and the indirect flux arriving in total
    is Σ_{k≥1} ρ^k·Φ = ρΦ/(1 − ρ); dividing by S_T gives the mean. The mean
    is exact for any shape and source position (the distribution over the
    surfaces is not uniform in a cube).

    References
    ----------
    .. [1] CIE 171:2006, section 5.8 (table in :data:`CIE171_5_8_TABLE_LX`).
    .. [2] docs/REFERENCES.md §CIE 171:2006 case 5.8.
    """
    flux = np.asarray(flux_lm, float)
    rho = _check_albedo(reflectance)
    area = np.asarray(total_area, float)
    if np.any(area <= 0.0):
        raise ValueError("cie171_indirect_illuminance: total_area must be > 0")
    return _out(rho * flux / ((1.0 - rho) * area))


# --------------------------------------------------------------------------- #
# CIE standard overcast sky, and skies stored as lat-long rows
# --------------------------------------------------------------------------- #


def cie_overcast_luminance(zenith_luminance, theta):
    """Luminance of the CIE standard overcast sky.

    Parameters
    ----------
    zenith_luminance : float or array_like
        L_z, cd/m² (or W m⁻² sr⁻¹).
    theta : float or array_like
        Zenith angle, rad, 0 ≤ θ ≤ π/2.

    Returns
    -------
    float or ndarray
        L(θ), in the units of ``zenith_luminance``.

    Notes
    -----
    L(θ) = L_z·(1 + 2·cosθ)/3: a third of the zenith value at the horizon,
    independent of azimuth.

    References
    ----------
    P. Moon, D. E. Spencer, "Illumination from a non-uniform sky",
    Illuminating Engineering 37, 707–726, 1942; CIE S 011/E:2003, *Spatial
    distribution of daylight — CIE standard general sky* (type 16).
    docs/REFERENCES.md §CIE standard overcast sky.
    """
    return zenith_luminance * (1.0 + 2.0 * np.cos(theta)) / 3.0


def cie_overcast_row_means(zenith_luminance, n_rows):
    """The CIE overcast sky as the rows of a lat-long map.

    Parameters
    ----------
    zenith_luminance : float
        L_z, cd/m².
    n_rows : int
        Rows of the map; row j spans θ ∈ [jπ/n, (j+1)π/n] (row 0 at the zenith).

    Returns
    -------
    ndarray, shape (n_rows,)
        Each row's luminance averaged over its solid angle; 0 below the horizon.

    Notes
    -----
    ∫(1 + 2cosθ)·sinθ dθ / ∫sinθ dθ over [θ0, θ1]
    = 1 + (sin²θ1 − sin²θ0)/(cosθ0 − cosθ1), times L_z/3.

    References
    ----------
    P. Moon, D. E. Spencer, "Illumination from a non-uniform sky",
    Illuminating Engineering 37, 707–726, 1942; CIE S 011/E:2003, *Spatial
    distribution of daylight — CIE standard general sky* (type 16).
    docs/REFERENCES.md §CIE standard overcast sky.
    """
    t = np.linspace(0.0, np.pi, n_rows + 1)
    t0, t1 = t[:-1], t[1:]
    mean = zenith_luminance * (1.0 + (np.sin(t1) ** 2 - np.sin(t0) ** 2) / (np.cos(t0) - np.cos(t1))) / 3.0
    return np.where(t1 <= np.pi / 2 + 1e-12, mean, 0.0)


def cie_overcast_illuminance(zenith_luminance, vertical=False):
    """Illuminance from the CIE overcast sky alone (no ground).

    Parameters
    ----------
    zenith_luminance : float
        L_z, cd/m².
    vertical : bool
        A vertical receiver instead of a horizontal one.

    Returns
    -------
    float
        Illuminance, lx (W/m² for radiometric input).

    Notes
    -----
    E = ∫∫ L·cosγ dω over the sky: horizontal, 2π·∫(L_z/3)(1 + 2cosθ)cosθ sinθ dθ
    = 7π·L_z/9; vertical, ∫(L_z/3)(1 + 2cosθ)·2sin²θ dθ = L_z·(π/6 + 4/9)
    (the azimuth integral of max(0, sinθ·cosφ) is 2·sinθ). Their ratio is 0.396.

    References
    ----------
    P. Moon, D. E. Spencer, "Illumination from a non-uniform sky",
    Illuminating Engineering 37, 707–726, 1942; CIE S 011/E:2003, *Spatial
    distribution of daylight — CIE standard general sky* (type 16).
    docs/REFERENCES.md §CIE standard overcast sky.
    """
    if vertical:
        return zenith_luminance * (np.pi / 6.0 + 4.0 / 9.0)
    return 7.0 * np.pi * zenith_luminance / 9.0


def latlong_rows_illuminance(row_luminance, vertical=False):
    """Illuminance from a sky map whose rows are uniform in azimuth, exact for
    the piecewise-constant map.

    Parameters
    ----------
    row_luminance : array_like, shape (n,)
        Luminance of each row; row j spans θ ∈ [jπ/n, (j+1)π/n].
    vertical : bool
        A vertical receiver instead of a horizontal one (rows below the
        horizon must be 0: the formula counts the upper hemisphere).

    Returns
    -------
    float
        Illuminance, in the luminance's units × sr.

    Notes
    -----
    Horizontal: Σ_j L_j·π·(sin²θ1 − sin²θ0), the integral of cosθ dω over
    the row. Vertical: Σ_j L_j·[θ − sinθ·cosθ] from θ0 to θ1, the integral
    of 2·sin²θ dθ (the azimuth integral of max(0, sinθ·cosφ) is 2·sinθ).

    References
    ----------
    The lat-long convention of ``simulator.io.latlong`` (OpenEXR environment
    maps): rows of equal angular height from the pole.
    """
    row_luminance = np.asarray(row_luminance, float)
    t = np.linspace(0.0, np.pi, len(row_luminance) + 1)
    t0, t1 = t[:-1], t[1:]
    if vertical:
        g = lambda x: x - np.sin(x) * np.cos(x)  # noqa: E731
        return float(np.sum(row_luminance * (g(t1) - g(t0))))
    return float(np.sum(row_luminance * np.pi * (np.sin(t1) ** 2 - np.sin(t0) ** 2)))


def thin_slab(cos_theta, n: float, t0: float | None = None):
    """Unpolarised (R, T) of a plane-parallel slab of index ``n`` at incidence cosine ``cos_theta``
    (docs/REFERENCES.md §Thin slab): per polarisation, with r the Fresnel reflectance of one interface
    and τ the internal transmittance of one pass, T = (1 − r)²τ/(1 − r²τ²) and R = r + (1 − r)²rτ²/(1 −
    r²τ²), averaged over s and p. ``t0``: the slab's normal-incidence transmittance (a glazing
    datasheet's), which fixes τ₀ by T₀r₀²τ₀² + (1 − r₀)²τ₀ − T₀ = 0 and τ = τ₀^(1/cosθ_t); None:
    clear (τ = 1)."""
    c = np.asarray(cos_theta, dtype=np.float64)
    sin_t = np.sqrt(np.maximum(0.0, 1.0 - c * c)) / n
    ct = np.sqrt(1.0 - sin_t * sin_t)
    tau0 = 1.0
    if t0 is not None:
        r0 = ((n - 1.0) / (n + 1.0)) ** 2
        a, b = t0 * r0 * r0, (1.0 - r0) ** 2
        tau0 = (-b + np.sqrt(b * b + 4.0 * a * t0)) / (2.0 * a)
    tau = tau0 ** (1.0 / ct)
    rs = ((c - n * ct) / (c + n * ct)) ** 2
    rp = ((n * c - ct) / (n * c + ct)) ** 2
    R = T = 0.0
    for r in (rs, rp):
        den = 1.0 - (r * tau) ** 2
        T = T + 0.5 * (1.0 - r) ** 2 * tau / den
        R = R + 0.5 * (r + (1.0 - r) ** 2 * r * tau * tau / den)
    return R, T
