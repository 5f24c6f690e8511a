"""Light sampling and evaluation, one small ``@wp.func`` per light kind.

Warp has no virtual dispatch, so each light is a :class:`LightRec` with a kind
integer, and :func:`sample_light`, :func:`pdf_light` and :func:`hit_light`
switch on it in one place. Each sampler returns the light's *unshadowed*
contribution to irradiance on a receiver at ``p`` with normal ``n``,

    value = L(ωi) · cosθ / pdf(ωi),

together with the direction, the shadow-ray length and the solid-angle pdf
(0 for delta lights, which no direction sample can hit). The caller traces
the shadow ray and applies multiple-importance weights.

Kinds and their strategies (solid-angle pdfs):

=============  =====================================================  ==================
kind           strategy                                               pdf(ω)
=============  =====================================================  ==================
POINT          exact direction (delta)                                0
SPHERE         uniform in the subtended cone                           1/(2π(1−cosθmax))
RECT           uniform in the subtended spherical rectangle            1/Ω (area if Ω tiny)
DISK           uniform in area                                         d²/(A·cosθl)
DISTANT        exact (angle 0, delta) or uniform in its cone           1/(2π(1−cosθmax))
DOME           cosine lobe about the receiver normal                   cosθ/π
DOME (map)     texel ∝ value·sinθ, uniform in (u, v) inside it         pdf_uv/(2π² sinθ)
CYLINDER       uniform in area on the side, front-facing points        d²/(A·cosθl)
EMISSIVE       triangle ∝ its power, then uniform in area             P(tri)·d²/(A·|cosθl|)
=============  =====================================================  ==================

A textured dome's radiance is ``emission × map[texel]`` with the texel of
the direction looked up *nearest* (no filtering), so the radiance is
piecewise constant exactly like the sampling density; the lat-long
convention is :mod:`simulator.io.latlong`'s. An untextured dome keeps cosine
sampling, which is optimal for uniform radiance (zero variance unoccluded).
"""

import warp as wp

from .distributions import direction_to_latlong_uv, latlong_texel, pdf_latlong, sample_latlong
from .sampling import (
    PI,
    TWO_PI,
    SPHRECT_MIN_SOLID_ANGLE,
    one_minus_cos_from_sin2,
    pdf_cosine_hemisphere,
    pdf_uniform_cone,
    sample_concentric_disk,
    sample_cosine_hemisphere,
    sample_triangle_bary,
    sample_uniform_cone,
    sphrect_sample,
    sphrect_setup,
    to_world,
)

# Light kinds; must match simulator.scene.model.LightKind.
POINT = wp.constant(0)
SPHERE = wp.constant(1)
RECT = wp.constant(2)
DISK = wp.constant(3)
DISTANT = wp.constant(4)
DOME = wp.constant(5)
CYLINDER = wp.constant(6)
EMISSIVE = wp.constant(7)

#: length of a ray that leaves the scene, metres
RAY_INF = wp.constant(1.0e30)


@wp.struct
class LightRec:
    """One light on the device (see :class:`simulator.scene.model.Light`)."""

    kind: int
    position: wp.vec3
    ex: wp.vec3
    ey: wp.vec3
    ez: wp.vec3  # rect/disk emit toward −ez; a distant light lies toward +ez
    emission: wp.vec2  # (radiometric, photometric)
    width: float
    height: float
    radius: float
    one_minus_cos: float  # distant light: 1 − cos(half-angle); 0 = delta
    area: float
    length: float  # cylinder length along ex (its axis)
    # textured dome: lat-long map in the frame (ex, ey = pole, ez = lat 0, lon 0)
    has_map: int  # 1: radiance = emission × map[texel]; 0: uniform
    map_w: int
    map_h: int
    map: wp.array(dtype=float)  # map_h × map_w values, row 0 at the pole ey
    map_marg: wp.array(dtype=float)  # map_h + 1: marginal CDF over rows
    map_cond: wp.array(dtype=float)  # map_h × (map_w + 1): conditional CDFs over columns
    # UsdLuxShapingAPI (estimators.shaping_factor): shaped = 1 multiplies emission toward ω by the factor
    shaped: int
    shaping: wp.vec4  # (cone half-angle rad, cone softness, focus, focus tint)
    ies_scale: float  # > 0: × ies_scale·I(θ, φ), I bilinear in map (map_h rows θ 0…180°, map_w columns φ 0…360°)


