"""Monte Carlo estimators of sensor readings: the Warp kernel entry point.

One kernel, :func:`estimate_kernel`, serves every sensor kind and every
sampling method; :class:`TraceParams` switches the strategies, so the module
compiles once and the kernel cache serves every run.

Measured quantity per sample (both radiometric and photometric channels):

- irradiance sensor: an unbiased estimate of E(p, n) = ∫ L(p, ω) cosθ dω (W/m²);
- patch: E at a point drawn uniformly on the rectangle; its mean is the
  patch's mean irradiance, and × area its flux (W);
- radiance meter: L arriving along a direction drawn uniformly in the cone
  (W m⁻² sr⁻¹): emitters seen directly, plus, at the first surface, its
  emission and ρ/π · E(surface), E estimated as for an irradiance sensor.

Irradiance at a vertex is estimated by the strategies the method enables:

- next-event estimation (``nee``): every light sampled once, shadow ray;
- cosine-weighted directions (``bsdf``): E ≈ π·L(ω); counts the emitters hit;
- both at once (``mis``): power-heuristic weights (β = 2, Veach 1997 §9.2.3);
- interreflection (``bounces`` ≠ 0): at a surface hit the path's throughput
  β (relative to the first vertex) is multiplied by the albedo ρ; while
  β ≥ ``params.rr_threshold`` the path simply goes on, below it Russian roulette
  lets it survive with probability β/rr_threshold and lifts β back to the
  threshold (a weight window: unbiased, since E[β'] = β), played at a vertex
  after its next-event estimate, so no fixed bounce limit truncates the light;
- guided paths (``guide_c`` > 0): the next vertex drawn, with probability c,
  on surface patches a pilot found bright (``sample_guide``), combined with
  the cosine direction by one-sample MIS (see vertex_irradiance).

References
----------
E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD
thesis, Stanford, 1997, ch. 9 (multiple importance sampling).
J. Arvo, D. Kirk, "Particle transport and image synthesis", SIGGRAPH 1990
(Russian roulette).
"""

import math
from dataclasses import dataclass
from typing import Any, Callable

import warp as wp

from simulator.scene.model import LightKind, Sensor, SensorKind

from .lights import (  # noqa: F401  (GuideRec, LightRec, SceneRec re-exported for the engine)
    RAY_INF,
    GuideRec,
    LightRec,
    LightSample,
    SceneRec,
    analytic_light,
    analytic_patch_light,
    escaped_radiance,
    hit_light,
    kind_chain,
    light_within,
    pdf_light,
    sample_light,
    tri_emitted,
    tri_vertex,
)
from .light_pick import LightPick, importance, is_delta, light_estimate, pick_light, pick_probability
from .sampling import (
    INV_PI,
    PI,
    pdf_cosine_hemisphere,
    sample_cosine_hemisphere,
    sample_triangle_bary,
    sample_uniform_cone,
    hero_stream_key,
    sensor_stream_key,
    to_world,
)

# Forward-only: no gradients are taken, and skipping the adjoint halves compile time.
wp.set_module_options({"enable_backward": False})

# A path whose every bounce survives Russian roulette with probability ρ < 1
# ends with probability one; this cap only guards against ρ rounding to 1.
# At ρ = 0.999 it drops a fraction 0.999^65536 ≈ 4e-29 of the light.
MAX_VERTICES = wp.constant(65536)

# Russian roulette weight window: a path's throughput β never falls below
# TraceParams.rr_threshold (see vertex_irradiance); the engine sets it per
# run from the scene's albedo, by the rule and the measurements at
# simulator.engine.methods.rr_threshold_rule (0.1 in a room, down to 0.01 in
# an enclosure of high albedo).


@wp.struct
class SensorRec:
    kind: int
    position: wp.vec3
    normal: wp.vec3  # faces the light it measures; look direction for radiance
    right: wp.vec3  # patch width axis
    up: wp.vec3  # patch height axis
    width: float
    height: float
    one_minus_cos: float  # radiance cone: 1 − cos(half-angle); 0 = one direction
    cull: int  # 1: the first vertex is the sensor, so the plan's light mask applies there


@wp.struct
class TraceParams:
    nee: int  # sample every light at each vertex
    bsdf: int  # follow cosine-weighted directions and count emitters they hit
    mis: int  # weight the two by the power heuristic
    bounces: int  # surface interactions to follow: 0 = direct only, −1 = unbounded
    skip_direct: int  # 1: leave out light that reaches the sensor without a reflection (indirect only)
    emissive_light: int  # index of the EMISSIVE light record, −1 if none
    seed: int
    count_rays: int  # 1: count traced rays per thread in scene.ray_counts (benchmarks)
    thread: int  # set by the kernel for each thread
    mask_row: int  # set by the kernel: the sensor whose light mask applies at vertex 0, −1 for none
    spectral: int  # 1: hero-wavelength transport (scene.spectral_* tables, response tallies)
    hero: wp.vec4i  # set by the kernel per sample: the 4 hero wavelengths' grid nodes (0…400)
    tint: wp.vec4  # spectral throughput / β per hero lane where a path starts (mean 1; ones at a sensor)
    # -- light-group tallies (see light_contribution and fold_group_sample); unused while group_tally is 0.
    # Groups of the light records: SceneRec.light_group. One array holds a thread's state, G·(G + 3)
    # slots from thread·G·(G + 3): this sample's light per group (G), K_g the thread's first sample
    # per group (G), Σ(x_g − K_g) (G), Σ(x_g − K_g)(x_h − K_h) at g·G + h, h ≤ g (G × G).
    group_tally: int  # 1: tally each sample's light per group as well as its total
    n_groups: int  # G
    group_state: wp.array(dtype=wp.vec2d)  # (threads × G·(G + 3))
    guide_c: float  # guided paths: probability of sampling the surface guide at a vertex (0: plain paths)
    guide_first: int  # the guide is used at vertices of depth ≥ guide_first ...
    guide_depth: int  # ... and < guide_depth (−1: no upper bound)
    tally: int  # 1: add each surface vertex's next-event contributions to scene.guide.tally (the pilot)
    tally_row: int  # the row of scene.guide.tally this launch adds to (one per CPU worker: no races)
    pick_light: int  # one picked light with area (light_pick.py): 0 never, 1 at every vertex, 2 past the first
    tally_pick: int  # 1: tally the light pick's pilot sums in scene.pick_tally (a pilot run)
    rr_threshold: float  # Russian roulette weight window (engine.methods.rr_threshold_rule)


@wp.func
def power_heuristic(pdf_a: float, pdf_b: float) -> float:
    """a²/(a² + b²), formed from the ratio of the smaller pdf to the larger:
    squaring a pdf overflows float32 above 1.8e19 sr⁻¹ (a distant light of
    angle 1e-9°), and inf/inf made the weight NaN, so MIS dropped that light."""
    if pdf_a <= 0.0 and pdf_b <= 0.0:
        return 0.0
    if pdf_a >= pdf_b:
        r = pdf_b / pdf_a
        return 1.0 / (1.0 + r * r)
    r = pdf_a / pdf_b
    return r * r / (1.0 + r * r)


@wp.func
def offset_length(scene: SceneRec, p: wp.vec3) -> float:
    """How far a ray origin is pushed off a surface at p: ``scene.eps``
    relative to the coordinate's magnitude, so the push stays well above
    float32 resolution (6e-8 relative) far from the origin, and well below
    modelled gaps (0.1 mm under a lamp) near it."""
    return scene.eps * wp.max(1.0, wp.max(wp.abs(p[0]), wp.max(wp.abs(p[1]), wp.abs(p[2]))))


