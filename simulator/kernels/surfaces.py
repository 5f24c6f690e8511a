"""What a ray does at a surface beyond Lambert: coverage and dielectric panes, as ``@wp.func``.

A face with a row in ``scene.surf`` (``scene.surf_id[face]`` ≥ 0; see
:mod:`simulator.scene.surfaces` for the rules the reader applies) is met in
two ways:

- **shadow rays** (light sampling, a probe's delta lights) pass it with the
  factor :func:`pass_factor`: (1 − c) + c·T(θ), c the coverage and T the
  slab transmittance at the ray's incidence (0 for an opaque face). The
  expected visibility, so a lamp or the sun behind glazing keeps its
  light-sampling efficiency: :func:`transmittance_along` multiplies the
  factors of every such face on the segment;
- **path rays** (direction samples, radiance meters, probe pixels) choose
  one event (:func:`surface_event`): pass a coverage gap (probability
  1 − c, weight 1) or, on the surface's part (c), the face's usual diffuse
  scattering on an opaque part, else the pane's slab: pass with
  probability q and weight T/q, or a mirror reflection with 1 − q and
  weight R/(1 − q) (absorption is in the weights, never drawn). Each
  event's weight is its factor over its probability, so the throughput's
  expectation is the shadow ray's: unbiased for any q in (0, 1), and a pass
  keeps the direction, so multiple importance sampling at the vertex the
  ray left still weighs the same two estimates of the same light.

  Here q = T/(T + R), so both weights are T + R: a pane that absorbs (a
  datasheet transmittance) passes every ray it does not reflect with
  weight T + R < 1 rather than ending a share 1 − R − T of the paths (3%
  less variance per sample in the office behind a pane of τ = 0.9,
  docs/DESIGN.md).

A translucent layer (``SurfRec.pane`` 2: UsdPreviewSurface's transparent
mode, 0 < opacity < 1) swaps the roles: its share c is the face's own
(matte) scattering and its gap 1 − c is the clear slab, so a shadow ray
passes (1 − c)·T and a path ray draws the slab's pass or mirror (with
the same weights) where u ≥ c.

Where an opacity texture drives the coverage, c is read at the hit point
(:mod:`.coverage`), so both expectations hold texel by texel.

A pane passes light straight on, with no offset (a thin slab). On a closed
pane mesh (``scene.surf_side`` ±1) the face a ray enters by takes the whole
slab and the face it leaves by passes it (its share was summed on entry),
which makes two parallel faces a few millimetres apart exactly the sheet.

Slab reflectance and transmittance (:func:`slab_rt`) per polarisation, r the
Fresnel reflectance of one interface and τ the internal transmittance of one
pass at that angle: T = (1 − r)²τ/(1 − r²τ²), R = r + (1 − r)²rτ²/(1 − r²τ²),
averaged over s and p (docs/REFERENCES.md §Thin slab).
"""

import warp as wp

from .coverage import coverage_at
from .lights import RAY_INF, SceneRec
from .rays import RayHit, first_hit, offset_length

#: most surfaces one shadow ray or one path segment passes before it is taken as blocked
MAX_PASSES = wp.constant(16)

#: :func:`surface_event` outcomes
SCATTER = wp.constant(0)  # the face's own (diffuse) scattering
PASS = wp.constant(1)  # the ray goes on straight
MIRROR = wp.constant(2)  # mirror reflection off a pane
ABSORB = wp.constant(3)  # absorbed (past MAX_PASSES surfaces, or a slab that neither passes nor reflects)


@wp.func
def fresnel_pair(c: float, n: float) -> wp.vec2:
    """Fresnel reflectances (r_s, r_p) of one interface into index n ≥ 1 at incidence cosine c ∈ (0, 1]."""
    ct = wp.sqrt(wp.max(0.0, 1.0 - (1.0 - c * c) / (n * n)))
    a = (c - n * ct) / (c + n * ct)
    b = (n * c - ct) / (n * c + ct)
    return wp.vec2(a * a, b * b)