@wp.struct
class SceneRec:
    """Geometry, materials and lights on the device."""

    mesh: wp.uint64
    has_mesh: int
    points: wp.array(dtype=wp.vec3)
    tris: wp.array(dtype=wp.int32)  # 3 per triangle
    albedo: wp.array(dtype=float)
    emission: wp.array(dtype=wp.vec2)  # front-face radiance per triangle
    two_sided: wp.array(dtype=wp.int32)
    emit_tris: wp.array(dtype=wp.int32)  # emissive triangle ids
    emit_cdf: wp.array(dtype=float)  # inclusive CDF over emit_tris, last = 1
    emit_prob: wp.array(dtype=float)  # per triangle: probability of being picked (0 if not emissive)
    lights: wp.array(dtype=LightRec)
    n_lights: int
    eps: float  # ray-origin offset relative to max(1 m, |p|∞)
    ray_counts: wp.array(dtype=wp.int32)  # per kernel thread, when TraceParams.count_rays
    light_mask: wp.array(dtype=wp.int32)  # (sensors × n_lights): 0 = light culled for that sensor


@wp.struct
class LightSample:
    wi: wp.vec3  # unit direction from the receiver toward the light
    dist: float  # shadow-ray length
    value: wp.vec2  # unshadowed L·cosθ/pdf (W/m², lx)
    pdf: float  # solid-angle pdf; 0 for delta lights
    tri: int  # sampled emissive triangle, −1 otherwise


@wp.func
def _empty_sample() -> LightSample:
    s = LightSample()
    s.wi = wp.vec3(0.0, 0.0, 1.0)
    s.dist = 0.0
    s.value = wp.vec2(0.0, 0.0)
    s.pdf = 0.0
    s.tri = -1
    return s


@wp.func
def tri_vertex(scene: SceneRec, tri: int, k: int) -> wp.vec3:
    return scene.points[scene.tris[3 * tri + k]]


@wp.func
def tri_emitted(scene: SceneRec, tri: int, wo_dot_ng: float) -> wp.vec2:
    """Radiance a triangle emits toward a viewer on the side where
    dot(toward viewer, geometric normal) = ``wo_dot_ng``."""
    if wo_dot_ng > 0.0 or scene.two_sided[tri] != 0:
        return scene.emission[tri]
    return wp.vec2(0.0, 0.0)


# ---------------------------------------------------------------- per-kind samplers


@wp.func
def _sample_point(l: LightRec, p: wp.vec3, n: wp.vec3) -> LightSample:
    s = _empty_sample()
    d = l.position - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    s.wi = d / dist
    s.dist = dist
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / (dist * dist))  # E = I·cosξ/d²
    return s


@wp.func
def _sphere_cone(l: LightRec, p: wp.vec3) -> float:
    """1 − cosθmax of the cone a sphere light subtends from p (0 if p is inside)."""
    d2 = wp.length_sq(l.position - p)
    r2 = l.radius * l.radius
    if d2 <= r2:
        return 0.0
    return one_minus_cos_from_sin2(r2 / d2)


