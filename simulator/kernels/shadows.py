"""Where a shadow ray toward a light ends: float32 error bounds on light points.

A surface flush with a lamp must not block it, while a shade 0.1 mm in
front of it must, even 300 m from the origin. :func:`light_point_error`
bounds how far a sampled light point may lie off the exact light surface
(Higham's γ(n) bounds, as pbrt-v4 bounds its computed points), and
:func:`light_end_offset` moves the shadow ray's far end off the light by
that bound; :func:`shadow_ray_clear` and :func:`hit_light_before` apply it
to light samples and to direction samples alike.
"""

import warp as wp

from simulator.scene.model import LightKind

from .lights import RAY_INF, LightRec, LightSample, SceneRec, hit_light
from .rays import unoccluded
from .surfaces import transmittance_along


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


@wp.func(inline=True)  # never a copy of the scene record per shadow ray (rays.unoccluded)
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
    seg = shadow_segment(scene, o, p, li, ls)
    if seg[3] <= 0.0:
        return True
    return unoccluded(scene, o, wp.vec3(seg[0], seg[1], seg[2]), seg[3], ls.tri)


@wp.func(inline=True)  # never a copy of the scene record per shadow ray (rays.unoccluded)
def shadow_segment(scene: SceneRec, o: wp.vec3, p: wp.vec3, li: int, ls: LightSample) -> wp.vec4:
    """The shadow ray of :func:`shadow_ray_clear` as (unit direction, length): from o to the light point
    moved off the light (lights at infinity: along ``ls.wi`` for ``ls.dist``); length 0 when o is on it."""
    if ls.dist >= RAY_INF:
        return wp.vec4(ls.wi[0], ls.wi[1], ls.wi[2], ls.dist)
    l = scene.lights[li]
    q = p + ls.dist * ls.wi
    if ls.tri < 0:
        q = wp.where(l.kind == POINT, l.position, q)
        nl = light_emit_normal(l, q, -ls.wi)
        q = q + light_end_offset(l, o, p, q, nl) * nl
    d = q - o
    dist = wp.length(d)
    if dist <= 0.0:
        return wp.vec4(0.0, 0.0, 0.0, 0.0)
    w = d / dist
    return wp.vec4(w[0], w[1], w[2], dist)


@wp.func(inline=True)  # never a copy of the scene record per shadow ray (rays.unoccluded)
def shadow_ray_pass(scene: SceneRec, o: wp.vec3, p: wp.vec3, li: int, ls: LightSample) -> float:
    """The share of light sample ``ls`` that reaches o along :func:`shadow_ray_clear`'s segment through
    surfaces that pass light (coverage, panes; :func:`.surfaces.transmittance_along`): 0 when blocked."""
    if scene.has_mesh == 0:
        return 1.0
    seg = shadow_segment(scene, o, p, li, ls)
    if seg[3] <= 0.0:
        return 1.0
    return transmittance_along(scene, o, wp.vec3(seg[0], seg[1], seg[2]), seg[3], ls.tri)


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