@wp.func
def count_ray(scene: SceneRec, params: TraceParams):
    """Tally one ray for ``probesim bench`` (a branch when counting is off)."""
    if params.count_rays != 0:
        scene.ray_counts[params.thread] = scene.ray_counts[params.thread] + 1


#: hits on planes a ray cannot cross that one query may skip (see first_hit)
MAX_SKIPS = wp.constant(4)


@wp.struct
class RayHit:
    t: float  # distance along the ray; RAY_INF when nothing is hit
    face: int  # triangle hit, −1 when none
    ng: wp.vec3  # its unit geometric normal


@wp.func
def plane_distance(scene: SceneRec, face: int, o: wp.vec3, d: wp.vec3) -> float:
    """Distance t > 0 at which the ray (o, d) meets the plane of triangle
    ``face``, or −1 when it cannot meet it ahead: o lies on the plane, or d
    is parallel to it or heads away. Solved in float64 on the float32
    vertices (exact up to ~1e-16 relative), whatever the triangle's size; a
    degenerate triangle has no plane and is never met."""
    a = wp.vec3d(tri_vertex(scene, face, 0))
    ng = wp.cross(wp.vec3d(tri_vertex(scene, face, 1)) - a, wp.vec3d(tri_vertex(scene, face, 2)) - a)
    side = wp.dot(wp.vec3d(o) - a, ng)
    dn = wp.dot(wp.vec3d(d), ng)
    if side * dn >= wp.float64(0.0):
        return -1.0
    return float(-side / dn)


@wp.func
def first_hit(scene: SceneRec, o: wp.vec3, d: wp.vec3, t_max: float) -> RayHit:
    """The first surface the ray (o, d) meets before ``t_max``.

    Warp's ray-triangle test works in float32 on vertices relative to the
    ray origin, so its error grows with the triangle's coordinates, not with
    the origin's: from a point 1e-5 m above a tilted 10 km ground plane
    (vertices 5 km out, float32 spacing 5e-4 m) it reports the plane as hit
    by rays that leave it (shadow acne: a receiver lying on the ground read
    0), and puts hits up to ~1e-4 m off the plane (a path vertex may then lie
    behind its own surface, which shadows it). So each hit's distance is
    recomputed by :func:`plane_distance`; a reported hit on a plane the ray
    cannot meet is skipped by restarting the query just past it, so
    occluders beyond are still found."""
    h = RayHit()
    h.t = RAY_INF
    h.face = -1
    h.ng = wp.vec3(0.0, 0.0, 1.0)
    if scene.has_mesh == 0:
        return h
    start = float(0.0)
    k = int(0)
    while k < MAX_SKIPS and start < t_max:
        q = wp.mesh_query_ray(scene.mesh, o + start * d, d, t_max - start)
        if not q.result:
            return h
        t = plane_distance(scene, q.face, o, d)
        if t > t_max:
            return h  # the exact crossing lies past the segment's end: nothing in the way
        if t > 0.0:
            h.t = t
            h.face = q.face
            h.ng = wp.normalize(q.normal)
            return h
        start = start + q.t + offset_length(scene, o + (start + q.t) * d)
        k += 1
    return h


@wp.func
def near_light(scene: SceneRec, p: wp.vec3, reach: float) -> bool:
    """True if the surface of a UsdLux area light lies within ``reach`` of p
    (or p is inside a sphere light). A ray origin pushed off p by ``reach``
    could then land inside or behind that light, which rays from there
    cannot see: a sensor 1 µm from a sphere light read 0 with ``bsdf``, and
    ``mis`` lost the bsdf share of its weight."""
    for li in range(scene.n_lights):
        l = scene.lights[li]
        if light_within(l, p - l.position, reach):
            return True
    return False


@wp.func
def unoccluded(scene: SceneRec, o: wp.vec3, wi: wp.vec3, dist: float, tri: int) -> bool:
    """True if nothing blocks the segment from o along wi for ``dist``. A
    sampled emissive triangle is reached when the first hit is that triangle;
    UsdLux lights are not geometry, so the segment ends on them (see
    :func:`light_end_offset`) and a surface 10⁻⁴ m in front of a lamp still
    blocks it."""
    if scene.has_mesh == 0:
        return True
    if tri >= 0:
        h = first_hit(scene, o, wi, dist * 1.001)
        return h.face < 0 or h.face == tri
    return first_hit(scene, o, wi, dist).face < 0


#: float32 unit roundoff u = 2⁻²⁴
FLOAT32_U = wp.constant(5.9604645e-08)
#: roundings bounded by LIGHT_POINT_GAMMA = γ(16) in light_point_error (see there)
LIGHT_POINT_GAMMA = wp.constant(16.0 * 5.9604645e-08 / (1.0 - 16.0 * 5.9604645e-08))
#: γ(6): the shadow segment's own reconstruction o + dist·wi (see light_end_offset)
SEGMENT_GAMMA = wp.constant(6.0 * 5.9604645e-08 / (1.0 - 6.0 * 5.9604645e-08))


# Kind integers for the flush-light error bounds below, taken from the one
# declaration (LightKind), not copied.
POINT = wp.constant(int(LightKind.POINT))
SPHERE = wp.constant(int(LightKind.SPHERE))
RECT = wp.constant(int(LightKind.RECT))
DISK = wp.constant(int(LightKind.DISK))
CYLINDER = wp.constant(int(LightKind.CYLINDER))


@wp.func
def abs3(v: wp.vec3) -> wp.vec3:
    return wp.vec3(wp.abs(v[0]), wp.abs(v[1]), wp.abs(v[2]))


@wp.func
def light_point_error(l: LightRec, p: wp.vec3, q: wp.vec3) -> wp.vec3:
    """Componentwise bound (metres) on how far the float32 light point q, as
    a shadow ray from a receiver at p ends on it, and the float32 vertices of
    a surface authored through that point, may lie from the exact light
    surface.

    Notes
    -----
    A computed sum of k float32 terms, each carrying j roundings, is off by
    at most γ(j + k)·Σ|terms| in each component (Higham 2002, §3.1;
    γ(n) = n·u/(1 − n·u), u = 2⁻²⁴). The light samplers form q from the
    receiver p, the light's centre c, and local coordinates along the
    light's frame axes a ∈ {ex, ey, ez} times those axes' components: the
    spherical-rectangle sampler as p + x·ex + y·ey + z₀·ez, with z₀ =
    (corner − p)·ez and the corner c − ½w·ex − ½h·ey; the disk sampler as c
    + x·ex + y·ey; the shadow ray then takes q back as p + dist·wi (d = q −
    p). Bounding each local coordinate (and the rounding of the dot product
    that gives it) by M_a = |a|·(|p| + |c|) + |d·a| + the half extent along
    a, a term along axis a moves component i by at most γ·|aᵢ|·M_a, so

        |q̃ᵢ − qᵢ| ≤ γ(n)·(|pᵢ| + |cᵢ| + |dᵢ| + Σ_a |aᵢ|·M_a).

    No term's path takes more than ~8 roundings, the centre and frame were
    rounded once from the stage's float64 transform, and a surface flush
    with the light has its float32 vertices (u/2 each) off the authored
    plane by no more than u·(|cᵢ| + extent); n = 16 covers these with a
    factor 2 to spare. Like pbrt-v4's error bounds on computed points
    (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., §6.8)
    it scales with each coordinate's magnitude, so it holds in metres or
    centimetres and near the origin or far from it; and since it keeps the
    frame's components, a horizontal lamp 300 m out, whose frame has exact
    zeros across its plane, gets a bound across the plane of γ·(a few
    metres), not γ·300 m. Sphere and cylinder points, formed along
    directions not in the light's frame, take |d| + extent in every
    component; a point light's q is its centre, exact."""
    c = l.position
    d = q - p
    if l.kind == POINT:
        return LIGHT_POINT_GAMMA * abs3(c)
    base = abs3(p) + abs3(c) + abs3(d)
    if l.kind == RECT or l.kind == DISK:
        pc = abs3(p) + abs3(c)
        hx = wp.where(l.kind == RECT, 0.5 * l.width, l.radius)
        hy = wp.where(l.kind == RECT, 0.5 * l.height, l.radius)
        mx = wp.dot(abs3(l.ex), pc) + wp.abs(wp.dot(d, l.ex)) + hx
        my = wp.dot(abs3(l.ey), pc) + wp.abs(wp.dot(d, l.ey)) + hy
        mz = wp.dot(abs3(l.ez), pc) + wp.abs(wp.dot(d, l.ez))
        return LIGHT_POINT_GAMMA * (base + mx * abs3(l.ex) + my * abs3(l.ey) + mz * abs3(l.ez))
    ext = wp.max(l.radius, 0.5 * l.length)
    s = wp.length(d) + ext
    return LIGHT_POINT_GAMMA * (base + wp.vec3(s, s, s))