@wp.func
def _sample_sphere(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = _empty_sample()
    omc = _sphere_cone(l, p)
    if omc <= 0.0:
        return s  # inside a sphere light: it emits outward only
    axis = wp.normalize(l.position - p)
    wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), omc), axis)
    # distance to the near side of the sphere along wi
    oc = l.position - p
    b = wp.dot(oc, wi)
    disc = l.radius * l.radius - (wp.length_sq(oc) - b * b)
    t = b - wp.sqrt(wp.max(disc, 0.0))
    s.wi = wi
    s.dist = wp.max(t, 0.0)
    s.pdf = pdf_uniform_cone(omc)
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def _area_sample(l: LightRec, p: wp.vec3, n: wp.vec3, q: wp.vec3, nl: wp.vec3) -> LightSample:
    """A point q drawn uniformly on the light's area A (pdf 1/A), whose
    emitting normal there is nl, as a direction sample from p: solid-angle
    pdf d²/(A·cosθl); nothing when q faces away from p."""
    s = _empty_sample()
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    wi = d / dist
    cos_l = -wp.dot(wi, nl)
    if cos_l <= 0.0:
        return s
    s.wi = wi
    s.dist = dist
    s.pdf = dist * dist / (l.area * cos_l)
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def _rect_corner(l: LightRec) -> wp.vec3:
    return l.position - 0.5 * l.width * l.ex - 0.5 * l.height * l.ey


@wp.func
def _sample_rect(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = _empty_sample()
    if wp.dot(p - l.position, l.ez) >= 0.0:
        return s  # behind a one-sided emitter
    corner = _rect_corner(l)
    sr = sphrect_setup(p, corner, l.ex, l.ey, l.width, l.height)
    if sr.solid_angle <= SPHRECT_MIN_SOLID_ANGLE:
        q = corner + (u[0] * l.width) * l.ex + (u[1] * l.height) * l.ey
        return _area_sample(l, p, n, q, -l.ez)
    q = sphrect_sample(sr, wp.vec2(u[0], u[1]))
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    s.wi = d / dist
    s.dist = dist
    s.pdf = 1.0 / sr.solid_angle
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r * sr.solid_angle)
    return s


