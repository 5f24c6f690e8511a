"""Light probes: incident radiance over the whole sphere, one lat-long pixel at a time.

One kernel, :func:`probe_kernel` (one per trace variant, :func:`make_probe_kernel`),
estimates for every pixel of a probe's lat-long map the mean radiance
arriving from the pixel's solid angle, and alongside it the per-sample
integrands of the probe's sphere integrals:

=====  ==========================  ===============================================
q      integrand f(ω)·L(ω)          its integral over the sphere
=====  ==========================  ===============================================
0      L                            scalar irradiance (fluence rate) ∫ L dω
1–6    L·max(0, ±ω·axis)            face irradiance on +X, −X, +Y, −Y, +Z, −Z
7–9    L·ω                          vector irradiance ∫ L ω dω (x, y, z)
10–18  L·Y_lm(ω)                    real spherical-harmonic coefficients, l ≤ 2
19–21  L·(x+y), L·(x+z), L·(y+z)    pair sums of 7–9: their variances give the
                                    covariances of the vector irradiance
                                    (Var(a+b) = Var a + Var b + 2 Cov(a, b))
=====  ==========================  ===============================================

(ω in the world frame). Directions are stratified: every *pass* draws one
direction in each pixel, uniform in solid angle within it (longitude uniform,
sine of latitude uniform: pdf 1/Ω_pixel, :func:`sample_latlong_pixel` and
:func:`pdf_latlong_pixel`). A pass is therefore an unbiased estimate
Σ_pixels Ω·f(ω)·L(ω) of each integral, and the passes are independent. The
radiance along a direction is the trace variant's ``sample_radiance``
(:func:`~simulator.kernels.estimators.make_trace`) of a zero-width
radiance meter: emitters seen straight along it, and at the first surface
its emission plus ρ/π times an estimate of its irradiance by the run's
method (light, bsdf, mis or path).

Delta lights (point lights, angle-0 distant lights) fill no solid angle, so
no direction sample sees them. With ``mode = 1`` the kernel instead adds
their exact contribution to the integrals (next-event estimation with a
shadow ray): a light of normal irradiance E⊥ = I/d² (point) or E⊥ (distant)
from direction ω contributes E⊥·f(ω) to integral q. The map never shows
them. In a spectral run each channel is the response to the light's
spectrum, through coloured panes at every grid wavelength
(:func:`delta_responses`): exact, and what the hero lanes of every other
sensor estimate.

Real spherical harmonics, l ≤ 2, in the order (l, m) = (0,0), (1,−1), (1,0),
(1,1), (2,−2), (2,−1), (2,0), (2,1), (2,2), with ω = (x, y, z):
Y00 = ½√(1/π); Y1,−1 = √(3/4π)·y, Y10 = √(3/4π)·z, Y11 = √(3/4π)·x;
Y2,−2 = ½√(15/π)·xy, Y2,−1 = ½√(15/π)·yz, Y20 = ¼√(5/π)·(3z² − 1),
Y21 = ½√(15/π)·xz, Y22 = ¼√(15/π)·(x² − y²)
(R. Ramamoorthi, P. Hanrahan, "An Efficient Representation for Irradiance
Environment Maps", SIGGRAPH 2001, eq. 3; P.-P. Sloan, "Stupid Spherical
Harmonics (SH) Tricks", GDC 2008, appendix).
"""

import functools

import warp as wp

from simulator.scene.model import LightKind, SensorKind

from .estimators import SensorRec, TraceParams, hero_nodes, make_trace, shaping_factor, spectral_row, trace_module, unoccluded
from .lights import SceneRec
from .spectral_surfaces import transmittance_lanes
from .surfaces import transmittance_along
from .sampling import hero_stream_key, sensor_stream_key

_POINT = wp.constant(int(LightKind.POINT))
_DISTANT = wp.constant(int(LightKind.DISTANT))
_RADIANCE = wp.constant(int(SensorKind.RADIANCE))

# Forward-only: no gradients are taken, and skipping the adjoint halves compile time.
wp.set_module_options({"enable_backward": False})

