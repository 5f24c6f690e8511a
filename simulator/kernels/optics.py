"""A sensor model's angular response at the sensor's own vertex: the record, r(ω), and its sampler with its pdf.

A modelled sensor (:mod:`simulator.sensor_models`) reads ∫ L(ω) r(ω) dω
instead of the irradiance ∫ L(ω) cosθ dω: r is the head's relative
response to a collimated beam, 1 at normal incidence. At the first vertex
of its paths (the sensor itself, ``TraceParams.optics`` > 0) the
estimators weigh a light sample by r(ω)/cosθ (its value carries the
cosine) and draw their direction by r instead of by the cosine, with the
density :func:`pdf_optics` in every MIS weight (kernels.estimators,
``vertex_estimate``). Every later vertex is a surface and keeps its cosine.

Two forms, one record (:class:`OpticsRec`), in the frame of the sensor
(x: ``TraceParams.optics_x``, the azimuth origin; z: its normal):

- ``kind`` 1, a power of the cosine: r = cos^n θ. Drawn exactly: with
  μ = cosθ = u₀^(1/(n+1)) and φ = 2π u₁ the density is (n + 1) μⁿ / 2π, so
  r/pdf = 2π/(n + 1), the same for every direction.
- ``kind`` 0, a table: r linear in θ between the knots ``theta`` (radians,
  from 0) and, with azimuth columns (``n_phi`` > 1), linear in φ between the
  knots ``phi`` (radians in [0, 2π), periodic); 0 past the last θ knot.
  Drawn from a piecewise-constant 2-D table over (θ bin, φ bin) built on the
  host (``marg``, ``cond``: :func:`.distributions.sample_piecewise_2d`'s
  CDFs, each bin's weight its integral of r, at least the largest r in it
  times a little, so every direction with r > 0 can be drawn): row j spans
  θ ∈ [j, j + 1)·``d_theta``, column i φ ∈ [i, i + 1)·2π/``cols``, and within
  a bin μ and φ are uniform (uniform in solid angle). Its pdf is the bin's
  probability over its solid angle, P_ji / (Δμ_j · 2π/cols), with Δμ_j
  (``row_dmu``) and the row's top μ (``row_mu``) computed on the host in
  float64 (cos θ_j − cos θ_{j+1} cancels in float32 near the normal).

References
----------
M. Pharr, W. Jakob, G. Humphreys, "Physically Based Rendering", 4th ed.,
A.5.6 (piecewise-constant 2-D distributions).
"""

import warp as wp

from .distributions import pdf_piecewise_2d, sample_piecewise_2d
from .sampling import TWO_PI, frame_x


@wp.struct
class OpticsRec:
    """One angular response on the device (host: :func:`simulator.sensor_models.angular.AngularResponse`)."""

    kind: int  # 0: a table; 1: cos^exponent
    exponent: float  # kind 1: n of cos^n θ
    integral: float  # ∫ r dω over the hemisphere, sr (π for the cosine): the scale of the head's path weights
    n_theta: int  # table knots in θ
    n_phi: int  # table knots in φ (1: rotationally symmetric)
    theta: wp.array(dtype=float)  # (n_theta,) radians, increasing from 0
    phi: wp.array(dtype=float)  # (n_phi,) radians in [0, 2π), increasing
    values: wp.array(dtype=float)  # (n_phi × n_theta): r at (phi[k], theta[j]) at k·n_theta + j
    rows: int  # θ bins of the sampling table
    cols: int  # φ bins of the sampling table
    d_theta: float  # width of a θ bin, radians
    marg: wp.array(dtype=float)  # (rows + 1): marginal CDF over θ bins
    cond: wp.array(dtype=float)  # (rows × (cols + 1)): conditional CDFs over φ bins
    row_mu: wp.array(dtype=float)  # (rows,): cos of each θ bin's top (its smaller θ)
    row_dmu: wp.array(dtype=float)  # (rows,): cos θ_j − cos θ_{j+1}, > 0
    cos_field: float  # cos of the field's half-angle for light samples at the head (< 0.5: a wide head, see optics_narrow)
    field_exact: int  # 1: r = 0 past the field (a table's last knot); 0: r is only small there (cosⁿ)


@wp.struct
class OpticsSample:
    local: wp.vec3  # unit direction in the sensor's frame (z: its normal)
    pdf: float  # solid-angle density, sr⁻¹
    weight: float  # r(local) / pdf: the direction's estimate of ∫ L r dω per unit radiance


@wp.func
def optics_frame_x(x_ref: wp.vec3, n: wp.vec3) -> wp.vec3:
    """The azimuth origin in the plane of ``n``: ``x_ref`` made orthogonal to it (the host sends a unit
    vector orthogonal already), or the frame of :func:`.sampling.frame_x` where that leaves nothing."""
    x = x_ref - wp.dot(x_ref, n) * n
    l2 = wp.dot(x, x)
    if l2 < 1.0e-12:
        return frame_x(n)
    return x / wp.sqrt(l2)