@wp.func
def slab_rt(cos_i: float, n: float, tau0: float) -> wp.vec2:
    """(R, T) of a plane-parallel slab of index n at incidence cosine ``cos_i``, unpolarised; ``tau0`` the
    internal transmittance of one normal pass, τ(θ) = τ0^(1/cos θ_t) (see the module docstring)."""
    c = wp.min(wp.abs(cos_i), 1.0)
    if c <= 1.0e-7:
        return wp.vec2(1.0, 0.0)  # grazing: every interface reflects
    ct = wp.sqrt(wp.max(0.0, 1.0 - (1.0 - c * c) / (n * n)))
    tau = float(1.0)
    if tau0 < 1.0:
        tau = wp.pow(tau0, 1.0 / wp.max(ct, 1.0e-6))
    rp = fresnel_pair(c, n)
    rr = float(0.0)
    tt = float(0.0)
    for k in range(2):
        r = rp[k]
        den = 1.0 - r * r * tau * tau
        tt += 0.5 * (1.0 - r) * (1.0 - r) * tau / den
        rr += 0.5 * (r + (1.0 - r) * (1.0 - r) * r * tau * tau / den)
    return wp.vec2(rr, tt)


@wp.func
def pane_rt(scene: SceneRec, face: int, d: wp.vec3, ng: wp.vec3) -> wp.vec2:
    """(R, T) the pane of ``face`` shows a ray along ``d`` (unit normal ``ng`` of the front face): the slab,
    or (0, 1) on the face of a closed pane mesh the ray leaves by."""
    s = scene.surf[scene.surf_id[face]]
    cosd = wp.dot(d, ng)
    side = scene.surf_side[face]
    if side != 0:
        # the ray enters through the outward side: against the front normal if the front faces out
        entering = (cosd < 0.0) == (side > 0)
        if not entering:
            return wp.vec2(0.0, 1.0)
    return slab_rt(cosd, s.ior, s.tau)


@wp.func
def pass_factor(scene: SceneRec, face: int, d: wp.vec3, ng: wp.vec3, p: wp.vec3) -> float:
    """The fraction of light along ``d`` that passes ``face`` at p: 0 for a matte face, (1 − c) + c·T for
    a surface of coverage c (its texture's at p where one drives it, :func:`.coverage.coverage_at`)
    whose part that is there transmits T (0 unless it is a pane); (1 − c)·T on a translucent layer."""
    sid = scene.surf_id[face]
    if sid < 0:
        return 0.0
    s = scene.surf[sid]
    c = coverage_at(scene, s, face, p)
    t = float(0.0)
    if s.pane == 2:  # a translucent layer: the gap is the slab, the share c the matte face
        return (1.0 - c) * pane_rt(scene, face, d, ng)[1]
    if s.pane != 0:
        t = pane_rt(scene, face, d, ng)[1]
    return (1.0 - c) + c * t


@wp.func
def transmittance_along(scene: SceneRec, o: wp.vec3, wi: wp.vec3, dist: float, tri: int) -> float:
    """The share of light that crosses the segment from o along wi for ``dist`` (a shadow ray): the
    product of :func:`pass_factor` over the faces on it, 0 when an opaque one blocks it. With ``tri``
    ≥ 0 (a sampled emissive triangle) the segment ends on that triangle, as :func:`rays.unoccluded`
    ends it; past :data:`MAX_PASSES` surfaces it is taken as blocked."""
    if scene.has_mesh == 0:
        return 1.0
    f = float(1.0)
    start = float(0.0)
    end = dist
    if tri >= 0:
        end = dist * 1.001
    for k in range(MAX_PASSES):
        h = first_hit(scene, o + start * wi, wi, end - start)
        if h.face < 0 or h.face == tri:
            return f
        if scene.surf_id[h.face] < 0:  # a matte face blocks it (no call: each copies the scene record)
            return 0.0
        f = f * pass_factor(scene, h.face, wi, h.ng, o + (start + h.t) * wi)
        if f <= 0.0:
            return 0.0
        start = start + h.t + offset_length(scene, o + (start + h.t) * wi)
        if start >= end:
            return f
    return 0.0


@wp.struct
class SurfaceEvent:
    kind: int  # SCATTER, PASS, MIRROR or ABSORB
    weight: float  # the throughput's factor: the event's share of the light over its probability
    slab: int  # 1 when the pane's slab was drawn (pass or mirror), 0 for a gap or a scatter