#: integrands per sample (see the module docstring), each with 2 channels
N_QUANTITIES = wp.constant(22)
#: spectral transport (params.spectral): linear sRGB radiance columns after the 2·N_QUANTITIES integrands
N_COLOUR = wp.constant(3)

# SH normalisation constants (module docstring)
_SH0 = wp.constant(0.28209479177387814)  # ½√(1/π)
_SH1 = wp.constant(0.4886025119029199)  # √(3/4π)
_SH2 = wp.constant(1.0925484305920792)  # ½√(15/π)
_SH20 = wp.constant(0.31539156525252005)  # ¼√(5/π)
_SH22 = wp.constant(0.5462742152960396)  # ¼√(15/π)


@wp.struct
class ProbeRec:
    """One probe's position and its lat-long map layout.

    Pixel (i, j) (column i of ``width``, row j of ``height``, row 0 on top)
    spans longitudes [lon0 + i·dlon, lon0 + (i+1)·dlon] and latitudes
    [lat0 + j·dlat, lat0 + (j+1)·dlat] (radians; dlon and dlat may be
    negative). (lon, lat) is the direction
    (sin lon·cos lat, sin lat, cos lon·cos lat) in the map frame, whose axes
    are ``ex``, ``ey``, ``ez`` in the world frame (the OpenEXR lat-long
    convention: latitude +π/2 along ey, (0, 0) along ez, (0, π/2) along ex).
    """

    position: wp.vec3
    ex: wp.vec3
    ey: wp.vec3
    ez: wp.vec3
    width: int
    height: int
    lon0: float
    dlon: float
    lat0: float
    dlat: float
    key: int  # random-stream key of the probe (sensor_stream_key(seed, sensor index))


@wp.func
def sample_latlong_pixel(u: wp.vec2, lon_a: float, lon_b: float, lat_a: float, lat_b: float) -> wp.vec3:
    """Direction (map frame) uniform in solid angle over the lat-long cell
    [lon_a, lon_b] × [lat_a, lat_b]: longitude uniform, sin(latitude) uniform
    (the area element is cos(lat) dlat dlon = d(sin lat) dlon).
    pdf: :func:`pdf_latlong_pixel`."""
    lon = lon_a + u[0] * (lon_b - lon_a)
    sa = wp.sin(lat_a)
    s = sa + u[1] * (wp.sin(lat_b) - sa)
    s = wp.clamp(s, -1.0, 1.0)
    c = wp.sqrt(wp.max(0.0, 1.0 - s * s))
    return wp.vec3(wp.sin(lon) * c, s, wp.cos(lon) * c)


@wp.func
def pdf_latlong_pixel(lon_a: float, lon_b: float, lat_a: float, lat_b: float) -> float:
    """Solid-angle pdf of :func:`sample_latlong_pixel`: 1/Ω with
    Ω = |lon_b − lon_a|·|sin lat_b − sin lat_a|."""
    return 1.0 / (wp.abs(lon_b - lon_a) * wp.abs(wp.sin(lat_b) - wp.sin(lat_a)))


@wp.func
def probe_weight(q: int, w: wp.vec3) -> float:
    """f_q(ω) of integrand q (module docstring) for the world direction ω = w."""
    x = w[0]
    y = w[1]
    z = w[2]
    if q == 0:
        return 1.0
    if q == 1:
        return wp.max(0.0, x)
    if q == 2:
        return wp.max(0.0, -x)
    if q == 3:
        return wp.max(0.0, y)
    if q == 4:
        return wp.max(0.0, -y)
    if q == 5:
        return wp.max(0.0, z)
    if q == 6:
        return wp.max(0.0, -z)
    if q == 7:
        return x
    if q == 8:
        return y
    if q == 9:
        return z
    if q == 10:
        return _SH0
    if q == 11:
        return _SH1 * y
    if q == 12:
        return _SH1 * z
    if q == 13:
        return _SH1 * x
    if q == 14:
        return _SH2 * x * y
    if q == 15:
        return _SH2 * y * z
    if q == 16:
        return _SH20 * (3.0 * z * z - 1.0)
    if q == 17:
        return _SH2 * x * z
    if q == 18:
        return _SH22 * (x * x - y * y)
    if q == 19:
        return x + y
    if q == 20:
        return x + z
    return y + z


