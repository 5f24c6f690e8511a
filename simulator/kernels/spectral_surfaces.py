"""Coloured glossy faces and coloured panes per hero lane (spectral mode), as ``@wp.func``.

Grey transport reads each glossy face's BSDF and each pane's slab with
luminance greys (:mod:`.bsdf`, :mod:`.surfaces`). In spectral mode a surface
row marked coloured (``scene.spectral_surface[row]``: (coloured, specular
row, transmittance row), built by :func:`simulator.spectra.hero._surface_rows`)
is evaluated once per hero lane λ_k:

- the BSDF with the face's ρ(λ_k) (``scene.spectral_reflectance`` at the
  face's row) in place of its grey albedo, so the metallic workflow's
  F0 = (1 − m)·((1 − ior)/(1 + ior))² + m·ρ(λ), F90 = (1 − m) + m·ρ(λ) and
  the diffuse ρ_d = (1 − m)·ρ(λ) follow the colour (a gold mirror reflects
  ρ(λ) at every angle); the specular workflow's F0 = specularColor(λ), its
  Mallett–Yuksel uplift (the specular row). The dielectric's Fresnel term
  ((1 − ior)/(1 + ior))² stays grey: no dispersion is read (one ior for
  every wavelength);
- a pane with a measured T0(λ) (the transmittance row) with the internal
  transmittance τ0(λ_k) that gives T0(λ_k) at normal incidence
  (:func:`lane_tau`, the quadratic of
  :func:`simulator.scene.surfaces.internal_transmittance`), then the slab at
  the ray's angle per lane (:func:`.surfaces.slab_rt`); the ior is grey.

The kernels keep their grey draws (directions, pass or reflect events) and
weigh each lane by its value over the grey one the draw used: a factor per
lane the path's tint takes (unbiased per lane, as long as the grey value is
> 0 wherever a lane's is, which holds: a grey of 0 is an all-zero colour).
"""

import warp as wp

from .bsdf import Bsdf, bsdf_f, mirror_reflectance, preview_bsdf
from .coverage import coverage_at
from .lights import RAY_INF, LightSample, SceneRec
from .rays import RayHit, first_hit, offset_length
from .shadows import shadow_segment
from .records import TraceParams
from .surfaces import (ABSORB, MAX_PASSES, MIRROR, PASS, SCATTER, Passage, next_hit_past, pane_rt, pass_factor,
                       pass_through, slab_rt, surface_event, walk)


@wp.func
def coloured_row(scene: SceneRec, face: int) -> wp.vec3i:
    """(coloured, specular row, transmittance row) of triangle ``face``'s surface row; coloured 0 for a
    matte face."""
    sid = scene.surf_id[face]
    if sid < 0:
        return wp.vec3i(0, -1, -1)
    return scene.spectral_surface[sid]


@wp.func
def lane_bsdf(scene: SceneRec, face: int, hero: wp.vec4i, k: int) -> Bsdf:
    """The BSDF of a glossy triangle at hero lane k: its surface row's lobes over ρ(λ_k) of the face,
    F0 = specularColor(λ_k) in the specular workflow when the row has a specular row."""
    s = scene.surf[scene.surf_id[face]]
    rho = scene.spectral_reflectance[scene.spectral_face[face], hero[k]]
    spec = s.specular
    rows = coloured_row(scene, face)
    if rows[1] >= 0:
        spec = scene.spectral_reflectance[rows[1], hero[k]]
    return preview_bsdf(rho, s.roughness, s.metallic, s.ior, spec, s.workflow, s.coat, s.coat_roughness)


@wp.func
def bsdf_lanes(scene: SceneRec, face: int, hero: wp.vec4i, wi: wp.vec3, wo: wp.vec3) -> wp.vec4:
    """f(wi, wo) of a glossy triangle at each hero lane (local frame), sr⁻¹."""
    out = wp.vec4(0.0, 0.0, 0.0, 0.0)
    for k in range(4):
        out[k] = bsdf_f(lane_bsdf(scene, face, hero, k), wi, wo)
    return out


@wp.func
def mirror_lanes(scene: SceneRec, face: int, hero: wp.vec4i, co: float) -> wp.vec4:
    """A mirror triangle's reflectance F(co) at each hero lane."""
    out = wp.vec4(0.0, 0.0, 0.0, 0.0)
    for k in range(4):
        out[k] = mirror_reflectance(lane_bsdf(scene, face, hero, k), co)
    return out


