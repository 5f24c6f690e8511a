"""A point light seen in a convex spherical mirror, in float64 numpy: the irradiance its image gives.

Written from geometric optics (docs/REFERENCES.md §Spherical mirror), not
from the device code (:mod:`simulator.kernels.curved`, which solves the
traced facets by Newton's method), so the two check each other.

The reflection point m on a sphere (centre c, radius R) that sends the
light at l to the receiver at x (both outside) lies in the plane of c, x
and l (Alhazen's problem): with u(φ) = cos φ e₁ + sin φ e₂ the unit vector
from c at angle φ from x's direction in that plane, the law of reflection
makes the tangent t(φ) see x and l at opposite equal angles,
t·(x − m)/|x − m| + t·(l − m)/|l − m| = 0, which :func:`reflection_point`
solves by bisection on φ between x's and l's directions (its one root on the
side both see).

The reflected beam is astigmatic. Coddington's equations for a spherical
mirror of radius R at incidence θ give the images of the light, at object
distance s = |l − m|, at 1/s + 1/s' = 2/(R cos θ) (tangential) and
2 cos θ/R (sagittal); a convex mirror's are virtual, |s'_t| = 1/(1/s +
2/(R cos θ)) and |s'_s| = 1/(1/s + 2 cos θ/R) behind it. The light's rays in a
solid angle dω cross m over s²dω; past the mirror the beam widens in each
principal direction as (|s'| + t)/|s'| at distance t, so the irradiance on
the plane normal to the reflected ray at x (t = |x − m|) is

    E⊥ = F · I · |s'_t| |s'_s| / (s² (|s'_t| + t)(|s'_s| + t)),

and E = E⊥ cos θ_x on a sensor whose normal makes θ_x with the direction to
m. A flat mirror (R → ∞) gives F·I/(s + t)², the image source.
:func:`numeric_irradiance` checks the closed form by tracing a bundle of
the light's rays off the exact sphere.
"""

from __future__ import annotations

import numpy as np

__all__ = ["reflection_point", "image_irradiance", "distant_image_irradiance", "numeric_irradiance"]


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def reflection_point(c, radius: float, x, light, direction=None) -> np.ndarray:
    """The point m of the sphere (c, radius) where the light at ``light`` (or, with ``light`` None, a
    distant light toward the unit ``direction``) reflects toward ``x``."""
    c, x = np.asarray(c, float), np.asarray(x, float)
    far = light is None
    if far:
        s_dir = _unit(np.asarray(direction, float))
    else:
        light = np.asarray(light, float)
    e1 = _unit(x - c)
    w = s_dir if far else light - c
    e2 = w - np.dot(w, e1) * e1
    if np.linalg.norm(e2) < 1e-15:  # collinear: the point facing both
        return c + radius * e1
    e2 = _unit(e2)
    phi_l = np.arctan2(np.dot(w, e2), np.dot(w, e1))

    def f(phi):
        u = np.cos(phi) * e1 + np.sin(phi) * e2
        m = c + radius * u
        t = -np.sin(phi) * e1 + np.cos(phi) * e2
        return np.dot(t, _unit(x - m)) + np.dot(t, s_dir if far else _unit(light - m))

    lo, hi = 0.0, phi_l
    f_lo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        f_mid = f(mid)
        if (f_mid > 0) == (f_lo > 0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    phi = 0.5 * (lo + hi)
    return c + radius * (np.cos(phi) * e1 + np.sin(phi) * e2)


def image_irradiance(c, radius: float, x, normal, light, intensity: float, reflectance: float = 1.0) -> float:
    """Irradiance at ``x`` on the side ``normal`` faces from the image of a point light of ``intensity``
    in the convex mirror (c, radius) of reflectance F (module docstring); 0 where x does not face m."""
    c, x, normal, light = (np.asarray(v, float) for v in (c, x, normal, light))
    m = reflection_point(c, radius, x, light)
    u = _unit(m - c)
    cos_i = float(np.dot(_unit(x - m), u))
    s = float(np.linalg.norm(light - m))
    t = float(np.linalg.norm(x - m))
    st = 1.0 / (1.0 / s + 2.0 / (radius * cos_i))
    ss = 1.0 / (1.0 / s + 2.0 * cos_i / radius)
    e_perp = reflectance * intensity * st * ss / (s * s * (st + t) * (ss + t))
    cos_x = float(np.dot(_unit(normal), _unit(m - x)))
    return e_perp * max(cos_x, 0.0)


def distant_image_irradiance(c, radius: float, x, normal, direction, e_perp: float, reflectance: float = 1.0) -> float:
    """Irradiance at ``x`` from the image of a distant light of normal irradiance ``e_perp`` toward the unit
    ``direction`` in the convex mirror (c, radius): the s → ∞ limit of :func:`image_irradiance`, whose
    images lie at the focal lengths R cos θ/2 and R/(2 cos θ)."""
    c, x, normal = (np.asarray(v, float) for v in (c, x, normal))
    m = reflection_point(c, radius, x, None, direction)
    u = _unit(m - c)
    cos_i = float(np.dot(_unit(x - m), u))
    t = float(np.linalg.norm(x - m))
    st, ss = 0.5 * radius * cos_i, 0.5 * radius / cos_i
    cos_x = float(np.dot(_unit(normal), _unit(m - x)))
    return reflectance * e_perp * st * ss / ((st + t) * (ss + t)) * max(cos_x, 0.0)


def numeric_irradiance(c, radius: float, x, normal, light, intensity: float, reflectance: float = 1.0,
                       h: float = 1e-5) -> float:
    """The same irradiance from rays: the light's rays at angles ±h about its direction to m, reflected off
    the exact sphere, crossing the plane through x normal to the reflected ray; E⊥ = F·I·dω/dA (the area
    of the parallelogram the two ray pairs span, central differences)."""
    c, x, normal, light = (np.asarray(v, float) for v in (c, x, normal, light))
    m0 = reflection_point(c, radius, x, light)
    d0 = _unit(m0 - light)
    r0 = _unit(x - m0)
    a = _unit(np.cross(d0, [0.3, 0.5, 0.7]))
    b = np.cross(d0, a)

    def land(d):
        oc = light - c
        bq = np.dot(oc, d)
        tt = -bq - np.sqrt(bq * bq - (np.dot(oc, oc) - radius * radius))
        m = light + tt * d
        nn = _unit(m - c)
        r = d - 2.0 * np.dot(d, nn) * nn
        return m + (np.dot(x - m, r0) / np.dot(r, r0)) * r  # where the reflected ray meets the plane

    du = (land(_unit(d0 + h * a)) - land(_unit(d0 - h * a))) / (2 * h)
    dv = (land(_unit(d0 + h * b)) - land(_unit(d0 - h * b))) / (2 * h)
    area = np.linalg.norm(np.cross(du, dv))
    cos_x = float(np.dot(_unit(normal), -r0))
    return reflectance * intensity / area * max(cos_x, 0.0)