@functools.cache
def make_delta_responses(surfaces: bool):
    """:func:`delta_responses` of one trace variant (:func:`make_probe_kernel`): with ``surfaces`` False
    a stage has no pane (``panes`` is 0), so the per-lane walk is left out of the generated code."""

    @wp.func
    def delta_responses(scene: SceneRec, li: int, p: wp.vec3, w: wp.vec3, panes: int) -> wp.vec2:
        """A spectral run's (radiometric, photopic) responses to delta light ``li`` at p (toward ω = w) per
        unit of its radiometric value, as the hero lanes take them (:func:`.spectral.spectral_contribution`)
        but exactly: the expectation over a lane's node, drawn with probability q_i/400,

            Σ_i (q_i/400) · W_c(λ_i) · S(λ_i) · T(λ_i),

        S the light's row of ``scene.spectral_emission``, W_c the response's lane weights
        (``scene.response_weights``, 400·q_c/q, so the sum is the response's own quadrature of S·T), q
        the trapezoid weights (½ at 380 and 780 nm). T(λ) is 1 unless ``panes`` is 1: then the product of
        every face's pass factor on the segment at λ, each coloured pane's at its T0(λ)
        (:func:`.spectral_surfaces.transmittance_lanes`, four grid nodes per call)."""
        l = scene.lights[li]
        dist = float(1.0e30)
        if l.kind == _POINT:
            dist = wp.length(l.position - p)
        out = wp.vec2(0.0, 0.0)
        for g in range(101):  # nodes 4g … 4g + 3 of the 401
            h = wp.vec4i(wp.min(4 * g, 400), wp.min(4 * g + 1, 400), wp.min(4 * g + 2, 400), wp.min(4 * g + 3, 400))
            t4 = wp.vec4(1.0, 1.0, 1.0, 1.0)
            if (panes != 0) if wp.static(surfaces) else False:
                t4 = transmittance_lanes(scene, h, p, w, dist, -1)
            s4 = spectral_row(scene.spectral_emission, li, h)
            for k in range(4):
                node = 4 * g + k
                if node <= 400:
                    q = float(1.0 / 400.0)
                    if node == 0 or node == 400:
                        q = 0.5 / 400.0
                    for c in range(2):
                        out[c] = out[c] + q * scene.response_weights[c, node] * s4[k] * t4[k]
        return out

    return delta_responses


@wp.func
def accumulate(t: int, q: int, first: int, v: wp.vec2, out_shift: wp.array2d(dtype=wp.float64),
               out_sum: wp.array2d(dtype=wp.float64), out_sumsq: wp.array2d(dtype=wp.float64)):  # fmt: skip
    """Shifted sums Σ(x − K), Σ(x − K)² of integrand q (both channels), K the first sample."""
    for c in range(2):
        k = 2 * q + c
        x = wp.float64(v[c])
        if first != 0:
            out_shift[t, k] = x
            out_sum[t, k] = wp.float64(0.0)
            out_sumsq[t, k] = wp.float64(0.0)
        dx = x - out_shift[t, k]
        out_sum[t, k] = out_sum[t, k] + dx
        out_sumsq[t, k] = out_sumsq[t, k] + dx * dx


@wp.func
def accumulate_one(t: int, k: int, first: int, x: wp.float64, out_shift: wp.array2d(dtype=wp.float64),
                   out_sum: wp.array2d(dtype=wp.float64), out_sumsq: wp.array2d(dtype=wp.float64)):  # fmt: skip
    """Shifted sums of one column ``k`` (as :func:`accumulate`)."""
    if first != 0:
        out_shift[t, k] = x
        out_sum[t, k] = wp.float64(0.0)
        out_sumsq[t, k] = wp.float64(0.0)
    dx = x - out_shift[t, k]
    out_sum[t, k] = out_sum[t, k] + dx
    out_sumsq[t, k] = out_sumsq[t, k] + dx * dx


