"""Sampling routines as ``@wp.func`` pairs: ``sample_x(u) -> value`` and ``pdf_x(value)``.

Every distribution here comes with the density it draws from, in the measure
the estimators use (solid angle for directions, area for points), so that a
sample's weight is ``f(x) / pdf(x)`` and multiple importance sampling can ask
any strategy for the density of a direction another strategy produced.

All pdfs are with respect to solid angle (sr⁻¹) unless the name says ``area``.

References
----------
T. Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
P. Shirley, K. Chiu, "A Low Distortion Map Between Disk and Square", JGT 1997.
C. Ureña, M. Fajardo, A. King, "An Area-Preserving Parametrization for
Spherical Rectangles", Computer Graphics Forum 32(4), 2013.
M. Pharr, W. Jakob, G. Humphreys, "Physically Based Rendering", 4th ed., ch. 2 and A.5.
"""

import warp as wp

PI = wp.constant(3.14159265358979323846)
TWO_PI = wp.constant(6.28318530717958647692)
INV_PI = wp.constant(0.31830988618379067154)

# Below this solid angle (sr) the spherical-rectangle parametrisation loses
# float32 precision (its S = Σγ − 2π cancels); area sampling is then nearly
# as good because the rectangle subtends an almost constant cos/d².
SPHRECT_MIN_SOLID_ANGLE = wp.constant(1.0e-4)


# ---------------------------------------------------------------- random numbers


# PCG-RXS-M-XS constants (O'Neill 2014), typed so no literal passes through int32
_PCG_MUL = wp.constant(wp.uint32(747796405))
_PCG_INC = wp.constant(wp.uint32(2891336453))
_PCG_OUT = wp.constant(wp.uint32(277803737))
_GOLDEN = wp.constant(wp.uint32(0x9E3779B9))


@wp.func
def hash_u32(x: wp.uint32) -> wp.uint32:
    """32-bit integer hash (a PCG output permutation) to decorrelate seeds."""
    state = x * _PCG_MUL + _PCG_INC
    word = ((state >> ((state >> wp.uint32(28)) + wp.uint32(4))) ^ state) * _PCG_OUT
    return (word >> wp.uint32(22)) ^ word


@wp.func
def sensor_stream_key(seed: int, sensor: int) -> int:
    """Seed of one sensor's random streams: sample j of sensor s under run seed
    k always draws from ``wp.rand_init(sensor_stream_key(k, s), j)``, whatever
    the batch layout, device thread count or stopping point."""
    return int(hash_u32(wp.uint32(seed) ^ hash_u32(wp.uint32(sensor) + _GOLDEN)) >> wp.uint32(1))


#: salt of the hero-wavelength stream (hero_stream_key)
_HERO_SALT = wp.constant(wp.uint32(0x85EBCA6B))


@wp.func
def hero_stream_key(key: int) -> int:
    """Seed of a sensor's wavelength stream, apart from its path stream ``key``
    (:func:`sensor_stream_key`): sample j draws its hero wavelengths from
    ``wp.rand_init(hero_stream_key(key), j)``, so they depend on neither the
    batch layout nor how many numbers the path used."""
    return int(hash_u32(wp.uint32(key) ^ _HERO_SALT) >> wp.uint32(1))


# ---------------------------------------------------------------- frames


@wp.func
def frame_x(n: wp.vec3) -> wp.vec3:
    """First tangent of an orthonormal basis around unit ``n`` (Duff et al. 2017)."""
    s = wp.where(n[2] >= 0.0, 1.0, -1.0)
    a = -1.0 / (s + n[2])
    b = n[0] * n[1] * a
    return wp.vec3(1.0 + s * n[0] * n[0] * a, s * b, -s * n[0])


@wp.func
def frame_y(n: wp.vec3) -> wp.vec3:
    """Second tangent of the basis of :func:`frame_x`; (x, y, n) is right-handed."""
    s = wp.where(n[2] >= 0.0, 1.0, -1.0)
    a = -1.0 / (s + n[2])
    b = n[0] * n[1] * a
    return wp.vec3(b, s + n[1] * n[1] * a, -n[1])


@wp.func
def to_world(local: wp.vec3, n: wp.vec3) -> wp.vec3:
    return local[0] * frame_x(n) + local[1] * frame_y(n) + local[2] * n


# ---------------------------------------------------------------- disk and hemisphere


