"""Tabulated distributions as ``@wp.func`` sample/pdf twins, and the lat-long map they serve.

A 2-D piecewise-constant distribution over the unit square ``(u, v)`` is
stored as two CDF tables (built on the host by
:func:`simulator.io.latlong.build_distribution`):

- ``marg``: ``H + 1`` values, ``marg[j] = P(row < j)`` (0 first, 1 last);
- ``cond``: ``H * (W + 1)`` values, row ``j`` at ``j * (W + 1)``:
  ``P(column < i | row j)`` (0 first, 1 last).

:func:`sample_piecewise_2d` inverts the marginal, then the row's conditional
(binary searches), and places the point uniformly inside the chosen texel;
:func:`pdf_piecewise_2d` returns the same density read off the same float32
tables, ``H (marg[j+1] − marg[j]) · W (cond[j, i+1] − cond[j, i])``, so the
pair agrees exactly whatever rounding the tables carry.

On a lat-long map (the convention of :mod:`simulator.io.latlong`:
``lon = π(1 − 2u)``, ``θ = πv`` from the pole ``ey``, direction
``sinθ sin(lon)·ex + cosθ·ey + sinθ cos(lon)·ez``), ``dω = 2π² sinθ du dv``, so
the solid-angle pdf is ``pdf_uv / (2π² sinθ)`` (:func:`sample_latlong`,
:func:`pdf_latlong`).

References
----------
M. Pharr, W. Jakob, G. Humphreys, "Physically Based Rendering", 4th ed.,
A.5.6 (piecewise-constant 2-D distributions) and 12.5 (image infinite lights).
"""

import warp as wp

from .sampling import PI, TWO_PI

#: 2π², the Jacobian |dω / (du dv)| / sinθ of the lat-long map
TWO_PI_SQ = wp.constant(19.739208802178717)
#: largest float32 below 1: a uniform variate is clamped to it so it never selects past the last entry
ONE_MINUS_EPS = wp.constant(0.99999994)


@wp.struct
class Dist2DSample:
    uv: wp.vec2  # point in the unit square
    pdf: float  # density over the unit square
    texel: int  # row * W + column of the texel holding uv


@wp.struct
class LatLongSample:
    wi: wp.vec3  # unit direction
    pdf: float  # solid-angle density, sr⁻¹ (0: not sampleable)
    texel: int  # row * W + column


@wp.func
def cdf_interval(cdf: wp.array(dtype=float), start: int, n: int, u: float) -> int:
    """Largest ``k`` in [0, n − 1] with ``cdf[start + k] <= u``: the interval
    ``[cdf[k], cdf[k+1])`` holding ``u``. Empty intervals (zero probability)
    are never returned for ``0 <= u < 1``, since a later entry equal to
    ``cdf[k]`` also satisfies the test."""
    lo = int(0)
    hi = n - 1
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if cdf[start + mid] <= u:
            lo = mid
        else:
            hi = mid - 1
    return lo


@wp.func
def sample_piecewise_2d(
    marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, u: wp.vec2
) -> Dist2DSample:
    """Point of the unit square with density ∝ the tabulated texel weights;
    ``u[0]`` picks the row, ``u[1]`` the column. pdf: :func:`pdf_piecewise_2d`."""
    s = Dist2DSample()
    u0 = wp.min(wp.max(u[0], 0.0), ONE_MINUS_EPS)
    u1 = wp.min(wp.max(u[1], 0.0), ONE_MINUS_EPS)
    j = cdf_interval(marg, 0, h, u0)
    pm = marg[j + 1] - marg[j]
    row = j * (w + 1)
    i = cdf_interval(cond, row, w, u1)
    pc = cond[row + i + 1] - cond[row + i]
    fv = wp.clamp((u0 - marg[j]) / pm, 0.0, ONE_MINUS_EPS)
    fu = wp.clamp((u1 - cond[row + i]) / pc, 0.0, ONE_MINUS_EPS)
    s.uv = wp.vec2((float(i) + fu) / float(w), (float(j) + fv) / float(h))
    s.pdf = (float(h) * pm) * (float(w) * pc)
    s.texel = j * w + i
    return s