@functools.cache
def make_probe_kernel(surfaces: bool):
    """:func:`probe_kernel` of one trace variant (:func:`.estimators.make_trace`): its radiance
    samples are that variant's ``sample_radiance``, and with ``surfaces`` False the panes and
    cut-outs on a delta light's segment are left out of the generated code."""
    sample_radiance = make_trace(surfaces).sample_radiance
    delta_responses = make_delta_responses(surfaces)

    @wp.func
    def delta_visibility(scene: SceneRec, p: wp.vec3, w: wp.vec3, dist: float) -> float:
        """1 or 0 for an open or blocked segment; through panes and cut-outs the share they pass."""
        if (scene.surfaces != 0) if wp.static(surfaces) else False:
            return transmittance_along(scene, p, w, dist, -1)
        if unoccluded(scene, p, w, dist, -1):
            return 1.0
        return 0.0

    @wp.func
    def delta_incident(scene: SceneRec, li: int, p: wp.vec3, open_segment: int) -> wp.vec4:
        """(ω, E⊥) of delta light ``li`` at p: the unit direction toward it in the
        first three components and the normal irradiance it gives (radiometric)
        in the fourth; use :func:`delta_scale` for the photometric twin. Zero if
        the light is not a delta light or is blocked. With ``open_segment`` 1 the
        segment is not traced (E⊥ as if open: :func:`delta_responses` then takes
        what it passes)."""
        l = scene.lights[li]
        if l.kind == _POINT:
            d = l.position - p
            dist = wp.length(d)
            if dist <= 0.0:
                return wp.vec4(0.0)
            w = d / dist
            vis = float(1.0)
            if open_segment == 0:
                vis = delta_visibility(scene, p, w, dist)
            if vis <= 0.0:
                return wp.vec4(0.0)
            return wp.vec4(w[0], w[1], w[2], vis * shaping_factor(l, -w) / (dist * dist))  # E⊥ = I(ω)/d²
        if l.kind == _DISTANT and l.one_minus_cos <= 0.0:
            vis = float(1.0)
            if open_segment == 0:
                vis = delta_visibility(scene, p, l.ez, 1.0e30)
            if vis <= 0.0:
                return wp.vec4(0.0)
            return wp.vec4(l.ez[0], l.ez[1], l.ez[2], vis)  # E⊥ is the emission itself (× what panes pass)
        return wp.vec4(0.0)

    @wp.kernel(module=trace_module(surfaces))  # beside the variant's estimate_kernel: their functions compile once
    def probe_kernel(
        scene: SceneRec,
        probe: ProbeRec,
        params: TraceParams,
        mode: int,
        first_pass: int,
        n_passes: int,
        pass_block: int,
        blocks: int,
        pixel_first: int,
        offset: int,
        out_shift: wp.array2d(dtype=wp.float64),
        out_sum: wp.array2d(dtype=wp.float64),
        out_sumsq: wp.array2d(dtype=wp.float64),
        out_bad: wp.array(dtype=wp.int32),
    ):
        """``mode`` 0: thread t (= tid + offset) draws passes
        [first_pass + b·pass_block, …) (at most ``pass_block``, within
        ``n_passes``) of pixel pixel_first + t // blocks, b = t mod blocks, and
        writes the shifted sums of the 22 integrands (row t, column 2q + channel). Sample k of pixel p always uses the random stream
        ``rand_init(sensor_stream_key(probe.key, p), k)``, whatever the batch
        layout. ``mode`` 1 (one thread): writes the delta lights' exact
        contributions to the integrals in ``out_sum[0]`` (shift and squares 0).

        Spectral transport (``params.spectral``): each direction carries hero
        wavelengths drawn from the pixel's wavelength stream
        (``hero_stream_key``), the integrands are its radiometric and photopic
        responses, and columns 2·N_QUANTITIES + c (c = 0, 1, 2) take its linear
        sRGB radiance (``scene.colour_weights``, cd/m²); delta lights, which the
        map cannot show, add nothing there."""
        t = wp.tid() + offset
        if mode == 1:
            for k in range(out_shift.shape[1]):
                out_shift[t, k] = wp.float64(0.0)
                out_sum[t, k] = wp.float64(0.0)
                out_sumsq[t, k] = wp.float64(0.0)
            out_bad[t] = 0
            # delta lights are direct light; method bsdf cannot see them (as for every sensor)
            if params.nee == 0 or params.skip_direct != 0:
                return
            # spectral runs: each channel the response to the light's spectrum (through coloured panes at
            # every wavelength), as the lanes of every other sensor read it
            per_lane = wp.where(params.spectral != 0 and scene.spectral_panes != 0, 1, 0)
            for li in range(scene.n_lights):
                inc = delta_incident(scene, li, probe.position, per_lane)
                if inc[3] > 0.0:
                    w = wp.vec3(inc[0], inc[1], inc[2])
                    e = scene.lights[li].emission * inc[3]
                    if params.spectral != 0:
                        e = (scene.lights[li].emission[0] * inc[3]) * delta_responses(scene, li, probe.position, w,
                                                                                       per_lane)
                    for q in range(N_QUANTITIES):
                        f = probe_weight(q, w)
                        for c in range(2):
                            out_sum[t, 2 * q + c] = out_sum[t, 2 * q + c] + wp.float64(f * e[c])
            return
        b = t % blocks
        pix = pixel_first + t // blocks
        i = pix % probe.width
        j = pix // probe.width
        start = first_pass + b * pass_block
        end = wp.min(start + pass_block, first_pass + n_passes)
        lon_a = probe.lon0 + float(i) * probe.dlon
        lat_a = probe.lat0 + float(j) * probe.dlat
        key = sensor_stream_key(probe.key, pix)
        s = SensorRec()
        s.kind = _RADIANCE
        s.position = probe.position
        s.one_minus_cos = 0.0
        bad = int(0)
        prm = params
        prm.thread = t
        for k in range(start, end):
            rng = wp.rand_init(key, k)
            loc = sample_latlong_pixel(wp.vec2(wp.randf(rng), wp.randf(rng)), lon_a, lon_a + probe.dlon, lat_a, lat_a + probe.dlat)
            w = wp.normalize(loc[0] * probe.ex + loc[1] * probe.ey + loc[2] * probe.ez)
            s.normal = w
            if params.spectral != 0:
                prm.hero = hero_nodes(wp.randf(wp.rand_init(hero_stream_key(key), k)))
                scene.response_lanes[t] = wp.vec4(0.0, 0.0, 0.0, 0.0)
            v = sample_radiance(scene, s, prm, rng)
            lanes = wp.vec4(0.0, 0.0, 0.0, 0.0)
            ok = wp.isfinite(v[0]) and wp.isfinite(v[1])
            if params.spectral != 0:
                lanes = scene.response_lanes[t]
                ok = ok and wp.isfinite(wp.dot(lanes, lanes))
            if not ok:
                bad += 1
                v = wp.vec2(0.0, 0.0)
                lanes = wp.vec4(0.0, 0.0, 0.0, 0.0)
            first = wp.where(k == start, 1, 0)
            for q in range(N_QUANTITIES):
                accumulate(t, q, first, probe_weight(q, w) * v, out_shift, out_sum, out_sumsq)
            if params.spectral != 0:
                for c in range(N_COLOUR):
                    x = 0.25 * wp.dot(spectral_row(scene.colour_weights, c, prm.hero), lanes)
                    accumulate_one(t, 2 * N_QUANTITIES + c, first, wp.float64(x), out_shift, out_sum, out_sumsq)
        out_bad[t] = bad

    return probe_kernel


def probe_kernel_for(surfaces: int):
    """The probe kernel for a stage whose ``SceneRec.surfaces`` is ``surfaces`` (:func:`.estimators.trace_for`),
    built with its trace variant on first use."""
    return make_probe_kernel(surfaces != 0)