@wp.func
def _sample_disk(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    if wp.dot(p - l.position, l.ez) >= 0.0:
        return _empty_sample()  # behind a one-sided emitter
    dp = sample_concentric_disk(wp.vec2(u[0], u[1])) * l.radius
    return _area_sample(l, p, n, l.position + dp[0] * l.ex + dp[1] * l.ey, -l.ez)


@wp.func
def _sample_distant(l: LightRec, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = _empty_sample()
    s.dist = RAY_INF
    if l.one_minus_cos <= 0.0:
        s.wi = l.ez
        cos_r = wp.dot(l.ez, n)
        if cos_r > 0.0:
            s.value = l.emission * cos_r  # E = E⊥·cosξ
        return s
    s.wi = to_world(sample_uniform_cone(wp.vec2(u[0], u[1]), l.one_minus_cos), l.ez)
    s.pdf = pdf_uniform_cone(l.one_minus_cos)
    cos_r = wp.dot(s.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def _sample_dome(l: LightRec, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = _empty_sample()
    if l.has_map != 0:
        return _sample_dome_map(l, n, u)
    local = sample_cosine_hemisphere(wp.vec2(u[0], u[1]))
    s.wi = to_world(local, n)
    s.dist = RAY_INF
    s.pdf = pdf_cosine_hemisphere(local[2])
    if s.pdf > 0.0:
        s.value = l.emission * PI  # L·cosθ / (cosθ/π)
    return s


@wp.func
def _sample_dome_map(l: LightRec, n: wp.vec3, u: wp.vec3) -> LightSample:
    """A direction from the map's value·sinθ distribution (whole sphere;
    directions below the receiver's horizon add 0)."""
    s = _empty_sample()
    ms = sample_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wp.vec2(u[0], u[1]))
    if ms.pdf <= 0.0:
        return s
    s.wi = ms.wi
    s.dist = RAY_INF
    s.pdf = ms.pdf
    cos_r = wp.dot(ms.wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (l.map[ms.texel] * cos_r / ms.pdf)
    return s


@wp.func
def _cylinder_normal(l: LightRec, q: wp.vec3) -> wp.vec3:
    """Outward unit normal of the cylinder's side at (or nearest to) q."""
    r = q - l.position
    r = r - wp.dot(r, l.ex) * l.ex
    return wp.normalize(r)


@wp.func
def _sample_cylinder(l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """Uniform point on the side (area pdf 1/A, A = 2π r·length); only points
    whose outward normal faces p emit toward it. A point facing p is also
    the first point of the cylinder the ray meets (it is convex), so no
    self-occlusion test is needed."""
    phi = TWO_PI * u[1]
    nl = wp.cos(phi) * l.ey + wp.sin(phi) * l.ez
    return _area_sample(l, p, n, l.position + ((u[0] - 0.5) * l.length) * l.ex + l.radius * nl, nl)


@wp.func
def _pick_emissive(scene: SceneRec, u: float) -> int:
    """Index into emit_tris with P(i) = cdf[i] − cdf[i−1] (binary search)."""
    lo = int(0)
    hi = scene.emit_cdf.shape[0] - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if scene.emit_cdf[mid] <= u:
            lo = mid + 1
        else:
            hi = mid
    return lo


@wp.func
def _sample_emissive(scene: SceneRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    s = _empty_sample()
    if scene.emit_tris.shape[0] == 0:
        return s
    tri = scene.emit_tris[_pick_emissive(scene, u[0])]
    a = tri_vertex(scene, tri, 0)
    b = tri_vertex(scene, tri, 1)
    c = tri_vertex(scene, tri, 2)
    bc = sample_triangle_bary(wp.vec2(u[1], u[2]))
    q = a + bc[0] * (b - a) + bc[1] * (c - a)
    ng2 = wp.cross(b - a, c - a)
    area = 0.5 * wp.length(ng2)
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0 or area <= 0.0:
        return s
    wi = d / dist
    cos_l = -wp.dot(wi, ng2) / (2.0 * area)  # > 0 when p is in front
    le = tri_emitted(scene, tri, cos_l)
    if wp.abs(cos_l) < 1.0e-9:
        return s
    s.wi = wi
    s.dist = dist
    s.tri = tri
    s.pdf = scene.emit_prob[tri] * dist * dist / (area * wp.abs(cos_l))
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0 and s.pdf > 0.0:
        s.value = le * (cos_r / s.pdf)
    return s


@wp.func
def sample_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """Sample light ``li`` for a receiver at ``p`` facing ``n``."""
    l = scene.lights[li]
    if l.kind == POINT:
        return _sample_point(l, p, n)
    if l.kind == SPHERE:
        return _sample_sphere(l, p, n, u)
    if l.kind == RECT:
        return _sample_rect(l, p, n, u)
    if l.kind == DISK:
        return _sample_disk(l, p, n, u)
    if l.kind == DISTANT:
        return _sample_distant(l, n, u)
    if l.kind == DOME:
        return _sample_dome(l, n, u)
    if l.kind == CYLINDER:
        return _sample_cylinder(l, p, n, u)
    if l.kind == EMISSIVE:
        return _sample_emissive(scene, p, n, u)
    return _empty_sample()


# ---------------------------------------------------------------- pdfs of given directions


@wp.func
def pdf_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    """Solid-angle pdf with which :func:`sample_light` would pick direction
    ``wi`` from ``p``, given that ``wi`` hits the light at distance ``t``
    (on triangle ``tri`` for emissive geometry)."""
    l = scene.lights[li]
    if l.kind == SPHERE:
        omc = _sphere_cone(l, p)
        return wp.where(omc > 0.0, pdf_uniform_cone(omc), 0.0)
    if l.kind == RECT:
        sr = sphrect_setup(p, _rect_corner(l), l.ex, l.ey, l.width, l.height)
        if sr.solid_angle > SPHRECT_MIN_SOLID_ANGLE:
            return 1.0 / sr.solid_angle
        cos_l = wp.dot(wi, l.ez)
        return wp.where(cos_l > 0.0, t * t / (l.area * cos_l), 0.0)
    if l.kind == DISK:
        cos_l = wp.dot(wi, l.ez)
        return wp.where(cos_l > 0.0, t * t / (l.area * cos_l), 0.0)
    if l.kind == DISTANT:
        return wp.where(l.one_minus_cos > 0.0, pdf_uniform_cone(l.one_minus_cos), 0.0)
    if l.kind == DOME:
        if l.has_map != 0:
            return pdf_latlong(l.map_marg, l.map_cond, l.map_w, l.map_h, l.ex, l.ey, l.ez, wi)
        return pdf_cosine_hemisphere(wp.dot(wi, n))
    if l.kind == CYLINDER:
        cos_l = -wp.dot(wi, _cylinder_normal(l, p + t * wi))
        return wp.where(cos_l > 0.0, t * t / (l.area * cos_l), 0.0)
    if l.kind == EMISSIVE:
        a = tri_vertex(scene, tri, 0)
        ng2 = wp.cross(tri_vertex(scene, tri, 1) - a, tri_vertex(scene, tri, 2) - a)
        area = 0.5 * wp.length(ng2)
        cos_l = wp.abs(wp.dot(wi, ng2)) / (2.0 * area)
        return wp.where(cos_l > 0.0, scene.emit_prob[tri] * t * t / (area * cos_l), 0.0)
    return 0.0


# ---------------------------------------------------------------- ray hits on lights


@wp.func
def _hit_cylinder(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    """Where a ray enters the cylinder's side from outside (the emitting,
    outward face), or −1. The caps neither emit nor block, so a ray through
    a cap sees only the inside of the side: nothing."""
    oc = o - l.position
    ox = wp.dot(oc, l.ex)
    dx = wp.dot(d, l.ex)
    op = oc - ox * l.ex  # parts across the axis
    dp = d - dx * l.ex
    a = wp.length_sq(dp)
    b = wp.dot(op, dp)
    c = wp.length_sq(op) - l.radius * l.radius
    if c <= 0.0 or a <= 0.0 or b >= 0.0:
        return -1.0  # inside the infinite cylinder, parallel to its axis, or moving away
    disc = b * b - a * c
    if disc < 0.0:
        return -1.0
    t = c / (wp.sqrt(disc) - b)  # nearer root (t0·t1 = c/a), free of cancellation
    if t <= 0.0 or t >= t_max:
        return -1.0
    if wp.abs(ox + t * dx) > 0.5 * l.length:
        return -1.0
    return t


@wp.func
def hit_light(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    """Distance along the ray (o, d) to the emitting side of an area light,
    or −1 if it is missed or lies beyond ``t_max``. UsdLux lights neither
    block nor reflect: a ray that hits one goes on to whatever lies behind."""
    if l.kind == RECT or l.kind == DISK:
        denom = wp.dot(d, l.ez)
        if denom <= 0.0:
            return -1.0  # seen from behind: one-sided
        t = wp.dot(l.position - o, l.ez) / denom
        if t <= 0.0 or t >= t_max:
            return -1.0
        q = o + t * d - l.position
        x = wp.dot(q, l.ex)
        y = wp.dot(q, l.ey)
        if l.kind == RECT:
            if wp.abs(x) <= 0.5 * l.width and wp.abs(y) <= 0.5 * l.height:
                return t
        else:
            if x * x + y * y <= l.radius * l.radius:
                return t
        return -1.0
    if l.kind == SPHERE:
        oc = l.position - o
        b = wp.dot(oc, d)
        c = wp.length_sq(oc) - l.radius * l.radius
        if c <= 0.0:
            return -1.0  # inside: the sphere emits outward
        disc = b * b - c
        if disc < 0.0 or b <= 0.0:
            return -1.0
        t = b - wp.sqrt(disc)
        if t >= t_max:
            return -1.0
        return t
    if l.kind == CYLINDER:
        return _hit_cylinder(l, o, d, t_max)
    return -1.0



@wp.func
def escaped_radiance(l: LightRec, d: wp.vec3) -> wp.vec2:
    """Radiance from an infinitely distant light along a ray that left the scene."""
    if l.kind == DOME:
        if l.has_map != 0:
            uv = direction_to_latlong_uv(d, l.ex, l.ey, l.ez)
            return l.emission * l.map[latlong_texel(uv, l.map_w, l.map_h)]
        return l.emission
    if l.kind == DISTANT and l.one_minus_cos > 0.0:
        if 1.0 - wp.dot(d, l.ez) <= l.one_minus_cos:
            return l.emission
    return wp.vec2(0.0, 0.0)
