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
- interreflection (``bounces`` ≠ 0): at a surface hit the path goes on with
  probability ρ (Russian roulette, unbiased: the throughput ρ/ρ stays 1), so
  no fixed bounce limit truncates the light.

References
----------
E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD
thesis, Stanford, 1997, ch. 9 (multiple importance sampling).
J. Arvo, D. Kirk, "Particle transport and image synthesis", SIGGRAPH 1990
(Russian roulette).
"""

import warp as wp

from .lights import (  # noqa: F401  (LightRec, SceneRec re-exported for the engine)
    DISK,
    EMISSIVE,
    RAY_INF,
    RECT,
    SPHERE,
    LightRec,
    SceneRec,
    escaped_radiance,
    hit_light,
    pdf_light,
    sample_light,
    tri_emitted,
)
from .sampling import (
    INV_PI,
    PI,
    pdf_cosine_hemisphere,
    pdf_uniform_cone,
    sample_concentric_disk,
    sample_cosine_hemisphere,
    sample_uniform_cone,
    sensor_stream_key,
    to_world,
)

# Forward-only: no gradients are taken, and skipping the adjoint halves compile time.
wp.set_module_options({"enable_backward": False})

# Sensor kinds; must match simulator.scene.model.SensorKind.
IRRADIANCE = wp.constant(0)
RADIANCE = wp.constant(1)
PATCH = wp.constant(2)

# A path whose every bounce survives Russian roulette with probability ρ < 1
# ends with probability one; this cap only guards against ρ rounding to 1.
# At ρ = 0.999 it drops a fraction 0.999^65536 ≈ 4e-29 of the light.
MAX_VERTICES = wp.constant(65536)


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


@wp.struct
class TraceParams:
    nee: int  # sample every light at each vertex
    bsdf: int  # follow cosine-weighted directions and count emitters they hit
    mis: int  # weight the two by the power heuristic
    bounces: int  # surface interactions to follow: 0 = direct only, −1 = unbounded
    skip_direct: int  # 1: leave out light that reaches the sensor without a reflection (indirect only)
    emissive_light: int  # index of the EMISSIVE light record, −1 if none
    seed: int


@wp.func
def power_heuristic(pdf_a: float, pdf_b: float) -> float:
    a2 = pdf_a * pdf_a
    b2 = pdf_b * pdf_b
    if a2 + b2 <= 0.0:
        return 0.0
    return a2 / (a2 + b2)


@wp.func
def offset_length(scene: SceneRec, p: wp.vec3) -> float:
    """How far a ray origin is pushed off a surface at p: ``scene.eps``
    relative to the coordinate's magnitude, so the push stays well above
    float32 resolution (6e-8 relative) far from the origin, and well below
    modelled gaps (0.1 mm under a lamp) near it."""
    return scene.eps * wp.max(1.0, wp.max(wp.abs(p[0]), wp.max(wp.abs(p[1]), wp.abs(p[2]))))


@wp.func
def unoccluded(scene: SceneRec, o: wp.vec3, wi: wp.vec3, dist: float, tri: int) -> bool:
    """True if nothing blocks the segment from o along wi for ``dist``. A
    sampled emissive triangle is reached when the first hit is that triangle;
    UsdLux lights are not geometry, so the segment ends exactly on them and a
    surface 10⁻⁴ m in front of a lamp still blocks it."""
    if scene.has_mesh == 0:
        return True
    if tri >= 0:
        q = wp.mesh_query_ray(scene.mesh, o, wi, dist * 1.001)
        return (not q.result) or q.face == tri
    q = wp.mesh_query_ray(scene.mesh, o, wi, dist)
    return not q.result


@wp.func
def vertex_irradiance(
    scene: SceneRec, p_in: wp.vec3, n_in: wp.vec3, weight: float, params: TraceParams, skip_first: int, rng_in: wp.uint32
) -> wp.vec2:
    """weight × an estimate of the irradiance on (p, n), following bounces
    when ``params.bounces`` allows (see module docstring). With ``skip_first``
    the light arriving at this first vertex straight from emitters is left
    out (the indirect component); the paths still go on from it."""
    rng = rng_in
    p = p_in
    n = n_in
    total = wp.vec2(0.0, 0.0)
    depth = int(0)
    while depth < MAX_VERTICES:
        o = p + offset_length(scene, p) * n
        count = not (skip_first != 0 and depth == 0)
        # -- next-event estimation: each light once
        if params.nee != 0 and count:
            for li in range(scene.n_lights):
                u = wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng))
                ls = sample_light(scene, li, p, n, u)  # geometry from the true point; only rays start at o
                if ls.value[0] > 0.0 or ls.value[1] > 0.0:
                    w = float(1.0)
                    if params.mis != 0 and ls.pdf > 0.0:
                        w = power_heuristic(ls.pdf, pdf_cosine_hemisphere(wp.dot(ls.wi, n)))
                    if w > 0.0 and unoccluded(scene, o, ls.wi, ls.dist, ls.tri):
                        total += (weight * w) * ls.value
        if params.bsdf == 0:
            break
        # -- a cosine-weighted direction: E ≈ π·L(ω)
        local = sample_cosine_hemisphere(wp.vec2(wp.randf(rng), wp.randf(rng)))
        if local[2] <= 0.0:
            break
        wi = to_world(local, n)
        pdf_b = local[2] * INV_PI
        w_dir = weight * PI
        t_hit = float(RAY_INF)
        face = int(-1)
        ng = wp.vec3(0.0, 0.0, 1.0)
        if scene.has_mesh != 0:
            q = wp.mesh_query_ray(scene.mesh, o, wi, RAY_INF)
            if q.result:
                t_hit = q.t
                face = q.face
                ng = wp.normalize(q.normal)
        # UsdLux area lights in front of the hit (they do not block)
        for li in range(scene.n_lights):
            l = scene.lights[li]
            if l.kind == RECT or l.kind == DISK or l.kind == SPHERE:
                t = hit_light(l, o, wi, t_hit)
                if t > 0.0 and count:
                    w = float(1.0)
                    if params.mis != 0 and params.nee != 0:
                        w = power_heuristic(pdf_b, pdf_light(scene, li, o, n, wi, t, -1))
                    total += (w_dir * w) * l.emission
        if face < 0:
            for li in range(scene.n_lights):
                le = escaped_radiance(scene.lights[li], wi)
                if (le[0] > 0.0 or le[1] > 0.0) and count:
                    w = float(1.0)
                    if params.mis != 0 and params.nee != 0:
                        w = power_heuristic(pdf_b, pdf_light(scene, li, o, n, wi, RAY_INF, -1))
                    total += (w_dir * w) * le
            break
        cos_view = -wp.dot(wi, ng)
        le = tri_emitted(scene, face, cos_view)
        if (le[0] > 0.0 or le[1] > 0.0) and count:
            w = float(1.0)
            if params.mis != 0 and params.nee != 0 and params.emissive_light >= 0:
                w = power_heuristic(pdf_b, pdf_light(scene, params.emissive_light, o, n, wi, t_hit, face))
            total += (w_dir * w) * le
        if params.bounces >= 0 and depth >= params.bounces:
            break
        # -- reflect: L_o = ρ/π·E, so the next vertex's weight is w_dir·ρ/π;
        #    survive with probability ρ and divide by it, leaving `weight` as is.
        rho = scene.albedo[face]
        if wp.randf(rng) >= rho:
            break
        p = o + t_hit * wi
        n = wp.where(cos_view > 0.0, ng, -ng)
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
    t_hit = float(RAY_INF)
    face = int(-1)
    ng = wp.vec3(0.0, 0.0, 1.0)
    if scene.has_mesh != 0:
        q = wp.mesh_query_ray(scene.mesh, o, d, RAY_INF)
        if q.result:
            t_hit = q.t
            face = q.face
            ng = wp.normalize(q.normal)
    # Emitters seen straight along the meter's ray, and the first surface's
    # reflection of the light reaching it straight from emitters, are the
    # direct component; with skip_direct both are left out.
    direct = params.skip_direct == 0
    total = wp.vec2(0.0, 0.0)
    for li in range(scene.n_lights):
        l = scene.lights[li]
        if l.kind == RECT or l.kind == DISK or l.kind == SPHERE:
            if hit_light(l, o, d, t_hit) > 0.0 and direct:
                total += l.emission
    if face < 0:
        if direct:
            for li in range(scene.n_lights):
                total += escaped_radiance(scene.lights[li], d)
        return total
    cos_view = -wp.dot(d, ng)
    if direct:
        total += tri_emitted(scene, face, cos_view)
    rho = scene.albedo[face]
    if rho > 0.0:
        n = wp.where(cos_view > 0.0, ng, -ng)
        total += vertex_irradiance(scene, o + t_hit * d, n, rho * INV_PI, params, params.skip_direct, rng)
    return total


@wp.func
def sample_sensor(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
    rng = rng_in
    if s.kind == RADIANCE:
        return sample_radiance(scene, s, params, rng)
    p = s.position
    if s.kind == PATCH:
        u = wp.vec2(wp.randf(rng), wp.randf(rng))
        p = p + ((u[0] - 0.5) * s.width) * s.right + ((u[1] - 0.5) * s.height) * s.up
    return vertex_irradiance(scene, p, s.normal, 1.0, params, params.skip_direct, rng)


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
):
    """Each thread draws ``thread_count[t]`` samples of one sensor and
    writes shifted sums Σ(x − K) and Σ(x − K)² with K its first sample, so
    that a constant estimator (a lone point light) has exactly zero variance
    and float64 accumulation does not cancel. Non-finite samples are counted
    in ``out_bad`` and left out of the sums (the host reports them)."""
    t = wp.tid() + offset
    sid = thread_sensor[t]
    first = thread_first_sample[t]
    key = sensor_stream_key(params.seed, sid)
    shift = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    s1 = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    s2 = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    bad = int(0)
    s = sensors[sid]
    for j in range(thread_count[t]):
        v = sample_sensor(scene, s, params, wp.rand_init(key, first + j))
        if not (wp.isfinite(v[0]) and wp.isfinite(v[1])):
            bad += 1
            v = wp.vec2(0.0, 0.0)
        x = wp.vec2d(wp.float64(v[0]), wp.float64(v[1]))
        if j == 0:
            shift = x
        dx = x - shift
        s1 += dx
        s2 += wp.cw_mul(dx, dx)
    out_shift[t] = shift
    out_sum[t] = s1
    out_sumsq[t] = s2
    out_bad[t] = bad