@wp.func
def light_emit_normal(l: LightRec, q: wp.vec3, toward: wp.vec3) -> wp.vec3:
    """Unit normal of light ``l``'s emitting surface at q, on the side the
    light shines from (toward the receiver); for a point light, which has no
    surface, the unit direction ``toward`` the receiver itself."""
    if l.kind == RECT or l.kind == DISK:
        return -l.ez
    if l.kind == SPHERE:
        return wp.normalize(q - l.position)
    if l.kind == CYLINDER:
        r = q - l.position
        return wp.normalize(r - wp.dot(r, l.ex) * l.ex)
    return toward


@wp.func
def light_end_offset(l: LightRec, o: wp.vec3, p: wp.vec3, q: wp.vec3, nl: wp.vec3) -> float:
    """How far (metres) a shadow ray's far end is moved off the light point
    q, along the light's emitting normal nl (toward the receiver), so that a
    surface the light is flush with does not block it while a shade a
    little further in front still does.

    Notes
    -----
    As pbrt-v4 offsets both ends of a shadow ray (``SpawnRayTo``) by the
    error bounds of its two points, projected on each point's normal, the
    end moves by

        δ = Σᵢ |nlᵢ|·(eᵢ + γ(6)·|qᵢ − oᵢ|),

    e the componentwise bound of :func:`light_point_error` (its projection
    on nl is the error across the light's surface, which alone decides on
    which side of a flush surface the end lies), plus the error with which
    the traced segment o + t·wi, t ≤ dist, reproduces its end: wi =
    fl(fl(q' − o)/fl(|q' − o|)) carries one rounding of the difference, ≤ 4
    in the norm and 1 in the division, so dist·wiᵢ is within γ(6)·|qᵢ − oᵢ|
    of q'ᵢ − oᵢ. ``first_hit`` finds plane crossings exactly (float64 on the
    float32 data), so a flush surface lies behind the moved end and is not
    hit. The leak stage's shades, 1e-4 m in front of their lamps, are ≥ 10δ
    away (δ ≈ 5e-6 m near the origin, and for the horizontal lamp 300 m out,
    whose frame keeps the bound across its plane small); a shade closer to a
    lamp than δ does not shadow it. For a point light nl is the direction to
    the receiver, so a surface through the point, seen at angle ψ from its
    normal, is cleared by δ·cos ψ only."""
    e = light_point_error(l, p, q) + SEGMENT_GAMMA * abs3(q - o)
    return wp.dot(abs3(nl), e)


@wp.func
def shadow_ray_clear(scene: SceneRec, o: wp.vec3, p: wp.vec3, li: int, ls: LightSample) -> bool:
    """Visibility of light sample ``ls`` of light ``li`` (drawn at p) from
    the ray origin o.

    The segment runs from o to the sampled light point q = p + dist·wi (a
    point light's centre), moved off the light's surface toward the
    receiver by :func:`light_end_offset`, not from o along wi for dist: o is
    pushed off the surface by up to 1e-5·|p|∞ (3 mm at 300 m), and the
    parallel segment ended beside the lamp, short of a shade 1e-4 m below it
    (a leak, measured on the leak stage moved 300 m out); and a segment
    ending on q itself was blocked, about half the time by rounding, by a
    ceiling the light is flush with (CIE 171 case 5.3's layout read 21–29%
    low). Lights at infinity keep the direction; an emissive triangle's
    segment ends on q itself, since it is met as the mesh triangle it is."""
    if scene.has_mesh == 0:
        return True
    if ls.dist >= RAY_INF:
        return unoccluded(scene, o, ls.wi, ls.dist, ls.tri)
    l = scene.lights[li]
    q = p + ls.dist * ls.wi
    if ls.tri < 0:
        q = wp.where(l.kind == POINT, l.position, q)
        nl = light_emit_normal(l, q, -ls.wi)
        q = q + light_end_offset(l, o, p, q, nl) * nl
    d = q - o
    dist = wp.length(d)
    if dist <= 0.0:
        return True
    return unoccluded(scene, o, d / dist, dist, ls.tri)


@wp.func
def hit_light_before(l: LightRec, o: wp.vec3, d: wp.vec3, t_surface: float) -> float:
    """Distance along the ray (o, d) to the emitting side of area light
    ``l`` when it is met before the surface hit at ``t_surface`` (or −1):
    the light's surface is taken moved by :func:`light_end_offset` toward
    the ray's origin, as shadow rays take it, so a light flush with the
    surface the ray hits is seen by direction samples as by light samples
    (the two strategies that MIS weighs estimate the same integrand). A
    surface at grazing cosθl to the light moves by δ/cosθl along the ray."""
    t = hit_light(l, o, d, RAY_INF)
    if t <= 0.0:
        return -1.0
    if t < t_surface:
        return t
    q = o + t * d
    nl = light_emit_normal(l, q, -d)
    cos_l = -wp.dot(d, nl)
    if cos_l <= 0.0:
        return -1.0
    if t - light_end_offset(l, o, o, q, nl) / cos_l < t_surface:
        return t
    return -1.0


@wp.func
def ies_candela(l: LightRec, theta_deg: float, phi_deg: float) -> float:
    """Bilinear interpolation of the light's regular (θ, φ) candela table
    (rows θ = 0…180°, columns φ = 0…360°; see
    GoniometricDistribution.regular_table, which puts every measured angle
    on a node, so this equals the distribution's own interpolation)."""
    ft = wp.clamp(theta_deg, 0.0, 180.0) / 180.0 * float(l.map_h - 1)
    fp = wp.clamp(phi_deg, 0.0, 360.0) / 360.0 * float(l.map_w - 1)
    i = wp.clamp(int(wp.floor(ft)), 0, l.map_h - 2)
    j = wp.clamp(int(wp.floor(fp)), 0, l.map_w - 2)
    a = wp.clamp(ft - float(i), 0.0, 1.0)
    b = wp.clamp(fp - float(j), 0.0, 1.0)
    w = l.map_w
    v0 = (1.0 - b) * l.map[i * w + j] + b * l.map[i * w + j + 1]
    v1 = (1.0 - b) * l.map[(i + 1) * w + j] + b * l.map[(i + 1) * w + j + 1]
    return (1.0 - a) * v0 + a * v1