@wp.func
def lane_ratio(lanes: wp.vec4, grey: float) -> wp.vec4:
    """Each lane's value over the grey one a draw used (0 where the grey is 0)."""
    if grey <= 0.0:
        return wp.vec4(0.0, 0.0, 0.0, 0.0)
    return lanes / grey


@wp.func
def lane_tau(t0: float, n: float) -> float:
    """τ0 in (0, 1] for which a slab of index n transmits t0 at normal incidence: the positive root of
    t0·r²·τ² + (1 − r)²·τ − t0 = 0, r = ((n − 1)/(n + 1))² (t0 = 0 gives 0)."""
    r = (n - 1.0) / (n + 1.0)
    r = r * r
    a = t0 * r * r
    b = (1.0 - r) * (1.0 - r)
    if a <= 0.0:
        return wp.min(1.0, t0 / b)
    return wp.min(1.0, (-b + wp.sqrt(b * b + 4.0 * a * t0)) / (2.0 * a))


@wp.struct
class LaneRT:
    r: wp.vec4  # slab reflectance per hero lane
    t: wp.vec4  # slab transmittance per hero lane


@wp.func
def pane_lanes(scene: SceneRec, face: int, hero: wp.vec4i, d: wp.vec3, ng: wp.vec3) -> LaneRT:
    """The pane of ``face`` at each hero lane along d: its T0(λ_k) slab's (R, T), or the grey slab's in
    every lane where the row has no measured T0(λ) or the ray leaves a closed pane ((0, 1))."""
    rows = coloured_row(scene, face)
    rt = pane_rt(scene, face, d, ng)
    out = LaneRT()
    out.r = wp.vec4(rt[0], rt[0], rt[0], rt[0])
    out.t = wp.vec4(rt[1], rt[1], rt[1], rt[1])
    if rows[2] < 0:
        return out
    s = scene.surf[scene.surf_id[face]]
    side = scene.surf_side[face]
    cosd = wp.dot(d, ng)
    if side != 0:
        if not ((cosd < 0.0) == (side > 0)):
            return out  # leaving a closed pane: (0, 1), as pane_rt says
    for k in range(4):
        lane = slab_rt(cosd, s.ior, lane_tau(scene.spectral_reflectance[rows[2], hero[k]], s.ior))
        out.r[k] = lane[0]
        out.t[k] = lane[1]
    return out


@wp.func
def transmittance_lanes(scene: SceneRec, hero: wp.vec4i, o: wp.vec3, wi: wp.vec3, dist: float, tri: int) -> wp.vec4:
    """Per hero lane, what :func:`.surfaces.transmittance_along` multiplies over the segment, each
    coloured pane's factor (1 − c) + c·T(λ_k) in its lane; the faces met are the same."""
    f = wp.vec4(1.0, 1.0, 1.0, 1.0)
    if scene.has_mesh == 0:
        return f
    start = float(0.0)
    end = dist
    if tri >= 0:
        end = dist * 1.001
    for k in range(MAX_PASSES):
        h = first_hit(scene, o + start * wi, wi, end - start)
        if h.face < 0 or h.face == tri:
            return f
        p = o + (start + h.t) * wi
        rows = coloured_row(scene, h.face)
        if rows[2] >= 0:
            c = coverage_at(scene, scene.surf[scene.surf_id[h.face]], h.face, p)
            t = pane_lanes(scene, h.face, hero, wi, h.ng).t
            for j in range(4):
                f[j] = f[j] * ((1.0 - c) + c * t[j])
        else:
            g = pass_factor(scene, h.face, wi, h.ng, p)
            f = f * g
        if f[0] <= 0.0 and f[1] <= 0.0 and f[2] <= 0.0 and f[3] <= 0.0:
            return wp.vec4(0.0, 0.0, 0.0, 0.0)
        start = start + h.t + offset_length(scene, p)
        if start >= end:
            return f
    return wp.vec4(0.0, 0.0, 0.0, 0.0)


@wp.func
def shadow_lanes(scene: SceneRec, hero: wp.vec4i, o: wp.vec3, p: wp.vec3, li: int, ls: LightSample) -> wp.vec4:
    """:func:`.shadows.shadow_ray_pass` per hero lane (:func:`transmittance_lanes` on its segment)."""
    if scene.has_mesh == 0:
        return wp.vec4(1.0, 1.0, 1.0, 1.0)
    seg = shadow_segment(scene, o, p, li, ls)
    if seg[3] <= 0.0:
        return wp.vec4(1.0, 1.0, 1.0, 1.0)
    return transmittance_lanes(scene, hero, o, wp.vec3(seg[0], seg[1], seg[2]), seg[3], ls.tri)