@wp.func
def optics_to_world(local: wp.vec3, x: wp.vec3, n: wp.vec3) -> wp.vec3:
    """A direction of the sensor's frame (x, n × x, n) in the world."""
    return local[0] * x + local[1] * wp.cross(n, x) + local[2] * n


@wp.func
def optics_to_local(v: wp.vec3, x: wp.vec3, n: wp.vec3) -> wp.vec3:
    """World direction ``v`` in the sensor's frame (inverse of :func:`optics_to_world`)."""
    return wp.vec3(wp.dot(v, x), wp.dot(v, wp.cross(n, x)), wp.dot(v, n))


@wp.func
def knot_interval(a: wp.array(dtype=float), n: int, x: float) -> int:
    """Largest k in [0, n − 2] with a[k] ≤ x (a increasing, n ≥ 2): the interval holding x, the ends
    extended."""
    lo = int(0)
    hi = n - 2
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if a[mid] <= x:
            lo = mid
        else:
            hi = mid - 1
    return lo


@wp.func
def table_column(o: OpticsRec, k: int, theta: float) -> float:
    """r along azimuth knot ``k`` at ``theta``: linear between θ knots, 0 past the last."""
    if theta > o.theta[o.n_theta - 1]:
        return 0.0
    j = knot_interval(o.theta, o.n_theta, theta)
    t0 = o.theta[j]
    t1 = o.theta[j + 1]
    f = wp.clamp((theta - t0) / (t1 - t0), 0.0, 1.0)
    base = k * o.n_theta
    return o.values[base + j] + f * (o.values[base + j + 1] - o.values[base + j])


@wp.func
def optics_response(o: OpticsRec, local: wp.vec3) -> float:
    """r(ω) for ``local`` in the sensor's frame: 0 behind the sensor (z ≤ 0)."""
    z = local[2]
    if z <= 0.0:
        return 0.0
    if o.kind == 1:
        return wp.pow(wp.min(z, 1.0), o.exponent)
    s = wp.sqrt(local[0] * local[0] + local[1] * local[1])
    theta = wp.atan2(s, z)  # accurate near the normal, where acos(z) is not
    if o.n_phi <= 1:
        return table_column(o, 0, theta)
    phi = wp.atan2(local[1], local[0])
    if phi < 0.0:
        phi = phi + TWO_PI
    # the azimuth interval, periodic: past the last knot, toward the first + 2π
    k0 = o.n_phi - 1
    k1 = int(0)
    p0 = o.phi[o.n_phi - 1]
    p1 = o.phi[0] + TWO_PI
    if phi < o.phi[0]:
        p0 = p0 - TWO_PI
        p1 = o.phi[0]
    elif phi < o.phi[o.n_phi - 1]:
        k0 = knot_interval(o.phi, o.n_phi, phi)
        k1 = k0 + 1
        p0 = o.phi[k0]
        p1 = o.phi[k1]
    f = wp.clamp((phi - p0) / (p1 - p0), 0.0, 1.0)
    r0 = table_column(o, k0, theta)
    r1 = table_column(o, k1, theta)
    return r0 + f * (r1 - r0)


@wp.func
def sample_optics(o: OpticsRec, u: wp.vec2) -> OpticsSample:
    """A direction of the sensor's frame drawn by its response (see module docstring); pdf:
    :func:`pdf_optics`."""
    s = OpticsSample()
    mu = float(1.0)
    phi = TWO_PI * u[1]
    if o.kind == 1:
        mu = wp.pow(wp.max(u[0], 1.0e-30), 1.0 / (o.exponent + 1.0))
    else:
        ds = sample_piecewise_2d(o.marg, o.cond, o.cols, o.rows, u)  # u[0] the θ bin, u[1] the φ bin
        j = ds.texel // o.cols
        fv = wp.clamp(ds.uv[1] * float(o.rows) - float(j), 0.0, 1.0)
        mu = o.row_mu[j] - fv * o.row_dmu[j]
        phi = TWO_PI * ds.uv[0]
    sin_t = wp.sqrt(wp.max(0.0, 1.0 - mu * mu))
    s.local = wp.vec3(sin_t * wp.cos(phi), sin_t * wp.sin(phi), mu)
    if o.kind == 1:
        s.pdf = pdf_optics(o, s.local)
    else:  # the bin's own density (pdf_optics finds the same bin but for rounding at its edges)
        s.pdf = ds.pdf / (float(o.rows) * o.row_dmu[j] * TWO_PI)
    s.weight = 0.0
    if s.pdf > 0.0:
        s.weight = optics_response(o, s.local) / s.pdf
    return s