@wp.func
def pdf_piecewise_2d(
    marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, uv: wp.vec2
) -> float:
    """Density of :func:`sample_piecewise_2d` at ``uv`` (per unit square area)."""
    i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)
    j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)
    row = j * (w + 1)
    return (float(h) * (marg[j + 1] - marg[j])) * (float(w) * (cond[row + i + 1] - cond[row + i]))


# ---------------------------------------------------------------- lat-long map


@wp.func
def latlong_uv_to_direction(uv: wp.vec2, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec3:
    """Unit direction of texture coordinates ``uv`` in the map frame (ex, ey = pole, ez);
    twin of :func:`simulator.io.latlong.latlong_uv_to_direction`."""
    lon = PI * (1.0 - 2.0 * uv[0])
    theta = PI * uv[1]
    st = wp.sin(theta)
    return (st * wp.sin(lon)) * ex + wp.cos(theta) * ey + (st * wp.cos(lon)) * ez


@wp.func
def direction_to_latlong_uv(d: wp.vec3, ex: wp.vec3, ey: wp.vec3, ez: wp.vec3) -> wp.vec2:
    """Texture coordinates of unit direction ``d``; twin of
    :func:`simulator.io.latlong.direction_to_latlong_uv`."""
    lx = wp.dot(d, ex)
    ly = wp.dot(d, ey)
    lz = wp.dot(d, ez)
    lon = wp.atan2(lx, lz)
    # θ from atan2 keeps precision near the poles, where acos(ly) does not
    theta = wp.atan2(wp.sqrt(lx * lx + lz * lz), ly)
    return wp.vec2(0.5 - lon / TWO_PI, theta / PI)


@wp.func
def latlong_texel(uv: wp.vec2, w: int, h: int) -> int:
    """``row * W + column`` of the texel holding ``uv`` (nearest lookup)."""
    i = wp.clamp(int(uv[0] * float(w)), 0, w - 1)
    j = wp.clamp(int(uv[1] * float(h)), 0, h - 1)
    return j * w + i


@wp.func
def sample_latlong(
    marg: wp.array(dtype=float),
    cond: wp.array(dtype=float),
    w: int,
    h: int,
    ex: wp.vec3,
    ey: wp.vec3,
    ez: wp.vec3,
    u: wp.vec2,
) -> LatLongSample:
    """Direction drawn from the map's 2-D distribution; solid-angle pdf
    ``pdf_uv / (2π² sinθ)`` (0 exactly on a pole, where sinθ = 0)."""
    ds = sample_piecewise_2d(marg, cond, w, h, u)
    s = LatLongSample()
    s.wi = latlong_uv_to_direction(ds.uv, ex, ey, ez)
    s.texel = ds.texel
    sin_t = wp.sin(PI * ds.uv[1])
    s.pdf = 0.0
    if sin_t > 0.0:
        s.pdf = ds.pdf / (TWO_PI_SQ * sin_t)
    return s


@wp.func
def pdf_latlong(
    marg: wp.array(dtype=float),
    cond: wp.array(dtype=float),
    w: int,
    h: int,
    ex: wp.vec3,
    ey: wp.vec3,
    ez: wp.vec3,
    d: wp.vec3,
) -> float:
    """Solid-angle density with which :func:`sample_latlong` draws unit direction ``d``."""
    lx = wp.dot(d, ex)
    lz = wp.dot(d, ez)
    sin_t = wp.sqrt(lx * lx + lz * lz)
    if sin_t <= 0.0:
        return 0.0
    uv = direction_to_latlong_uv(d, ex, ey, ez)
    return pdf_piecewise_2d(marg, cond, w, h, uv) / (TWO_PI_SQ * sin_t)