@wp.func
def shaping_factor(l: LightRec, w_out: wp.vec3) -> float:
    """UsdLuxShapingAPI factor of light ``l``'s emission toward the unit
    direction ``w_out`` (from the light to the receiver); 1 for an unshaped
    light. θ is the angle from the light's −Z axis, φ its azimuth from +X
    toward +Y (the IES frame); see :class:`simulator.scene.model.LightShaping`
    for the formula (cone with smoothstep softness, focus with tint, IES
    candela table). Multiplying a sample's value by it keeps every estimator
    unbiased: the pdfs are those of the unshaped light."""
    if l.shaped == 0:
        return 1.0
    cos_t = wp.clamp(-wp.dot(w_out, l.ez), -1.0, 1.0)
    theta = wp.acos(cos_t)
    f = float(1.0)
    if l.ies_scale <= 0.0:  # UsdLux: the cone "does not affect IES profiles"
        cut = l.shaping[0]
        if theta > cut:
            return 0.0
        start = cut * (1.0 - l.shaping[1])
        if l.shaping[1] > 0.0 and cut > start:
            t = wp.clamp((theta - start) / (cut - start), 0.0, 1.0)
            f = 1.0 - t * t * (3.0 - 2.0 * t)
    if l.shaping[2] > 0.0:
        tint = l.shaping[3]
        f = f * (tint + (1.0 - tint) * wp.pow(wp.abs(cos_t), l.shaping[2]))
    if l.ies_scale > 0.0:
        phi = wp.atan2(wp.dot(w_out, l.ey), wp.dot(w_out, l.ex))
        if phi < 0.0:
            phi = phi + 2.0 * PI
        f = f * l.ies_scale * ies_candela(l, wp.degrees(theta), wp.degrees(phi))
    return f


# ---------------------------------------------------------------- hero wavelengths
#
# Spectral mode (params.spectral = 1, simulator.spectra.hero): each sample
# carries 4 wavelengths (grid nodes params.hero) and, besides the scalar
# throughput β that Russian roulette reads, a tint per lane: the spectral
# throughput divided by β, kept at mean 1 (so β is the lanes' mean). A
# contribution value (W channel) × tint_k × the light's spectral row at node
# k is the spectral density the sample adds at λ_k; it is summed per lane in
# scene.response_lanes and projected on every response when the sample ends.

#: hero wavelengths per sample (simulator.spectra.transport.HERO_WAVELENGTHS)
N_HERO = wp.constant(4)
#: grid nodes spanned by the 4 lanes: 380–780 nm at 1 nm
GRID_SPAN_NM = wp.constant(400.0)


@wp.func
def hero_nodes(u: float) -> wp.vec4i:
    """Grid nodes of the 4 hero wavelengths of a uniform ``u`` ∈ [0, 1):
    x_k = 400·frac(u + k/4) nm above 380 nm, each rounded to its nearest
    node ⌊x_k + ½⌋ ∈ {0 … 400}. Node i is then drawn with probability w_i/400
    (w the trapezoid weights: ½ at either end), which
    ``scene.response_weights`` (400·q/w) divides out (simulator.spectra.hero)."""
    h = wp.vec4i(0, 0, 0, 0)
    for k in range(4):
        x = GRID_SPAN_NM * (u + float(k) * 0.25)
        if x >= GRID_SPAN_NM:
            x = x - GRID_SPAN_NM
        h[k] = wp.min(int(x + 0.5), 400)
    return h


@wp.func
def spectral_row(table: wp.array2d(dtype=float), row: int, h: wp.vec4i) -> wp.vec4:
    """``table[row]`` at the 4 hero nodes."""
    return wp.vec4(table[row, h[0]], table[row, h[1]], table[row, h[2]], table[row, h[3]])


@wp.func
def lane_response(scene: SceneRec, r: int, h: wp.vec4i, lanes: wp.vec4) -> float:
    """Response ``r`` of one sample from its 4 lanes: (1/4) Σ_k W_r(λ_k)·X_k."""
    return 0.25 * wp.dot(spectral_row(scene.response_weights, r, h), lanes)


@wp.func
def spectral_contribution(scene: SceneRec, params: TraceParams, li: int, value: wp.vec2, tint: wp.vec4) -> wp.vec2:
    """Tally light ``li``'s share of a spectral sample in its lanes and
    return its (radiometric, photopic) responses, which stand for the W and
    lm channels in spectral mode."""
    lanes = value[0] * wp.cw_mul(tint, spectral_row(scene.spectral_emission, li, params.hero))
    scene.response_lanes[params.thread] = scene.response_lanes[params.thread] + lanes
    return wp.vec2(lane_response(scene, 0, params.hero, lanes), lane_response(scene, 1, params.hero, lanes))


@wp.struct
class Reflection:
    rho: float  # what the path's throughput β is multiplied by
    tint: wp.vec4  # the lanes' spectral throughput / β after the reflection


@wp.func
def light_contribution(scene: SceneRec, params: TraceParams, li: int, value: wp.vec2, tint: wp.vec4) -> wp.vec2:
    """Light ``li``'s share ``value`` (W and lm channels) of one sample, as
    the trace tallies it; ``tint`` is the path's spectral tint there (see
    :class:`Reflection`). Every place a sample adds emitted light goes
    through here, so per-light tallies (light groups) and per-light scalings
    have one hook. Grey transport passes the value on; spectral transport
    tallies its lanes and passes on its spectral (W, lm) responses. With
    ``params.group_tally`` the value passed on is also added to this
    sample's slot of the light's group (``scene.light_group[li]``; a light
    in no group, or ``li`` = −1, adds to none), in the thread's state (see
    :class:`TraceParams`)."""
    v = value
    if params.spectral != 0:
        v = spectral_contribution(scene, params, li, value, tint)
    if params.group_tally != 0 and li >= 0:
        g = scene.light_group[li]
        if g >= 0:
            k = params.thread * params.n_groups * (params.n_groups + 3) + g
            params.group_state[k] = params.group_state[k] + wp.vec2d(v)
    return v
    return value


@wp.func
def clear_group_sample(params: TraceParams, t: int):
    """Zero thread ``t``'s per-group slots of this sample."""
    base = t * params.n_groups * (params.n_groups + 3)
    for g in range(params.n_groups):
        params.group_state[base + g] = wp.vec2d(wp.float64(0.0), wp.float64(0.0))


@wp.func
def fold_group_sample(params: TraceParams, t: int, first: int, keep: int):
    """Add thread ``t``'s sample, per group, to its shifted sums.

    Notes
    -----
    With x_g the sample's light from group g and K_g the thread's first
    sample of it, the thread keeps S_g = Σ(x_g − K_g) and the lower triangle
    of P_gh = Σ(x_g − K_g)(x_h − K_h) (per channel, float64), from which the
    host forms each block's mean and co-moment (:mod:`simulator.engine.stats`).
    A non-finite sample (``keep`` 0) counts as 0 in every group, as it does
    in the total."""
    n_g = params.n_groups
    x0 = t * n_g * (n_g + 3)  # this sample's light per group
    k0 = x0 + n_g  # shifts
    s0 = k0 + n_g  # sums
    p0 = s0 + n_g  # cross sums
    st = params.group_state
    for g in range(n_g):
        if keep == 0:
            st[x0 + g] = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
        if first != 0:
            st[k0 + g] = st[x0 + g]
        st[x0 + g] = st[x0 + g] - st[k0 + g]  # from here on the slot holds x_g − K_g
    for g in range(n_g):
        dg = st[x0 + g]
        st[s0 + g] = st[s0 + g] + dg
        for h in range(g + 1):
            k = p0 + g * n_g + h
            st[k] = st[k] + wp.cw_mul(dg, st[x0 + h])


