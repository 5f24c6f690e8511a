"""Closed-form unoccluded irradiance from one light, as ``@wp.func``.

The ``analytic`` estimator sums these over a sensor's lights where nothing can
block them. Each takes the receiver point ``p`` and unit normal ``n`` and
returns irradiance per unit emission, so the caller multiplies by the light's
(radiometric, photometric) pair.

Notes
-----
- Point: E = I·cosξ/d².
- Sphere of angular radius σ (and a distant light of half-angle σ, which is
  the same thing at infinity), centre direction at θ from n:
  wholly above the horizon E/L = π·sin²σ·cosθ; straddling, with
  x = √(1/sin²σ − 1), y = −x·cotθ,
  E/L = (cosθ·acos y − x·sinθ·√(1 − y²))·sin²σ + atan(sinθ·√(1 − y²)/x).
- Polygon (rectangle, triangle), clipped to the receiver's upper hemisphere:
  Lambert's contour formula E/L = ½·|Σ acos(vᵢ·vᵢ₊₁)·n·normalize(vᵢ × vᵢ₊₁)|.
- Disk wholly above the horizon: the same contour integral over the circle,
  E/L = ½·|n · ∮ (r × dr)/|r|²|, by the periodic trapezoid rule, which
  converges geometrically for this analytic periodic integrand (256 nodes give
  float32 precision unless the receiver is within ~1% of a radius of the rim).

References
----------
J. H. Lambert, Photometria, 1760 (the contour formula); J. R. Howell, "A
Catalog of Radiation Heat Transfer Configuration Factors", cases C-12, C-41;
L. N. Trefethen, J. A. C. Weideman, "The exponentially convergent trapezoidal
rule", SIAM Review 56(3), 2014.
"""

import warp as wp

from .sampling import PI, TWO_PI

#: trapezoid nodes around a disk's rim
DISK_NODES = wp.constant(256)


@wp.func
def point_irradiance(light_pos: wp.vec3, p: wp.vec3, n: wp.vec3) -> float:
    """E/I for a point source: cosξ/d²."""
    d = light_pos - p
    d2 = wp.length_sq(d)
    c = wp.dot(d, n)
    if c <= 0.0 or d2 <= 0.0:
        return 0.0
    return c / (d2 * wp.sqrt(d2))


@wp.func
def cap_irradiance(axis: wp.vec3, sin2_sigma: float, n: wp.vec3) -> float:
    """E/L from a uniform spherical cap of angular radius σ centred on unit
    ``axis`` (a sphere light, or a distant light's cone).

    Evaluated in float64: for a small cap straddling the horizon (the sun at
    sunset) the two terms of the straddling formula are ~σ and cancel to
    ~σ², which float32 cannot hold (1% error at σ = 0.27°)."""
    f0 = wp.float64(0.0)
    f1 = wp.float64(1.0)
    s2 = wp.float64(sin2_sigma)
    cos_t = wp.clamp(wp.dot(wp.vec3d(axis), wp.vec3d(n)), -f1, f1)
    sin_t = wp.sqrt(wp.max(f0, f1 - cos_t * cos_t))
    cos_s = wp.sqrt(wp.max(f0, f1 - s2))
    pi = wp.float64(PI)
    # wholly above the horizon: θ + σ ≤ π/2  ⇔  cosθ ≥ sinσ
    if cos_t * cos_t > s2 and cos_t > f0:
        return float(pi * s2 * cos_t)
    # wholly below: θ − σ ≥ π/2  ⇔  cosθ ≤ −sinσ
    if cos_t <= -wp.sqrt(s2):
        return 0.0
    if sin_t <= f0:
        return float(pi * s2 * cos_t)
    x = cos_s / wp.sqrt(s2)  # √(1/sin²σ − 1)
    y = wp.clamp(-x * cos_t / sin_t, -f1, f1)
    sy = wp.sqrt(wp.max(f0, f1 - y * y))
    return float((cos_t * wp.acos(y) - x * sin_t * sy) * s2 + wp.atan(sin_t * sy / x))


@wp.func
def _edge_term(a: wp.vec3d, b: wp.vec3d, n: wp.vec3d) -> wp.float64:
    """acos(a·b)·n·normalize(a × b) for unit a, b (0 for a degenerate edge),
    in float64: a small or distant emitter's edges subtend ~1e-4 rad, which
    float32's cross product resolves to only ~1e-3 relative."""
    c = wp.cross(a, b)
    s = wp.length(c)
    if s <= wp.float64(0.0):
        return wp.float64(0.0)
    return wp.atan2(s, wp.dot(a, b)) * wp.dot(n, c) / s