@wp.func
def sample_concentric_disk(u: wp.vec2) -> wp.vec2:
    """Uniform point on the unit disk (Shirley–Chiu concentric map); area pdf 1/π."""
    a = 2.0 * u[0] - 1.0
    b = 2.0 * u[1] - 1.0
    if a == 0.0 and b == 0.0:
        return wp.vec2(0.0, 0.0)
    r = float(0.0)
    phi = float(0.0)
    if wp.abs(a) > wp.abs(b):
        r = a
        phi = (PI / 4.0) * (b / a)
    else:
        r = b
        phi = (PI / 2.0) - (PI / 4.0) * (a / b)
    return wp.vec2(r * wp.cos(phi), r * wp.sin(phi))


@wp.func
def sample_cosine_hemisphere(u: wp.vec2) -> wp.vec3:
    """Cosine-weighted direction about +Z (Malley's method); pdf cosθ/π."""
    d = sample_concentric_disk(u)
    z = wp.sqrt(wp.max(0.0, 1.0 - d[0] * d[0] - d[1] * d[1]))
    return wp.vec3(d[0], d[1], z)


@wp.func
def pdf_cosine_hemisphere(cos_theta: float) -> float:
    return wp.where(cos_theta > 0.0, cos_theta * INV_PI, 0.0)


# ---------------------------------------------------------------- cones


@wp.func
def sample_uniform_cone(u: wp.vec2, one_minus_cos_max: float) -> wp.vec3:
    """Uniform direction in the cone about +Z with 1 − cosθmax = ``one_minus_cos_max``.

    Takes 1 − cosθmax rather than cosθmax because for a tiny cone (a 1 mm
    sphere at 1 m) cosθmax rounds to 1 in float32; sin²θ is formed as
    (1 − cosθ)(1 + cosθ) for the same reason. pdf: :func:`pdf_uniform_cone`.
    """
    omc = u[0] * one_minus_cos_max  # 1 − cosθ, uniform in [0, 1 − cosθmax]
    cos_t = 1.0 - omc
    sin_t = wp.sqrt(wp.max(0.0, omc * (2.0 - omc)))
    phi = TWO_PI * u[1]
    return wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), cos_t)


@wp.func
def pdf_uniform_cone(one_minus_cos_max: float) -> float:
    """Solid-angle pdf of :func:`sample_uniform_cone`: 1 / (2π(1 − cosθmax))."""
    return 1.0 / (TWO_PI * one_minus_cos_max)


@wp.func
def one_minus_cos_from_sin2(sin2: float) -> float:
    """1 − cosθ from sin²θ without cancellation: sin²θ / (1 + cosθ)."""
    s2 = wp.min(sin2, 1.0)
    return s2 / (1.0 + wp.sqrt(1.0 - s2))


# ---------------------------------------------------------------- triangles


@wp.func
def sample_triangle_bary(u: wp.vec2) -> wp.vec2:
    """Uniform barycentrics (b1, b2) on a triangle (square-root map); area pdf 1/A."""
    su = wp.sqrt(u[0])
    return wp.vec2(u[1] * su, 1.0 - su)


@wp.func
def patch_index(s: float, t: float, m: int) -> int:
    """Index k (0 … m² − 1) of the sub-triangle holding (s, t) on a triangle
    cut m × m: k = j·(2m − j) + 2i + upper (see
    simulator.scene.patches). Twin of :func:`patch_point`."""
    fm = float(m)
    i = wp.clamp(int(wp.floor(s * fm)), 0, m - 1)
    j = wp.clamp(int(wp.floor(t * fm)), 0, m - 1)
    upper = int(0)
    if i + j > m - 1:  # rounding past the hypotenuse
        i = m - 1 - j
    elif i + j <= m - 2 and (s * fm - float(i)) + (t * fm - float(j)) >= 1.0:
        upper = 1
    return j * (2 * m - j) + 2 * i + upper


@wp.func
def patch_point(k: int, m: int, u: wp.vec2) -> wp.vec2:
    """(s, t) uniform on sub-triangle k of a triangle cut m × m (area pdf
    m²/A on the triangle's plane). Twin of :func:`patch_index`."""
    fm = float(m)
    j = wp.clamp(int(wp.floor(fm - wp.sqrt(wp.max(fm * fm - float(k), 0.0)))), 0, m - 1)
    while j > 0 and j * (2 * m - j) > k:
        j -= 1
    while j < m - 1 and (j + 1) * (2 * m - j - 1) <= k:
        j += 1
    r = k - j * (2 * m - j)
    i = r // 2
    b = sample_triangle_bary(u)  # weights of the corners B and C, A gets the rest
    a0 = wp.vec2(float(i), float(j))
    e1 = wp.vec2(1.0, 0.0)
    e2 = wp.vec2(0.0, 1.0)
    if r % 2 == 1:  # upper: corners (i+1, j+1), (i, j+1), (i+1, j)
        a0 = wp.vec2(float(i + 1), float(j + 1))
        e1 = wp.vec2(-1.0, 0.0)
        e2 = wp.vec2(0.0, -1.0)
    return (a0 + b[0] * e1 + b[1] * e2) / fm