@wp.func
def surface_albedo(scene: SceneRec, params: TraceParams, face: int, tint: wp.vec4) -> Reflection:
    """Diffuse reflection off triangle ``face`` for this trace: the one place
    a path reads a surface's reflectance. Grey: ρ = the albedo, the tint is
    kept. Spectral: with ρ_k = ρ(λ_k) the uplifted reflectance, the scalar
    is the mean m = (1/4) Σ_k tint_k ρ_k and the tint becomes tint_k ρ_k / m,
    so β·tint_k stays the lane's spectral throughput and β their mean (what
    Russian roulette reads)."""
    r = Reflection()
    r.tint = tint
    if params.spectral == 0:
        r.rho = scene.albedo[face]
        return r
    t = wp.cw_mul(tint, spectral_row(scene.spectral_reflectance, scene.spectral_face[face], params.hero))
    m = 0.25 * (t[0] + t[1] + t[2] + t[3])
    r.rho = m
    if m > 0.0:
        r.tint = t / m
    return r


# ---------------------------------------------------------------- surface guide
#
# Guided paths (method ``guided``) add a second way to pick the next vertex y
# from x: a patch j of the stage's surfaces with probability P_j (from a
# pilot's tallies of the light each patch passed on to the sensors), then a
# point uniform on it, area pdf P_j/A_j. It is mixed with the cosine
# direction by one-sample MIS (balance heuristic: divide by the mixture pdf,
# in area measure, Veach 1997 §9.2.4; docs/REFERENCES.md §One-sample MIS);
# see vertex_irradiance. The idea of
# learning where light comes from with a pilot and sampling it is path
# guiding's (Vorba et al. 2014, Müller et al. 2017), here on surface patches.


@wp.func
def patch_index(s: float, t: float, m: int) -> int:
    """Index k (0 … m² − 1) of the sub-triangle holding (s, t) on a triangle
    cut m × m: k = j·(2m − j) + 2i + upper (see
    :mod:`simulator.scene.patches`). Twin of :func:`patch_point`."""
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