@wp.func
def polygon_irradiance4(v0: wp.vec3, v1: wp.vec3, v2: wp.vec3, v3: wp.vec3, nv: int, p: wp.vec3, n: wp.vec3) -> float:
    """E/L from a uniform convex polygon of 3 (``nv`` = 3) or 4 vertices,
    clipped to the receiver's upper hemisphere (Sutherland–Hodgman against
    the plane through p with normal n), by Lambert's contour formula, in
    float64 (see :func:`_edge_term`)."""
    pd = wp.vec3d(p)
    nd = wp.vec3d(n)
    r0 = wp.vec3d(v0) - pd
    r1 = wp.vec3d(v1) - pd
    r2 = wp.vec3d(v2) - pd
    r3 = wp.vec3d(v3) - pd
    if nv == 3:
        r3 = r0
    f0 = wp.float64(0.0)
    total = wp.float64(0.0)
    # walk the edges; each edge contributes its clipped part, and a crossing
    # pair (leave, enter) contributes the closing edge along the horizon
    exit_pt = wp.vec3d(f0, f0, f0)
    have_exit = int(0)
    first_enter = wp.vec3d(f0, f0, f0)
    pending_enter = int(0)
    for k in range(4):
        if k >= nv:
            continue
        a = r0
        b = r1
        if k == 1:
            a = r1
            b = r2
        elif k == 2:
            a = r2
            b = r3
            if nv == 3:
                b = r0
        elif k == 3:
            a = r3
            b = r0
        ha = wp.dot(a, nd)
        hb = wp.dot(b, nd)
        if ha > f0 and hb > f0:
            total += _edge_term(wp.normalize(a), wp.normalize(b), nd)
        elif ha > f0 and hb <= f0:
            x = a + (b - a) * (ha / (ha - hb))  # leaves the hemisphere
            total += _edge_term(wp.normalize(a), wp.normalize(x), nd)
            exit_pt = x
            have_exit = 1
        elif ha <= f0 and hb > f0:
            x = a + (b - a) * (ha / (ha - hb))  # enters
            total += _edge_term(wp.normalize(x), wp.normalize(b), nd)
            if have_exit != 0:
                total += _edge_term(wp.normalize(exit_pt), wp.normalize(x), nd)
                have_exit = 0
            else:
                first_enter = x
                pending_enter = 1
    if have_exit != 0 and pending_enter != 0:
        total += _edge_term(wp.normalize(exit_pt), wp.normalize(first_enter), nd)
    return float(wp.float64(0.5) * wp.abs(total))


@wp.func
def disk_irradiance(centre: wp.vec3, ex: wp.vec3, ey: wp.vec3, radius: float, p: wp.vec3, n: wp.vec3) -> float:
    """E/L from a uniform disk wholly above the receiver's horizon (the caller
    checks that): ½·|n · ∮ (r × dr)/|r|²| by the periodic trapezoid rule,
    accumulated in float64 (a small distant disk's integrand is ~R/d and its
    terms cancel around the rim)."""
    acc = wp.float64(0.0)
    nodes = int(DISK_NODES)
    h = wp.float64(TWO_PI) / wp.float64(float(nodes))
    c0 = wp.vec3d(centre) - wp.vec3d(p)
    exd = wp.vec3d(ex)
    eyd = wp.vec3d(ey)
    nd = wp.vec3d(n)
    rad = wp.float64(radius)
    for k in range(nodes):
        phi = wp.float64(float(k)) * h
        c = wp.cos(phi)
        s = wp.sin(phi)
        r = c0 + rad * (c * exd + s * eyd)
        dr = rad * (-s * exd + c * eyd)
        acc += wp.dot(nd, wp.cross(r, dr)) / wp.length_sq(r)
    return float(wp.float64(0.5) * wp.abs(acc * h))


@wp.func
def disk_above_horizon(centre: wp.vec3, ex: wp.vec3, ey: wp.vec3, radius: float, p: wp.vec3, n: wp.vec3) -> bool:
    """Whether every rim point is strictly above the receiver's horizon: the
    lowest rim point sits R·|n projected on the disk plane| below the centre."""
    a = wp.dot(ex, n)
    b = wp.dot(ey, n)
    return wp.dot(centre - p, n) - radius * wp.sqrt(a * a + b * b) > 0.0


@wp.func
def triangle_solid_angle(a: wp.vec3, b: wp.vec3, c: wp.vec3) -> float:
    """Solid angle of the triangle (a, b, c) seen from the origin
    (Van Oosterom & Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983)."""
    la = wp.length(a)
    lb = wp.length(b)
    lc = wp.length(c)
    num = wp.abs(wp.dot(a, wp.cross(b, c)))
    den = la * lb * lc + wp.dot(a, b) * lc + wp.dot(a, c) * lb + wp.dot(b, c) * la
    return 2.0 * wp.atan2(num, den)