# ---------------------------------------------------------------- spherical rectangles


@wp.struct
class SphRect:
    """A rectangle as seen from a point, set up for solid-angle sampling.

    Local frame: x, y along the rectangle's edges, z toward the side the
    point is on (z0 < 0 is the rectangle's signed distance along z).
    """

    o: wp.vec3
    x: wp.vec3
    y: wp.vec3
    z: wp.vec3
    x0: float
    y0: float
    x1: float
    y1: float
    z0: float
    b0: float
    b1: float
    k: float
    solid_angle: float


@wp.func
def sphrect_setup(o: wp.vec3, corner: wp.vec3, ex: wp.vec3, ey: wp.vec3, w: float, h: float) -> SphRect:
    """Prepare the rectangle ``corner + [0,w]·ex + [0,h]·ey`` (ex ⊥ ey unit) seen from ``o``.

    The solid angle is the spherical excess of the quadrilateral: the sum of
    the four dihedral angles between the planes through ``o`` and each edge,
    minus 2π (Ureña et al. 2013, §3).
    """
    r = SphRect()
    r.o = o
    r.x = ex
    r.y = ey
    z = wp.cross(ex, ey)
    d = corner - o
    r.x0 = wp.dot(d, ex)
    r.y0 = wp.dot(d, ey)
    z0 = wp.dot(d, z)
    if z0 > 0.0:
        z0 = -z0
        z = -z
    r.z = z
    r.z0 = z0
    r.x1 = r.x0 + w
    r.y1 = r.y0 + h
    v00 = wp.vec3(r.x0, r.y0, z0)
    v01 = wp.vec3(r.x0, r.y1, z0)
    v10 = wp.vec3(r.x1, r.y0, z0)
    v11 = wp.vec3(r.x1, r.y1, z0)
    n0 = wp.normalize(wp.cross(v00, v10))
    n1 = wp.normalize(wp.cross(v10, v11))
    n2 = wp.normalize(wp.cross(v11, v01))
    n3 = wp.normalize(wp.cross(v01, v00))
    g0 = wp.acos(wp.clamp(-wp.dot(n0, n1), -1.0, 1.0))
    g1 = wp.acos(wp.clamp(-wp.dot(n1, n2), -1.0, 1.0))
    g2 = wp.acos(wp.clamp(-wp.dot(n2, n3), -1.0, 1.0))
    g3 = wp.acos(wp.clamp(-wp.dot(n3, n0), -1.0, 1.0))
    r.b0 = n0[2]
    r.b1 = n2[2]
    r.k = TWO_PI - g2 - g3
    r.solid_angle = g0 + g1 - r.k
    return r


@wp.func
def sphrect_sample(r: SphRect, u: wp.vec2) -> wp.vec3:
    """Point on the rectangle whose direction from ``r.o`` is uniform in solid
    angle (pdf 1/``r.solid_angle``), by inverting the area of the spherical
    sub-rectangle in x and then the height along the chosen x (Ureña et al. 2013, §4)."""
    au = u[0] * r.solid_angle + r.k
    fu = (wp.cos(au) * r.b0 - r.b1) / wp.sin(au)
    cu = wp.where(fu > 0.0, 1.0, -1.0) / wp.sqrt(fu * fu + r.b0 * r.b0)
    cu = wp.clamp(cu, -1.0, 1.0)
    xu = -(cu * r.z0) / wp.max(wp.sqrt(1.0 - cu * cu), 1.0e-12)
    xu = wp.clamp(xu, r.x0, r.x1)
    d = wp.sqrt(xu * xu + r.z0 * r.z0)
    h0 = r.y0 / wp.sqrt(d * d + r.y0 * r.y0)
    h1 = r.y1 / wp.sqrt(d * d + r.y1 * r.y1)
    hv = h0 + u[1] * (h1 - h0)
    hv2 = hv * hv
    yv = r.y1
    if hv2 < 1.0 - 1.0e-6:
        yv = (hv * d) / wp.sqrt(1.0 - hv2)
    yv = wp.clamp(yv, r.y0, r.y1)
    return r.o + xu * r.x + yv * r.y + r.z0 * r.z