@wp.func
def tri_params(scene: SceneRec, face: int, y: wp.vec3) -> wp.vec2:
    """(s, t) of the point y on triangle ``face``: y = a + s·(b − a) + t·(c − a)
    (least squares, so a point off the plane by rounding projects onto it)."""
    a = tri_vertex(scene, face, 0)
    e1 = tri_vertex(scene, face, 1) - a
    e2 = tri_vertex(scene, face, 2) - a
    d = y - a
    d00 = wp.dot(e1, e1)
    d01 = wp.dot(e1, e2)
    d11 = wp.dot(e2, e2)
    d20 = wp.dot(d, e1)
    d21 = wp.dot(d, e2)
    den = d00 * d11 - d01 * d01
    if den <= 0.0:
        return wp.vec2(0.0, 0.0)
    return wp.vec2((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den)


@wp.func
def patch_at(scene: SceneRec, face: int, y: wp.vec3) -> int:
    """The patch (global index) holding the point y of triangle ``face``."""
    st = tri_params(scene, face, y)
    return scene.guide.tri_offset[face] + patch_index(st[0], st[1], scene.guide.tri_m[face])


@wp.struct
class GuideSample:
    y: wp.vec3  # the point drawn
    face: int  # its triangle
    density: float  # area pdf P_j/A_j there (m⁻²)


@wp.func
def guide_row(scene: SceneRec, depth: int, face: int) -> int:
    """The guide table a vertex samples from: row 0 at a path's first
    vertex, else its triangle's (see GuideRec)."""
    if depth == 0 or face < 0:
        return 0
    return scene.guide.tri_row[face]


@wp.func
def sample_guide(scene: SceneRec, row: int, u: wp.vec3) -> GuideSample:
    """A patch j with row ``row``'s probability P_j (binary search of its
    CDF: P_j = cdf[k] − cdf[k−1]), then a point uniform on it: area pdf
    P_j/A_j. Twin of :func:`pdf_guide`. Needs the row to be non-empty."""
    lo = scene.guide.row_start[row]
    hi = scene.guide.row_start[row + 1] - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if scene.guide.cdf[mid] <= u[0]:
            lo = mid + 1
        else:
            hi = mid
    j = scene.guide.ids[lo]
    face = scene.guide.patch_tri[j]
    st = patch_point(j - scene.guide.tri_offset[face], scene.guide.tri_m[face], wp.vec2(u[1], u[2]))
    a = tri_vertex(scene, face, 0)
    g = GuideSample()
    g.y = a + st[0] * (tri_vertex(scene, face, 1) - a) + st[1] * (tri_vertex(scene, face, 2) - a)
    g.face = face
    g.density = scene.guide.density[row * scene.guide.n_patches + j]
    return g


@wp.func
def pdf_guide(scene: SceneRec, row: int, face: int, y: wp.vec3) -> float:
    """Area pdf (m⁻²) with which :func:`sample_guide` draws the point y of
    triangle ``face``: row ``row``'s P_j/A_j of its patch, 0 where that row
    never goes."""
    if scene.guide.n == 0:
        return 0.0
    return scene.guide.density[row * scene.guide.n_patches + patch_at(scene, face, y)]


@wp.func
def guide_fraction(scene: SceneRec, params: TraceParams, depth: int, row: int) -> float:
    """c: the probability of the guide strategy at a vertex of this depth
    that samples guide row ``row`` (0: cosine only). None where the row is
    empty, outside [guide_first, guide_depth), or at the last vertex a
    bounce limit allows (the next one would add nothing)."""
    if params.guide_c <= 0.0 or scene.guide.n == 0:
        return 0.0
    if scene.guide.row_start[row + 1] <= scene.guide.row_start[row]:
        return 0.0
    if depth < params.guide_first or (params.guide_depth >= 0 and depth >= params.guide_depth):
        return 0.0
    if params.bounces >= 0 and depth >= params.bounces:
        return 0.0
    return params.guide_c


@wp.func
def mixture_factor(c: float, pdf_guide_area: float, pdf_cos_area: float) -> float:
    """p_cos,A(y) / p_mix(y), p_mix = c·p_guide,A + (1 − c)·p_cos,A: what a
    vertex reached by either strategy multiplies the path's throughput by
    (besides ρ; it is 1 for c = 0 and at most 1/(1 − c)).

    Notes
    -----
    Light leaving y toward x contributes L(y) = ρ/π·E(y) to E(x) through
    ∫ L G dA_y with G = cosθx·cosθy/r²; one-sample MIS with the balance
    heuristic estimates it by L·G/p_mix(y) whichever strategy drew y (Veach
    1997, §9.2.4). Since p_cos,A = cosθx·cosθy/(π r²) = G/π, the next
    vertex's weight is weight·ρ·G/(π·p_mix) = weight·ρ·p_cos,A/p_mix."""
    den = c * pdf_guide_area + (1.0 - c) * pdf_cos_area
    if den <= 0.0:
        return 0.0
    return pdf_cos_area / den


@wp.struct
class GuideStep:
    y: wp.vec3  # the next vertex
    n: wp.vec3  # its normal, facing the previous vertex
    face: int  # its triangle; −1: the strategy gave nothing (the path ends)
    factor: float  # p_cos,A / p_mix at y (see mixture_factor)


@wp.func
def guided_step(scene: SceneRec, row: int, o: wp.vec3, n: wp.vec3, c: float, u: wp.vec3) -> GuideStep:
    """The guide strategy at a vertex with ray origin o and normal n: a point
    y from :func:`sample_guide`, kept when it faces o, o sees its side, and
    the segment o → y first meets y's triangle (within the ray offset of y:
    a coplanar neighbour met at y by rounding does not block it)."""
    g = GuideStep()
    g.face = -1
    gs = sample_guide(scene, row, u)
    d = gs.y - o
    dist = wp.length(d)
    if dist <= 0.0:
        return g
    wi = d / dist
    cos_x = wp.dot(wi, n)
    a = tri_vertex(scene, gs.face, 0)
    ng = wp.cross(tri_vertex(scene, gs.face, 1) - a, tri_vertex(scene, gs.face, 2) - a)
    if cos_x <= 0.0 or wp.length(ng) <= 0.0:
        return g
    ng = wp.normalize(ng)
    cos_y = -wp.dot(wi, ng)
    if cos_y < 0.0:
        ng = -ng
        cos_y = -cos_y
    if cos_y <= 0.0:
        return g
    off = offset_length(scene, gs.y)
    h = first_hit(scene, o, wi, dist + off)
    if h.face >= 0 and h.face != gs.face and h.t < dist - off:
        return g
    g.y = gs.y
    g.n = ng
    g.face = gs.face
    g.factor = mixture_factor(c, gs.density, cos_x * cos_y * INV_PI / (dist * dist))
    return g


@wp.func
def tally_patch(scene: SceneRec, params: TraceParams, row: int, face: int, y: wp.vec3, value: wp.vec2):
    """Pilot: add a next-event contribution made at the vertex y of triangle
    ``face``, reached from a vertex sampling guide row ``row``, to that
    row's tally of y's patch (in the worker's block ``params.tally_row``)."""
    if scene.guide.n_patches > 0 and face >= 0:
        k = (params.tally_row * scene.guide.n_rows + row) * scene.guide.n_patches + patch_at(scene, face, y)
        wp.atomic_add(scene.guide.tally, k, value)


@wp.func
def picks_at(params: TraceParams, depth: int) -> bool:
    """Whether the vertex at ``depth`` picks one light (pick_light 1: every
    vertex; 2: every vertex past the sensor's own)."""
    return params.pick_light == 1 or (params.pick_light == 2 and depth > 0)


@wp.func
def pick_scale(
    scene: SceneRec, params: TraceParams, pk: LightPick, li: int, p: wp.vec3, n: wp.vec3, depth: int
) -> float:
    """P(li | vertex) of the light pick, 1 when every light is sampled: the
    factor on pdf_light that makes it the next-event strategy's density."""
    if not picks_at(params, depth):
        return 1.0
    return pick_probability(scene, pk, li, p, n, params.mask_row, depth)


@wp.func
def tally_pick(
    scene: SceneRec, params: TraceParams, li: int, p: wp.vec3, n: wp.vec3, depth: int, weight: float, got: wp.vec2
):
    """A pilot's sums for light ``li``'s pick factor (light_pick.py): the
    path weight × its estimate ê, and × the value its shadowed sample gave;
    slot 0 for a sensor's first vertex, 1 for the rest."""
    if is_delta(scene.lights[li]):
        return
    slot = wp.where(depth == 0 and params.mask_row >= 0, 0, 1)
    k = (params.thread * 2 + slot) * scene.n_lights + li
    e = light_estimate(scene, li, p, n)
    scene.pick_tally[k] = scene.pick_tally[k] + weight * wp.vec2(e[0], importance(got))


@wp.func
def vertex_irradiance(
    scene: SceneRec, p_in: wp.vec3, n_in: wp.vec3, weight_in: float, params: TraceParams, skip_first: int, rng_in: wp.uint32
) -> wp.vec2:
    """weight_in × an estimate of the irradiance on (p, n), following bounces
    when ``params.bounces`` allows (see module docstring). With ``skip_first``
    the light arriving at this first vertex straight from emitters is left
    out (the indirect component); the paths still go on from it.

    Guided paths (``params.guide_c`` > 0, see :func:`guide_fraction`): at a
    vertex the next one is drawn with probability c by the surface guide
    (:func:`guided_step`), otherwise by the cosine direction, and either way
    the throughput takes ρ·p_cos,A/p_mix (:func:`mixture_factor`). Direct
    light stays next-event estimation plus the emitters cosine rays meet;
    the cosine strategy now runs with probability 1 − c, so its solid-angle
    density is (1 − c)·cosθ/π in both MIS weights and in the hit's estimate
    π·L/(1 − c). Emitters, escapes and emission along guided segments are
    not counted: those two strategies already cover all direct light."""
    rng = rng_in
    p = p_in
    n = n_in
    weight = weight_in  # weight_in × the path throughput β
    beta = float(1.0)
    tint = params.tint  # spectral throughput / β per hero lane (spectral mode; see surface_albedo)
    total = wp.vec2(0.0, 0.0)
    depth = int(0)
    cur_face = int(-1)  # the triangle p lies on (depth ≥ 1)
    prev_row = int(0)  # the guide row of the vertex before p
    while depth < MAX_VERTICES:
        row = guide_row(scene, depth, cur_face)
        c_v = guide_fraction(scene, params, depth, row)
        # Rays leave a surface from o, pushed off it (see offset_length). A
        # sensor within that push of a UsdLux light starts them at p itself:
        # lights are not geometry, and first_hit (plane_distance) still keeps
        # the surface a sensor may lie on from shadowing it.
        o = p
        off = offset_length(scene, p)
        if scene.has_mesh != 0 and (depth > 0 or not near_light(scene, p, off)):
            o = p + off * n
        count = not (skip_first != 0 and depth == 0)
        # -- next-event estimation: each light once, or (pick_light) the
        #    delta lights and one light with area, picked with P(li | x)
        pk = LightPick()
        if params.nee != 0 and count:
            if picks_at(params, depth):
                pk = pick_light(scene, p, n, params.mask_row, depth, rng)
                rng = pk.rng
            for li in range(scene.n_lights):
                u = wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng))
                # a light the plan proved wholly behind the sensor adds nothing there
                if depth == 0 and params.mask_row >= 0:
                    if scene.light_mask[params.mask_row * scene.n_lights + li] == 0:
                        continue
                sel = float(1.0)
                if picks_at(params, depth) and not is_delta(scene.lights[li]):
                    if li != pk.li:
                        continue
                    sel = pk.prob
                ls = sample_light(scene, li, p, n, u)  # geometry from the true point; only rays start at o
                ls.value = ls.value * (shaping_factor(scene.lights[li], -ls.wi) / sel)
                got = wp.vec2(0.0, 0.0)
                if ls.value[0] > 0.0 or ls.value[1] > 0.0:
                    w = float(1.0)
                    if params.mis != 0 and ls.pdf > 0.0:
                        w = power_heuristic(sel * ls.pdf, (1.0 - c_v) * pdf_cosine_hemisphere(wp.dot(ls.wi, n)))
                    if w > 0.0 or params.tally_pick != 0:
                        count_ray(scene, params)
                        if shadow_ray_clear(scene, o, p, li, ls):
                            got = ls.value
                            c_light = light_contribution(scene, params, li, (weight * w) * ls.value, tint)
                            total += c_light
                            if params.tally != 0 and depth > 0:
                                tally_patch(scene, params, prev_row, cur_face, p, c_light)
                if params.tally_pick != 0:
                    tally_pick(scene, params, li, p, n, depth, weight, got)
        if params.bsdf == 0:
            break
        # -- Russian roulette (a weight window): below the threshold t the path
        #    survives with probability q = β/t and β is divided by q
        #    (unbiased: E[β'] = β). It comes after this vertex's next-event
        #    estimate, not before it: that light is then gathered at weight
        #    β rather than 0 or t, which cost one shadow ray per ended path
        #    and measured 1.5× less variance × time in the integrating
        #    sphere, 1.1–1.3× in the office, within 4% elsewhere (docs/DESIGN.md
        #    §Russian roulette); and a guided step toward a bright patch
        #    far off takes a small factor, which rouletting before that
        #    patch's own light is gathered would turn back into noise
        if depth > 0 and beta < params.rr_threshold:
            q_late = beta / params.rr_threshold
            if wp.randf(rng) >= q_late:
                break
            beta = beta / q_late
            weight = weight_in * beta
        # -- guided paths: with probability c the surface guide picks the next vertex
        if c_v > 0.0:
            if wp.randf(rng) < c_v:
                count_ray(scene, params)
                g = guided_step(scene, row, o, n, c_v, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
                if g.face < 0:
                    break
                refl = surface_albedo(scene, params, g.face, tint)
                beta = beta * refl.rho * g.factor
                tint = refl.tint
                weight = weight_in * beta
                p = g.y
                n = g.n
                cur_face = g.face
                prev_row = row
                depth += 1
                continue
        # -- a cosine-weighted direction: E ≈ π·L(ω)
        local = sample_cosine_hemisphere(wp.vec2(wp.randf(rng), wp.randf(rng)))
        if local[2] <= 0.0:
            break
        wi = to_world(local, n)
        pdf_b = (1.0 - c_v) * local[2] * INV_PI  # this strategy's density: it runs with probability 1 − c
        w_dir = weight * PI / (1.0 - c_v)
        count_ray(scene, params)
        hit = first_hit(scene, o, wi, RAY_INF)
        t_hit = hit.t
        face = hit.face
        ng = hit.ng
        # UsdLux area lights in front of the hit (they do not block), met
        # along the same ray as the mesh: a light tested along another line
        # (from p, parallel) was seen past a shade the mesh ray hit.
        for li in range(scene.n_lights):
            l = scene.lights[li]
            t = hit_light_before(l, o, wi, t_hit)  # −1 for lights with no surface
            if t > 0.0 and count:
                w = float(1.0)
                if params.mis != 0 and params.nee != 0:
                    pdf_l = pick_scale(scene, params, pk, li, p, n, depth) * pdf_light(scene, li, o, n, wi, t, -1)
                    w = power_heuristic(pdf_b, pdf_l)
                total += light_contribution(scene, params, li, (w_dir * w * shaping_factor(l, -wi)) * l.emission, tint)
        if face < 0:
            for li in range(scene.n_lights):
                le = escaped_radiance(scene.lights[li], wi)
                if (le[0] > 0.0 or le[1] > 0.0) and count:
                    w = float(1.0)
                    if params.mis != 0 and params.nee != 0:
                        pdf_l = pick_scale(scene, params, pk, li, p, n, depth) * pdf_light(scene, li, o, n, wi, RAY_INF, -1)
                        w = power_heuristic(pdf_b, pdf_l)
                    total += light_contribution(scene, params, li, (w_dir * w) * le, tint)
            break
        cos_view = -wp.dot(wi, ng)
        le = tri_emitted(scene, face, cos_view)
        if (le[0] > 0.0 or le[1] > 0.0) and count:
            w = float(1.0)
            if params.mis != 0 and params.nee != 0 and params.emissive_light >= 0:
                w = power_heuristic(pdf_b, pick_scale(scene, params, pk, params.emissive_light, p, n, depth)
                                    * pdf_light(scene, params.emissive_light, o, n, wi, t_hit, face))
            total += light_contribution(scene, params, params.emissive_light, (w_dir * w) * le, tint)
        if params.bounces >= 0 and depth >= params.bounces:
            break
        # -- reflect: L_o = ρ/π·E, so the next vertex's weight is w_dir·ρ/π
        #    = weight_in·β·ρ (the roulette comes after that vertex's
        #    next-event estimate, above)
        refl = surface_albedo(scene, params, face, tint)
        beta = beta * refl.rho
        tint = refl.tint
        if c_v > 0.0:  # one-sample MIS against the guide (mixture_factor)
            beta = beta * mixture_factor(c_v, pdf_guide(scene, row, face, o + t_hit * wi),
                                         local[2] * wp.abs(cos_view) * INV_PI / (t_hit * t_hit))  # fmt: skip
        weight = weight_in * beta
        p = o + t_hit * wi
        n = wp.where(cos_view > 0.0, ng, -ng)
        cur_face = face
        prev_row = row
        depth += 1
    return total


@wp.func
def sample_radiance(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    """One estimate of the radiance arriving at the meter from within its cone."""
    rng = rng_in
    d = s.normal
    if s.one_minus_cos > 0.0:
        d = to_world(sample_uniform_cone(wp.vec2(wp.randf(rng), wp.randf(rng)), s.one_minus_cos), s.normal)
    o = s.position
    count_ray(scene, params)
    hit = first_hit(scene, o, d, RAY_INF)
    t_hit = hit.t
    face = hit.face
    ng = hit.ng
    # Emitters seen straight along the meter's ray, and the first surface's
    # reflection of the light reaching it straight from emitters, are the
    # direct component; with skip_direct both are left out.
    direct = params.skip_direct == 0
    total = wp.vec2(0.0, 0.0)
    for li in range(scene.n_lights):
        l = scene.lights[li]
        if hit_light_before(l, o, d, t_hit) > 0.0 and direct:
            total += light_contribution(scene, params, li, shaping_factor(l, -d) * l.emission, params.tint)
    if face < 0:
        if direct:
            for li in range(scene.n_lights):
                total += light_contribution(scene, params, li, escaped_radiance(scene.lights[li], d), params.tint)
        return total
    cos_view = -wp.dot(d, ng)
    if direct:
        le = tri_emitted(scene, face, cos_view)
        if le[0] > 0.0 or le[1] > 0.0:
            total += light_contribution(scene, params, params.emissive_light, le, params.tint)
    refl = surface_albedo(scene, params, face, params.tint)
    if refl.rho > 0.0:
        n = wp.where(cos_view > 0.0, ng, -ng)
        prm = params
        prm.tint = refl.tint
        total += vertex_irradiance(scene, o + t_hit * d, n, refl.rho * INV_PI, prm, params.skip_direct, rng)
    return total


@wp.func
def sample_irradiance(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    """One estimate of the irradiance on the sensor's side."""
    return vertex_irradiance(scene, s.position, s.normal, 1.0, params, params.skip_direct, rng_in)


@wp.func
def sample_patch(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    """One estimate of the irradiance at a point drawn uniformly on the patch."""
    rng = rng_in
    u = wp.vec2(wp.randf(rng), wp.randf(rng))
    p = s.position + ((u[0] - 0.5) * s.width) * s.right + ((u[1] - 0.5) * s.height) * s.up
    return vertex_irradiance(scene, p, s.normal, 1.0, params, params.skip_direct, rng)


@wp.func
def analytic_irradiance(scene: SceneRec, s: SensorRec) -> wp.vec2:
    """Every light's unoccluded irradiance on the sensor, in closed form."""
    v = wp.vec2(0.0, 0.0)
    for li in range(scene.n_lights):
        l = scene.lights[li]
        e = analytic_light(scene, li, s.position, s.normal)
        if l.shaped != 0:  # the planner sends only shaped point lights here: E = I(ω)·cosψ/d²
            e = e * shaping_factor(l, wp.normalize(s.position - l.position))
        v += e
    return v


@wp.func
def analytic_patch(scene: SceneRec, s: SensorRec) -> wp.vec2:
    """Every light's unoccluded mean irradiance on the patch, in closed form
    (point lights: I·Ω/A)."""
    v = wp.vec2(0.0, 0.0)
    for li in range(scene.n_lights):
        v += analytic_patch_light(scene.lights[li], s.position, s.normal, s.right, s.up, s.width, s.height)
    return v


def _upload_radiance(rec, sensor: Sensor) -> None:
    # 1 − cos of the cone as 2·sin²(θ/2), without cancellation
    rec.one_minus_cos = 2.0 * math.sin(0.5 * sensor.half_angle) ** 2


def _upload_patch(rec, sensor: Sensor) -> None:
    from simulator.scene.model import patch_width_axis

    rec.right = wp.vec3(*map(float, patch_width_axis(sensor.up, sensor.normal)))
    rec.up = wp.vec3(*map(float, sensor.up))
    rec.width, rec.height = float(sensor.size[0]), float(sensor.size[1])


@dataclass(frozen=True)
class SensorKernel:
    """One sensor kind's device side (its other facts: ``SensorKindSpec``).

    ``sample(scene, s, params, rng) -> vec2`` draws one sample of the
    reading; ``analytic(scene, s) -> vec2`` is its closed form, if any;
    ``upload(rec, sensor)`` fills its fields of the :class:`SensorRec`."""

    kind: SensorKind
    sample: Any
    analytic: Any = None
    upload: Callable | None = None


#: sensor kinds read by :func:`estimate_kernel` (probes have their own kernel)
SENSOR_KERNELS = (
    SensorKernel(SensorKind.IRRADIANCE, sample_irradiance, analytic=analytic_irradiance),
    SensorKernel(SensorKind.RADIANCE, sample_radiance, upload=_upload_radiance),
    SensorKernel(SensorKind.PATCH, sample_patch, analytic=analytic_patch, upload=_upload_patch),
)
def _sample_link(k, hook, rest):
    @wp.func
    def sample_kind(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        if s.kind == wp.static(k):
            return wp.static(hook)(scene, s, params, rng_in)
        return wp.static(rest)(scene, s, params, rng_in)

    return sample_kind


@wp.func
def _no_sample(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    return wp.vec2(0.0, 0.0)


def _analytic_link(k, hook, rest):
    @wp.func
    def analytic_kind(scene: SceneRec, s: SensorRec) -> wp.vec2:
        if s.kind == wp.static(k):
            return wp.static(hook)(scene, s)
        return wp.static(rest)(scene, s)

    return analytic_kind


@wp.func
def _no_analytic(scene: SceneRec, s: SensorRec) -> wp.vec2:
    return wp.vec2(0.0, 0.0)


_sample_chain = kind_chain(tuple((int(k.kind), k.sample) for k in SENSOR_KERNELS), _sample_link, _no_sample)
_analytic_chain = kind_chain(
    tuple((int(k.kind), k.analytic) for k in SENSOR_KERNELS if k.analytic is not None), _analytic_link, _no_analytic
)


@wp.func
def sample_sensor(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    """One sample of sensor ``s``'s reading (dispatch over ``SENSOR_KERNELS``)."""
    return _sample_chain(scene, s, params, rng_in)


@wp.func
def analytic_sensor(scene: SceneRec, s: SensorRec) -> wp.vec2:
    """Closed-form reading of sensor ``s`` (dispatch over ``SENSOR_KERNELS``)."""
    return _analytic_chain(scene, s)


def sensor_record(sensor: Sensor) -> SensorRec:
    """The device record of one sensor: common fields, then its kind's ``upload``."""
    r = SensorRec()
    r.kind = int(sensor.kind)
    r.position = wp.vec3(*map(float, sensor.position))
    r.normal = wp.vec3(*map(float, sensor.normal))
    r.one_minus_cos = 0.0
    r.cull = 1 if sensor.spec.culls_lights else 0
    for k in SENSOR_KERNELS:
        if k.kind == sensor.kind and k.upload is not None:
            k.upload(r, sensor)
    return r


@wp.kernel
def estimate_kernel(
    scene: SceneRec,
    sensors: wp.array(dtype=SensorRec),
    params: TraceParams,
    thread_sensor: wp.array(dtype=wp.int32),
    thread_first_sample: wp.array(dtype=wp.int32),
    thread_count: wp.array(dtype=wp.int32),
    offset: int,
    out_shift: wp.array(dtype=wp.vec2d),
    out_sum: wp.array(dtype=wp.vec2d),
    out_sumsq: wp.array(dtype=wp.vec2d),
    out_bad: wp.array(dtype=wp.int32),
    response_shift: wp.array2d(dtype=wp.float64),
    response_sum: wp.array2d(dtype=wp.float64),
    response_sumsq: wp.array2d(dtype=wp.float64),
):
    """Each thread draws ``thread_count[t]`` samples of one sensor and
    writes shifted sums Σ(x − K) and Σ(x − K)² with K its first sample, so
    that a constant estimator (a lone point light) has exactly zero variance
    and float64 accumulation does not cancel. Non-finite samples are counted
    in ``out_bad`` and left out of the sums (the host reports them).

    Spectral mode: each sample first draws its hero wavelengths from the
    sensor's wavelength stream (:func:`hero_stream_key`); its lanes are
    projected on every response r of ``scene.response_weights`` and tallied
    likewise in ``response_*[t, r]`` (rows 0 and 1, radiometric and
    photopic, are also the W and lm channels).

    With ``params.group_tally`` the same samples are also summed per light
    group (:func:`fold_group_sample`); off, that costs one branch a sample."""
    t = wp.tid() + offset
    sid = thread_sensor[t]
    first = thread_first_sample[t]
    key = sensor_stream_key(params.seed, sid)
    shift = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    s1 = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    s2 = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    bad = int(0)
    s = sensors[sid]
    prm = params
    prm.thread = t
    prm.mask_row = wp.where(s.cull != 0, sid, -1)
    n_resp = int(0)
    if params.spectral != 0:
        n_resp = scene.response_weights.shape[0]
    for r in range(n_resp):
        response_sum[t, r] = wp.float64(0.0)
        response_sumsq[t, r] = wp.float64(0.0)
    for j in range(thread_count[t]):
        if params.spectral != 0:
            prm.hero = hero_nodes(wp.randf(wp.rand_init(hero_stream_key(key), first + j)))
            scene.response_lanes[t] = wp.vec4(0.0, 0.0, 0.0, 0.0)
        if prm.group_tally != 0:
            clear_group_sample(prm, t)
        v = sample_sensor(scene, s, prm, wp.rand_init(key, first + j))
        keep = int(1)
        ok = wp.isfinite(v[0]) and wp.isfinite(v[1])
        lanes = wp.vec4(0.0, 0.0, 0.0, 0.0)
        if n_resp > 0:
            lanes = scene.response_lanes[t]
            ok = ok and wp.isfinite(wp.dot(lanes, lanes))
        if not ok:
            bad += 1
            keep = 0
            v = wp.vec2(0.0, 0.0)
            lanes = wp.vec4(0.0, 0.0, 0.0, 0.0)
        if prm.group_tally != 0:
            fold_group_sample(prm, t, wp.where(j == 0, 1, 0), keep)
        x = wp.vec2d(wp.float64(v[0]), wp.float64(v[1]))
        if j == 0:
            shift = x
        dx = x - shift
        s1 += dx
        s2 += wp.cw_mul(dx, dx)
        for r in range(n_resp):
            xr = wp.float64(lane_response(scene, r, prm.hero, lanes))
            if j == 0:
                response_shift[t, r] = xr
            dr = xr - response_shift[t, r]
            response_sum[t, r] = response_sum[t, r] + dr
            response_sumsq[t, r] = response_sumsq[t, r] + dr * dr
    out_shift[t] = shift
    out_sum[t] = s1
    out_sumsq[t] = s2
    out_bad[t] = bad


# ---------------------------------------------------------------- analytic


@wp.kernel
def analytic_kernel(
    scene: SceneRec,
    sensors: wp.array(dtype=SensorRec),
    sensor_ids: wp.array(dtype=wp.int32),
    out_value: wp.array(dtype=wp.vec2d),
):
    """Closed-form reading of each listed sensor: irradiance sensors sum every
    light's unoccluded irradiance; patches sum point lights' I·Ω/A."""
    t = wp.tid()
    v = analytic_sensor(scene, sensors[sensor_ids[t]])
    out_value[t] = wp.vec2d(wp.float64(v[0]), wp.float64(v[1]))