@wp.func
def pdf_optics(o: OpticsRec, local: wp.vec3) -> float:
    """Solid-angle density with which :func:`sample_optics` draws ``local`` (0 behind the sensor)."""
    z = local[2]
    if z <= 0.0:
        return 0.0
    if o.kind == 1:
        return (o.exponent + 1.0) / TWO_PI * wp.pow(wp.min(z, 1.0), o.exponent)
    theta = wp.atan2(wp.sqrt(local[0] * local[0] + local[1] * local[1]), z)
    j = int(theta / o.d_theta)
    if j >= o.rows:
        return 0.0
    fv = wp.clamp((o.row_mu[j] - z) / o.row_dmu[j], 0.0, 0.99999994)
    phi = wp.atan2(local[1], local[0])
    if phi < 0.0:
        phi = phi + TWO_PI
    uv = wp.vec2(wp.clamp(phi / TWO_PI, 0.0, 0.99999994), (float(j) + fv) / float(o.rows))
    return pdf_piecewise_2d(o.marg, o.cond, o.cols, o.rows, uv) / (float(o.rows) * o.row_dmu[j] * TWO_PI)


@wp.func
def optics_weight(o: OpticsRec, x: wp.vec3, n: wp.vec3, wi: wp.vec3) -> float:
    """r(ω)/cosθ for the world direction ``wi``: a light sample's value carries cosθ (L·cosθ/pdf), the
    head reads L·r(ω)/pdf. 0 behind the sensor."""
    c = wp.dot(wi, n)
    if c <= 0.0:
        return 0.0
    return optics_response(o, optics_to_local(wi, x, n)) / c


@wp.func
def optics_pdf(o: OpticsRec, x: wp.vec3, n: wp.vec3, wi: wp.vec3) -> float:
    """:func:`pdf_optics` of the world direction ``wi`` (the density MIS weighs a light sample against)."""
    return pdf_optics(o, optics_to_local(wi, x, n))


@wp.func
def optics_narrow(o: OpticsRec) -> bool:
    """Whether light samples at the head's vertex are drawn toward its response (a rect light's,
    kernels.lights.rect.sample_field): a field under 60° (wider heads gain little over the plain sample)."""
    return o.cos_field >= 0.5


@wp.func
def optics_field(o: OpticsRec, mis: int) -> float:
    """cos α of the cone within which a narrow head's light samples are drawn (a rect light's part in it,
    kernels.lights.rect.field_window), or −1: over the whole light. A table head is 0 past its last knot,
    so any estimator may leave the rest out; a cosⁿ head's r is only small past its field (r ≤
    ``FIELD_RESPONSE``), so only where MIS (``mis`` ≠ 0) gives that rest to the directions drawn by r,
    which reach every direction with r > 0."""
    if o.field_exact == 0 and mis == 0:
        return -1.0
    return o.cos_field


# ---------------------------------------------------------------- host

#: a cosⁿ head's field for light samples: where r falls to this; past it (a share cos^{n+1}α ≈ FIELD_RESPONSE
#: of ∫r dω) only the directions drawn by r reach a light (docs/DESIGN.md §Sensor models, narrow fields)
FIELD_RESPONSE = 0.01
#: a table head's field: its last knot, widened by this (radians) against float32 rounding of the window
FIELD_MARGIN_RAD = 0.005


def optics_record(response, keep: list) -> OpticsRec:
    """The device record of an :class:`simulator.sensor_models.angular.AngularResponse`; the arrays it
    points to are appended to ``keep`` (they must outlive the record)."""
    import numpy as np

    r = OpticsRec()
    r.integral = float(response.integral_sr())

    def arr(a):
        a = np.ascontiguousarray(np.asarray(a, np.float64).reshape(-1).astype(np.float32))
        out = wp.array(a if a.size else np.zeros(1, np.float32), dtype=float)
        keep.append(out)
        return out

    if response.kind == "power":
        r.cos_field, r.field_exact = float(FIELD_RESPONSE ** (1.0 / float(response.exponent))), 0
        r.kind, r.exponent = 1, float(response.exponent)
        r.n_theta, r.n_phi, r.rows, r.cols, r.d_theta = 0, 1, 1, 1, 1.0
        r.theta = r.phi = r.values = r.marg = r.cond = r.row_mu = r.row_dmu = arr([0.0])
        return r
    t = response.sampling_tables()
    r.cos_field = float(np.cos(min(np.pi / 2, np.radians(response.theta_deg[-1]) + FIELD_MARGIN_RAD)))
    r.field_exact = 1
    r.kind, r.exponent = 0, 0.0
    r.n_theta, r.n_phi = len(response.theta_deg), len(response.phi_deg)
    r.theta = arr(np.radians(response.theta_deg))
    r.phi = arr(np.radians(response.phi_deg))
    r.values = arr(response.values)
    r.rows, r.cols, r.d_theta = int(t["rows"]), int(t["cols"]), float(t["d_theta"])
    r.marg, r.cond = arr(t["marg"]), arr(t["cond"])
    r.row_mu, r.row_dmu = arr(t["row_mu"]), arr(t["row_dmu"])
    return r


def no_optics(keep: list) -> OpticsRec:
    """A placeholder record (the scene's table when no sensor has a model): never read."""
    from simulator.sensor_models.angular import cos_power

    return optics_record(cos_power(1.0), keep)