@wp.func
def surface_event(scene: SceneRec, face: int, d: wp.vec3, ng: wp.vec3, p: wp.vec3, u: float) -> SurfaceEvent:
    """What a path ray along ``d`` does at ``face`` (hit at p), drawn with the uniform ``u``, and its
    weight (module docstring); a matte face scatters."""
    ev = SurfaceEvent()
    ev.kind = SCATTER
    ev.weight = 1.0
    ev.slab = 0
    sid = scene.surf_id[face]
    if sid < 0:
        return ev
    s = scene.surf[sid]
    x = u
    c = coverage_at(scene, s, face, p)
    if s.pane == 2:  # a translucent layer: its share c scatters, its gap is the slab
        if x < c:
            return ev
        x = (x - c) / (1.0 - c)  # uniform again on [0, 1)
    elif c < 1.0:
        if x >= c:
            ev.kind = PASS
            return ev
        x = x / c  # uniform again on [0, 1)
    if s.pane == 0:
        return ev
    rt = pane_rt(scene, face, d, ng)
    if rt[0] + rt[1] <= 0.0:
        ev.kind = ABSORB
        return ev
    ev.slab = 1
    ev.weight = rt[0] + rt[1]  # R/(1 − q) = T/q with q = T/(T + R)
    if x * ev.weight < rt[0]:
        ev.kind = MIRROR
    else:
        ev.kind = PASS
    return ev


@wp.func
def next_hit_past(scene: SceneRec, o: wp.vec3, d: wp.vec3, h: RayHit) -> RayHit:
    """The next face along the ray (o, d) past its hit ``h``, its distance still measured from o (the
    query starts a rounding offset past h, :func:`.rays.offset_length`); face −1 where it escapes."""
    start = h.t + offset_length(scene, o + h.t * d)
    nxt = first_hit(scene, o + start * d, d, 1.0e30)
    if nxt.face >= 0:
        nxt.t = nxt.t + start
    return nxt


@wp.struct
class Passage:
    hit: RayHit  # the face where the ray stops (distance from the original origin), face −1: it escaped
    event: int  # what it does there: SCATTER, MIRROR or ABSORB (PASS is followed)
    rng: wp.uint32
    weight: float  # the product of the events' weights: the passes' and the stop's (a mirror's R + T)
    t_weight: float  # distance of the first face whose weight is not 1 (RAY_INF for none)


@wp.func
def walk(scene: SceneRec, o: wp.vec3, d: wp.vec3, first: RayHit, rng_in: wp.uint32, t_cut: float) -> Passage:
    """Follow the ray (o, d), whose first hit is ``first``, through every surface it passes
    (:func:`surface_event`) to the one where it stops, or to the first face at or past the distance
    ``t_cut`` (not drawn: its hit is returned with event SCATTER, and the weight is that of the faces in
    front of it). Distances stay measured from o along d, so lights in front of the stop are found along
    the same line; past :data:`MAX_PASSES` surfaces the ray is absorbed."""
    out = Passage()
    out.weight = 1.0
    out.t_weight = RAY_INF
    rng = rng_in
    h = first
    out.event = SCATTER
    for k in range(MAX_PASSES):
        if h.face < 0 or h.t >= t_cut:
            out.hit = h
            out.rng = rng
            return out
        ev = surface_event(scene, h.face, d, h.ng, o + h.t * d, wp.randf(rng))
        if ev.slab != 0:
            out.weight = out.weight * ev.weight
            out.t_weight = wp.min(out.t_weight, h.t)
        if ev.kind != PASS:
            out.hit = h
            out.event = ev.kind
            out.rng = rng
            return out
        h = next_hit_past(scene, o, d, h)
    out.hit = h
    out.event = ABSORB
    out.rng = rng
    return out


@wp.func
def pass_through(scene: SceneRec, o: wp.vec3, d: wp.vec3, first: RayHit, rng_in: wp.uint32) -> Passage:
    """:func:`walk` to where the ray stops."""
    return walk(scene, o, d, first, rng_in, RAY_INF)


@wp.func
def mirror(d: wp.vec3, ng: wp.vec3) -> wp.vec3:
    """The mirror image of direction d in the plane of unit normal ng."""
    return d - (2.0 * wp.dot(d, ng)) * ng