@wp.struct
class LanePassage:
    hit: RayHit  # as Passage
    event: int
    rng: wp.uint32
    tint: wp.vec4  # per hero lane: each pass and reflection's lane value over the grey one it was drawn by
    t_tint: float  # distance (from o) of the first coloured pane that set a lane factor; RAY_INF for none
    weight: float  # the grey weights, as Passage (kernels.surfaces.walk)
    t_weight: float


@wp.func
def grey_lanes(pas: Passage) -> LanePassage:
    """The grey walk ``pas`` with lane factor 1 and no coloured pane (``t_tint`` RAY_INF)."""
    out = LanePassage()
    out.hit = pas.hit
    out.event = pas.event
    out.rng = pas.rng
    out.tint = wp.vec4(1.0, 1.0, 1.0, 1.0)
    out.t_tint = RAY_INF
    out.weight = pas.weight
    out.t_weight = pas.t_weight
    return out


@wp.func
def walk_lanes(scene: SceneRec, hero: wp.vec4i, o: wp.vec3, d: wp.vec3, first: RayHit, rng_in: wp.uint32,
               t_cut: float) -> LanePassage:
    """:func:`.surfaces.walk` (the same draws: one uniform per face, in order, and the same grey weights)
    which also returns the lane factors of the faces nearer than ``t_cut``."""
    out = LanePassage()
    out.tint = wp.vec4(1.0, 1.0, 1.0, 1.0)
    out.t_tint = RAY_INF
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
        p = o + h.t * d
        ev = surface_event(scene, h.face, d, h.ng, p, wp.randf(rng))
        if ev.slab != 0:  # the pane's slab: its grey weight, and its lane weights on a coloured pane
            out.weight = out.weight * ev.weight
            out.t_weight = wp.min(out.t_weight, h.t)
            if coloured_row(scene, h.face)[2] >= 0:
                rt = pane_rt(scene, h.face, d, h.ng)
                lanes = pane_lanes(scene, h.face, hero, d, h.ng)
                if ev.kind == MIRROR:
                    out.tint = wp.cw_mul(out.tint, lane_ratio(lanes.r, rt[0]))
                else:
                    out.tint = wp.cw_mul(out.tint, lane_ratio(lanes.t, rt[1]))
                out.t_tint = wp.min(out.t_tint, h.t)
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
def pass_through_lanes(scene: SceneRec, hero: wp.vec4i, o: wp.vec3, d: wp.vec3, first: RayHit,
                       rng_in: wp.uint32) -> LanePassage:
    """:func:`.surfaces.pass_through` with the same draws (one uniform per face, :func:`.surfaces.
    surface_event`), which also returns the lane factor of the events drawn: 1 through a coverage gap,
    T(λ_k)/T through a pane's slab, R(λ_k)/R off it (the pane's lanes, :func:`pane_lanes`), and where
    along the ray the first such factor applies. A light met before that distance is seen with the
    lanes as they were; one met past it takes the factors of the panes in front of it only
    (:func:`walk_before`)."""
    return walk_lanes(scene, hero, o, d, first, rng_in, RAY_INF)


@wp.func
def pass_through_traced(scene: SceneRec, params: TraceParams, o: wp.vec3, d: wp.vec3, first: RayHit,
                        rng_in: wp.uint32) -> LanePassage:
    """The walk a traced ray takes through panes and cut-outs: :func:`pass_through_lanes` in a spectral
    run with coloured panes, else :func:`.surfaces.pass_through` with lane factor 1 (:func:`grey_lanes`),
    so callers keep one set of lanes either way."""
    if params.spectral != 0 and scene.spectral_panes != 0:
        return pass_through_lanes(scene, params.hero, o, d, first, rng_in)
    return grey_lanes(pass_through(scene, o, d, first, rng_in))


@wp.func
def walk_before(scene: SceneRec, params: TraceParams, o: wp.vec3, d: wp.vec3, first: RayHit, rng_in: wp.uint32,
                t_light: float) -> LanePassage:
    """The walk :func:`pass_through_traced` took from ``first`` with ``rng_in``, replayed with the same
    uniforms (so its events are the same) and cut at a light met at ``t_light``: its lane factors
    (``tint``) and grey weight are those of the faces between o and the light only (faces past it pass
    or reflect light that never reached it)."""
    if params.spectral != 0 and scene.spectral_panes != 0:
        return walk_lanes(scene, params.hero, o, d, first, rng_in, t_light)
    return grey_lanes(walk(scene, o, d, first, rng_in, t_light))


