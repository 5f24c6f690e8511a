"""Monte Carlo estimators of sensor readings: the Warp kernel entry point.

One kernel, :func:`estimate_kernel`, serves every sensor kind and every
sampling method; :class:`TraceParams` switches the strategies, so its
module compiles once and the kernel cache serves every run. It comes in two
variants built from the same source (:func:`make_trace`): with the surface
model (panes, cut-outs, glossy faces) and without it, for all-matte stages.

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

import functools
import math
from dataclasses import dataclass
from typing import Any, Callable

import warp as wp

from simulator.scene.model import LightKind, Sensor, SensorKind

from .group_tally import clear_group_sample, fold_group_sample, tally_group, tregenza_patch
from .guide import glossy_mixture_factor, guide_fraction, guide_row, make_guided_step, mixture_factor, pdf_guide, tally_patch
from .light_pick import (LM_TO_W, LightPick, computed_at, is_delta, pick_light_at, pick_scale, picks_at,
                         tally_patch_pick, tally_pick)
from .lights.emissive import pdf_at as emissive_pdf_at
from .lights.emissive import sample_piece
from .lights.base import empty_sample
from .lights.rect import pdf_field as rect_pdf_field
from .lights.rect import sample_field as rect_sample_field
from .lights import (  # noqa: F401  (GuideRec, LightRec, SceneRec re-exported for the engine)
    RAY_INF,
    GuideRec,
    LightRec,
    SceneRec,
    analytic_light,
    analytic_patch_light,
    escaped_radiance,
    kind_chain,
    pdf_light,
    sample_light,
    tri_emitted,
)
from .rays import RayHit, count_ray, count_shadow_ray, first_hit, near_light, offset_length, unoccluded  # noqa: F401  (unoccluded: probes)
from .records import SensorRec, TraceParams
from .sampling import (
    INV_PI,
    PI,
    hero_stream_key,
    pdf_cosine_hemisphere,
    sample_cosine_hemisphere,
    sample_uniform_cone,
    frame_x,
    frame_y,
    sensor_stream_key,
    to_world,
)
from .shadows import hit_light_before, shadow_ray_clear, shadow_ray_pass
from .surfaces import ABSORB, MIRROR, mirror, transmittance_along
from .bsdf import Bsdf, bsdf_f, bsdf_pdf, bsdf_sample, lobe_weights, mirror_reflectance
from .glossy import face_bsdf, is_glossy, is_shaded, mirror_share, spawn_origin, vertex_normal
from .mirrors import (
    ImageSample, area_image, area_image_mirror_prob, has_area_image, has_image, image_light_pdf, image_may_exist, image_source,
    is_cone_light, mirror_event_prob,
)
from .curved import curve_covers
from .glints import glint_pdf, glint_sample, glint_share
from .surface_rec import GlintRec
from .shaping import shaping_factor
from .optics import optics_field, optics_frame_x, optics_narrow, optics_pdf, optics_to_world, optics_weight, sample_optics
from .spectral import Reflection, hero_nodes, lane_response, spectral_contribution, spectral_row
from .spectral_surfaces import (
    bsdf_lanes, coloured_row, lane_ratio, mirror_lanes, pass_through_traced, shadow_lanes, walk_before,
    transmittance_lanes,
)

# Forward-only: no gradients are taken, and skipping the adjoint halves compile time.
wp.set_module_options({"enable_backward": False})


#: clang's optimisation level for the trace modules. Measured on the all-matte module (CPU seconds of
#: the compile, a shared 2-core machine): O2 (Warp's CPU default) 64.8 s, O1 49.3 s; the trace's CPU
#: time the same within the noise (furnace, 4,096 samples: 5.7-6.5 s both) and every reading the same
#: bytes (quickstart, furnace, office_bench CSVs and maps): without fast-math clang keeps each float
#: operation as written at any level, FMAs are formed per expression by the front end, and the raised
#: inlining thresholds (``engine.device.INLINE_THRESHOLDS``) apply at O1 too (docs/DESIGN.md §Kernel modules).
TRACE_OPTIMIZATION_LEVEL = 1


def trace_module(surfaces: bool) -> str:
    """The Warp module of one trace variant: its :func:`estimate_kernel` and its probe kernel
    (:func:`.probe.make_probe_kernel`), compiled together so that the path functions they share
    are compiled once, and apart from the other variant so that a run compiles only its stage's
    (docs/DESIGN.md §Kernel modules). The ``@wp.func``s stay in this module; a kernel's module
    holds the code of every function it calls."""
    name = f"{__name__}.trace_{'surfaces' if surfaces else 'matte'}"
    options = {"enable_backward": False, "optimization_level": TRACE_OPTIMIZATION_LEVEL}
    current = wp.get_module_options(name)
    if any(current.get(k) != v for k, v in options.items()):  # setting them drops the module's hash: once
        wp.set_module_options(options, module=name)
    return name

# A path whose every bounce survives Russian roulette with probability ρ < 1
# ends with probability one; this cap only guards against ρ rounding to 1.
# At ρ = 0.999 it drops a fraction 0.999^65536 ≈ 4e-29 of the light.
MAX_VERTICES = wp.constant(65536)
# a radiance meter's ray reflected off more panes than this (two facing panes) is taken as absorbed
MAX_MIRRORS = wp.constant(64)
# a rect light: sampled within a narrow head's field at the head's own vertex (kernels.lights.rect.sample_field)
_RECT_LIGHT = wp.constant(int(LightKind.RECT))

# Russian roulette weight window: a path's throughput β never falls below
# TraceParams.rr_threshold (see vertex_irradiance); the engine sets it per
# run from the scene's albedo, by the rule and the measurements at
# simulator.engine.methods.rr_threshold_rule (0.1 in a room, down to 0.01 in
# an enclosure of high albedo).


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
def tallied_contribution(
    scene: SceneRec, params: TraceParams, row: int, group: int, value: wp.vec2, tint: wp.vec4
) -> wp.vec2:
    """An emitted share ``value`` (W and lm channels) of one sample as the
    trace counts it: spectral transport tallies its lanes with emission row
    ``row`` and passes on its spectral (W, lm) responses (grey transport
    passes ``value`` on); with ``params.group_tally`` what is passed on is
    also added to this sample's slot of light group ``group`` (none for
    ``group`` < 0), in the thread's state (see :class:`TraceParams`)."""
    v = value
    if params.spectral != 0:
        v = spectral_contribution(scene, params, row, value, tint)
    if params.group_tally != 0:
        tally_group(params, group, v)
    return v


@wp.func
def light_group_of(scene: SceneRec, params: TraceParams, li: int) -> int:
    """The light group of light record ``li`` while groups are tallied (−1
    for none, for ``li`` = −1, and when ``params.group_tally`` is off: the
    table is then not read at all)."""
    if params.group_tally == 0 or li < 0:
        return -1
    return scene.light_group[li]


@wp.func
def light_contribution(scene: SceneRec, params: TraceParams, li: int, value: wp.vec2, tint: wp.vec4) -> wp.vec2:
    """Light ``li``'s share ``value`` of one sample, as the trace tallies it
    (:func:`tallied_contribution`: its emission row and its group); ``tint``
    is the path's spectral tint there (see :class:`Reflection`). Every place
    a sample adds emitted light goes through here or through its two
    variants below, so per-light tallies (light groups) and per-light
    scalings have one hook."""
    return tallied_contribution(scene, params, li, light_group_of(scene, params, li), value, tint)


@wp.func
def emissive_contribution(scene: SceneRec, params: TraceParams, face: int, value: wp.vec2, tint: wp.vec4) -> wp.vec2:
    """:func:`light_contribution` of emissive triangle ``face`` (its record
    ``params.emissive_light``). Spectral transport reads the face's own
    emission row, ``scene.spectral_face_emission[face]`` (a coloured
    ``emissiveColor``), where it has one (≥ 0), else the record's; the
    light-group tally stays the record's."""
    li = params.emissive_light
    row = li
    if params.spectral != 0 and face >= 0:
        own = scene.spectral_face_emission[face]
        if own >= 0:
            row = own
    return tallied_contribution(scene, params, row, light_group_of(scene, params, li), value, tint)


@wp.func
def light_contribution_dir(scene: SceneRec, params: TraceParams, li: int, value: wp.vec2, tint: wp.vec4,
                           wi: wp.vec3) -> wp.vec2:  # fmt: skip
    """:func:`light_contribution` for light arriving along ``wi`` (toward the light): a dome split into
    sky patches (``scene.patch_base[li]`` ≥ 0) tallies it in the group of the patch ``wi`` points
    into, ``patch_base + tregenza_patch(wi)`` (146 slots: 145 patches and the ground)."""
    group = light_group_of(scene, params, li)
    if params.group_tally != 0 and li >= 0:
        pb = scene.patch_base[li]
        if pb >= 0:
            group = pb + tregenza_patch(wi)
    return tallied_contribution(scene, params, li, group, value, tint)


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


@wp.func
def image_lanes(scene: SceneRec, params: TraceParams, im: ImageSample, tint: wp.vec4, o: wp.vec3) -> wp.vec4:
    """``tint`` × the lanes of a light seen in a mirror (:mod:`.mirrors`), spectral mode: the mirror's
    coloured reflectance and the coloured panes on the way to the mirror and from it to the light, each
    over the grey share the sample already carries."""
    tint_m = tint
    if im.pane == 0 and coloured_row(scene, im.face)[0] != 0:
        tint_m = wp.cw_mul(tint_m, lane_ratio(mirror_lanes(scene, im.face, params.hero, im.cos_m), im.refl))
    if scene.spectral_panes != 0:
        vis4 = transmittance_lanes(scene, params.hero, im.m_off, im.to_l, im.dist_l, im.tri)
        tint_m = wp.cw_mul(tint_m, lane_ratio(vis4, im.vis))
        if im.vis_in < 1.0:  # the panes before the mirror, per lane
            vin4 = transmittance_lanes(scene, params.hero, o, im.wi, im.t_m - offset_length(scene, o + im.t_m * im.wi), -1)
            tint_m = wp.cw_mul(tint_m, lane_ratio(vin4, im.vis_in))
    return tint_m


@wp.func
def to_local(v: wp.vec3, n: wp.vec3) -> wp.vec3:
    """v in the frame of :func:`to_world` about n (its inverse)."""
    return wp.vec3(wp.dot(v, frame_x(n)), wp.dot(v, frame_y(n)), wp.dot(v, n))


@functools.cache
def make_lights_seen_along(surfaces: bool):
    """:func:`lights_seen_along` of one trace variant (:func:`make_trace`): with ``surfaces`` False no
    face weighs or colours a ray (``t_w`` and ``t_tint`` stay ``RAY_INF``), so the walk replayed past
    one is left out of the generated code."""

    @wp.func
    def lights_seen_along(scene: SceneRec, params: TraceParams, total_in: wp.vec2, o: wp.vec3, d: wp.vec3, t_stop: float,
                          first: RayHit, rng0: wp.uint32, w: float, t_w: float, tint: wp.vec4, t_tint: float) -> wp.vec2:
        """``total_in`` plus the radiance a meter's ray (o, d) receives from the UsdLux area lights it meets before ``t_stop``
        (they do not block), each × ``w`` and the lanes ``tint`` its segment carried in, and × the weights
        and lanes of the faces between o and the light when it lies past the first weighted face (``t_w``)
        or coloured pane (``t_tint``) of the walk from ``first`` (:func:`.spectral_surfaces.walk_before`
        replays it with the same uniforms), added light by light."""
        total = total_in
        for li in range(scene.n_lights):
            l = scene.lights[li]
            t_l = hit_light_before(l, o, d, t_stop)
            if t_l > 0.0:
                tint_l = tint
                w_l = w
                if (t_l >= wp.min(t_tint, t_w)) if wp.static(surfaces) else False:
                    wb = walk_before(scene, params, o, d, first, rng0, t_l)
                    tint_l = wp.cw_mul(tint, wb.tint)
                    w_l = w * wb.weight
                total += light_contribution(scene, params, li, (w_l * shaping_factor(l, -d)) * l.emission, tint_l)
        return total

    return lights_seen_along


@wp.func
def matte_dir_pdf(glints: wp.array(dtype=GlintRec), n_glints: int, p: wp.vec3, n: wp.vec3, c_v: float, gw: float,
                  wi: wp.vec3) -> float:
    """A matte vertex's direction density p_dir(ω) (sr⁻¹) with the glint strategy drawn with probability
    gw of its direction samples, which run with 1 − c_v: (1 − c_v)·((1 − gw)·cosθ/π + gw·p_glint(ω))."""
    return (1.0 - c_v) * ((1.0 - gw) * pdf_cosine_hemisphere(wp.dot(wi, n)) + gw * glint_pdf(glints, n_glints, p, wi))


@wp.func
def cylinder_normal(s: SensorRec, phi: float) -> wp.vec3:
    """The outward normal at azimuth ``phi`` about the axis ``s.up``, from ``s.right`` (the facing) toward ``up × right``."""
    return wp.cos(phi) * s.right + wp.sin(phi) * wp.cross(s.up, s.right)


@wp.func
def analytic_cylinder(scene: SceneRec, s: SensorRec, half: int) -> wp.vec2:
    """Point lights on a (semi-)cylinder in closed form: the irradiance on the normal toward the light's
    projection across the axis is I·sinθ/d², and the mean over the (half) surface is that × (1 + cos φ)/π
    for a half facing φ away, 1/π for the whole (the planner sends only point lights here)."""
    v = wp.vec2(0.0, 0.0)
    for li in range(scene.n_lights):
        l = scene.lights[li]
        w = l.position - s.position
        across = w - wp.dot(w, s.up) * s.up
        la = wp.length(across)
        if la <= 0.0:
            continue  # on the axis: sinθ = 0
        n = across / la
        e = analytic_light(scene, li, s.position, n)
        if l.shaped != 0:
            e = e * shaping_factor(l, wp.normalize(s.position - l.position))
        f = 1.0 / PI
        if half != 0:
            f = (1.0 + wp.dot(n, s.right)) / PI
        v += f * e
    return v


@wp.func
def analytic_cylindrical(scene: SceneRec, s: SensorRec) -> wp.vec2:
    return analytic_cylinder(scene, s, 0)


@wp.func
def analytic_semicylindrical(scene: SceneRec, s: SensorRec) -> wp.vec2:
    return analytic_cylinder(scene, s, 1)


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


def _upload_cylinder(rec, sensor: Sensor) -> None:
    # axis in ``up``, the facing (a whole cylinder's azimuth origin) in ``right``, orthogonal to it
    rec.up = wp.vec3(*map(float, sensor.up))
    rec.right = wp.vec3(*map(float, sensor.normal))


def _upload_patch(rec, sensor: Sensor) -> None:
    from simulator.scene.model import patch_width_axis

    rec.right = wp.vec3(*map(float, patch_width_axis(sensor.up, sensor.normal)))
    rec.up = wp.vec3(*map(float, sensor.up))
    rec.width, rec.height = float(sensor.size[0]), float(sensor.size[1])


@dataclass(frozen=True)
class SensorKernel:
    """One sensor kind's device side (its other facts: ``SensorKindSpec``).

    ``sample`` names the function ``(scene, s, params, rng) -> vec2`` that
    draws one sample of the reading, among the samplers :func:`make_trace`
    writes (``Trace.samplers``: one per trace variant); ``analytic(scene,
    s) -> vec2`` is its closed form, if any; ``upload(rec, sensor)`` fills
    its fields of the :class:`SensorRec`."""

    kind: SensorKind
    sample: str
    analytic: Any = None
    upload: Callable | None = None


#: sensor kinds read by :func:`estimate_kernel` (probes have their own kernel)
SENSOR_KERNELS = (
    SensorKernel(SensorKind.IRRADIANCE, "sample_irradiance", analytic=analytic_irradiance),
    SensorKernel(SensorKind.RADIANCE, "sample_radiance", upload=_upload_radiance),
    SensorKernel(SensorKind.PATCH, "sample_patch", analytic=analytic_patch, upload=_upload_patch),
    SensorKernel(SensorKind.CYLINDRICAL, "sample_cylindrical", analytic=analytic_cylindrical, upload=_upload_cylinder),
    SensorKernel(SensorKind.SEMICYLINDRICAL, "sample_semicylindrical", analytic=analytic_semicylindrical,
                 upload=_upload_cylinder),
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


_analytic_chain = kind_chain(
    tuple((int(k.kind), k.analytic) for k in SENSOR_KERNELS if k.analytic is not None), _analytic_link, _no_analytic
)


@wp.func
def analytic_sensor(scene: SceneRec, s: SensorRec) -> wp.vec2:
    """Closed-form reading of sensor ``s`` (dispatch over ``SENSOR_KERNELS``)."""
    return _analytic_chain(scene, s)


def sensor_record(sensor: Sensor, optics: int = 0) -> SensorRec:
    """The device record of one sensor: common fields, then its kind's ``upload``. ``optics``: k ≥ 1 when
    ``sensor.optics`` is row k − 1 of the scene's optics table (its azimuth reference goes in ``right``)."""
    r = SensorRec()
    r.kind = int(sensor.kind)
    r.position = wp.vec3(*map(float, sensor.position))
    r.normal = wp.vec3(*map(float, sensor.normal))
    r.one_minus_cos = 0.0
    r.cull = 1 if sensor.spec.culls_lights else 0
    r.optics = int(optics)
    for k in SENSOR_KERNELS:
        if k.kind == sensor.kind and k.upload is not None:
            k.upload(r, sensor)
    if optics > 0 and sensor.kind == SensorKind.IRRADIANCE and sensor.azimuth_ref is not None:
        r.right = wp.vec3(*map(float, sensor.azimuth_ref))
    return r


# ---------------------------------------------------------------- trace variants


@dataclass(frozen=True)
class Trace:
    """The path functions and the estimator kernel of one trace variant (:func:`make_trace`)."""

    surfaces: bool  # whether the surface model (panes, cut-outs, glossy faces) is compiled in
    vertex_estimate: Any
    vertex_irradiance: Any
    sample_radiance: Any  # also the probe kernel's (kernels.probe)
    samplers: dict  # the per-sample entries by name (SensorKernel.sample)
    sample_sensor: Any
    estimate_kernel: Any
    piece_table_kernel: Any  # the emitter pieces' table per cell (simulator.engine.piece_table)


@functools.cache
def make_trace(surfaces: bool) -> Trace:
    """The trace functions and :func:`estimate_kernel`, with the surface
    model (``SceneRec.surfaces``: panes, cut-outs and glossy faces,
    :mod:`.surfaces`, :mod:`.glossy`) compiled in or not.

    Every test of ``scene.surfaces`` below reads ``(test) if
    wp.static(surfaces) else <its all-matte value>``. With ``surfaces`` True
    that is the runtime test as written, and the kernel is the one every
    stage ran before the variants (it still reads ``scene.surfaces``, so it
    is right on any stage). With False Warp folds the condition to a
    constant and leaves the untaken branch out of the generated code: the
    BSDF record, flags and directions a glossy vertex carries are then no
    live state in the vertex loop of an all-matte stage, which takes the
    same branches, the same draws and so the same bytes either way. The
    engine launches the matte variant where ``SceneRec.surfaces`` is 0
    (:func:`trace_for`).

    Each variant is built on first use (:func:`trace_for`);
    its kernels live in a Warp module of their own (:func:`trace_module`),
    so a run defines, compiles and loads only its stage's and Warp's kernel
    cache serves each (docs/DESIGN.md §Trace variants, §Kernel modules,
    §Start-up of a small run)."""
    guided_step = make_guided_step(surfaces)
    lights_seen_along = make_lights_seen_along(surfaces)

    @wp.func
    def vertex_estimate(
        scene: SceneRec, p_in: wp.vec3, n_in: wp.vec3, weight_in: float, params: TraceParams, skip_first: int,
        rng_in: wp.uint32, face_in: int, wo_in: wp.vec3
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
        not counted: those two strategies already cover all direct light.

        Glossy faces (``scene.surfaces``, :mod:`.glossy`): a vertex on one (the
        first when ``face_in`` is glossy, seen from ``wo_in``) weighs its light
        samples by π·f(wi, wo), draws the next direction by the BSDF (β takes
        f·cosθ/pdf) and weighs both by MIS with the BSDF's pdf; its mirror part
        is a direction chosen with probability :func:`mirror_share`, whose rays
        no light sample weighs against. With the guide, a glossy vertex draws
        it with c·(1 − P_mirror)·w_diffuse (it stands in for the diffuse lobe)
        and its lobes with the rest, every MIS weight over those real
        densities; a delta vertex (a pane's or a mirror part's reflection)
        never draws it, and the path it starts takes 1/(1 − c) instead of a
        mixture factor (docs/DESIGN.md §Surface guide)."""
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
        # a mirror reflection off a pane (scene.surfaces only, see kernels.surfaces): the next vertex p is
        # that delta vertex; the ray leaves it along spec_d, with no light sample there and no MIS weight on
        # what that ray meets (no light sample could have found it); β and the weight are unchanged, since
        # the reflection was chosen with the probability R it weighs
        delta = int(0)
        spec_d = wp.vec3(0.0, 0.0, 1.0)
        # the vertex on a glossy face: its BSDF, and the direction toward the vertex before it
        gl = int(0)
        bs = Bsdf()
        wo_g = wo_in
        g_face = int(-1)  # the glossy vertex's triangle
        g_lanes = int(0)  # 1: its BSDF is evaluated per hero lane (spectral mode, a coloured row)
        img_prev = int(0)  # 1: the vertex before p ran the image-source connection (kernels.mirrors)
        # a sensor model's angular response r(ω) at the sensor's own vertex (kernels.optics; params.optics > 0,
        # depth 0): light samples weigh r(ω)/cosθ, the direction is drawn by r (pdf in every MIS weight),
        # and the guide and glints, strategies of cosine vertices, are not drawn there; a narrow head
        # (f_on) draws a rect light's samples toward r, within its field (cos α = f_cos; −1: the whole
        # light; kernels.optics.optics_field, kernels.lights.rect.sample_field)
        opt = params.optics
        opt_x = wp.vec3(1.0, 0.0, 0.0)
        rr_t = params.rr_threshold  # the roulette's threshold on β: a head's paths carry ∫r dω/π of a cosine's
        f_on = int(0)
        f_cos = float(-1.0)
        if opt > 0:
            opt_x = optics_frame_x(params.optics_x, n_in)
            rr_t = params.rr_threshold * (scene.optics[opt - 1].integral * INV_PI)
            both = int(0)  # light samples and directions drawn by r, combined by MIS
            if params.mis != 0 and params.bsdf != 0:
                both = 1
            if optics_narrow(scene.optics[opt - 1]):
                f_on = 1
                f_cos = optics_field(scene.optics[opt - 1], both)
        # a glossy vertex's shading normal (kernels.glossy.vertex_normal; n elsewhere), and whether it has one of
        # its own (sh: its rays then leave past the face they head into, kernels.glossy.spawn_origin)
        ns = n_in
        sh = int(0)
        o_prev = p_in  # the ray origin of the vertex before p, where it ran the image sources (curved mirrors' sun)
        c_prev = int(-1)  # the curved mirror that vertex lay on (it connected none through its own)
        # the vertex before p sampled area lights in flat mirrors (kernels.mirrors.area_image): its point, the
        # normal its light samples stood on, and the path strategy's density of its direction toward p
        ia_prev = int(0)
        x_prev = p_in
        nx_prev = n_in
        pa_prev = float(0.0)
        if (scene.surfaces != 0 and is_glossy(scene, face_in)) if wp.static(surfaces) else False:
            gl = 1
            bs = face_bsdf(scene, face_in)
            g_face = face_in
            if params.spectral != 0:
                g_lanes = coloured_row(scene, face_in)[0]
        while depth < MAX_VERTICES:
            row = guide_row(scene, depth, cur_face)
            c_v = guide_fraction(scene, params, depth, row)
            if delta != 0:  # a mirror vertex on a pane follows its one direction: no guide there
                c_v = 0.0
            o_on = int(0)  # 1: this vertex is a modelled sensor's own (see opt above)
            if depth == 0 and opt > 0:
                o_on = 1
                c_v = 0.0
            # Rays leave a surface from o, pushed off it (see offset_length). A
            # sensor within that push of a UsdLux light starts them at p itself:
            # lights are not geometry, and first_hit (plane_distance) still keeps
            # the surface a sensor may lie on from shadowing it.
            o = p
            off = offset_length(scene, p)
            if scene.has_mesh != 0 and (depth > 0 or not near_light(scene, p, off)):
                o = p + off * n
            count = not (skip_first != 0 and depth == 0)
            wo_l = wp.vec3(0.0, 0.0, 1.0)
            pm = float(0.0)  # probability of the glossy vertex's mirror part
            ns = n
            sh = 0
            if (gl != 0 and is_shaded(scene, g_face)) if wp.static(surfaces) else False:
                ns = vertex_normal(scene, g_face, p, n, wo_g)
                sh = 1
            if gl != 0:
                wo_l = to_local(wo_g, ns)
                pm = mirror_share(bs, wo_l[2])
                # the guide is a strategy for the diffuse lobe: it is drawn with c times the share of the
                # vertex's draws that go to that lobe, (1 − p_mirror)·w_diffuse, and the lobes with 1 − c_v
                if c_v > 0.0:
                    c_v = c_v * (1.0 - pm) * lobe_weights(bs, wo_l[2])[2]
            # a matte vertex draws the glint strategy (kernels.glints) with probability gw of its direction
            # samples where a glossy plane shows it a distant light's reflection: its direction density is
            # then p_dir(ω) = (1 − c_v)·((1 − gw)·cosθ/π + gw·p_glint(ω)) in every weight below
            gw = float(0.0)
            if (scene.n_glints > 0 and gl == 0 and delta == 0 and o_on == 0) if wp.static(surfaces) else False:
                gw = glint_share(scene.glints, scene.n_glints, p, n)
            # -- next-event estimation: each light once, or (pick_light) the
            #    delta lights and one light with area, picked with P(li | x)
            pk = LightPick()
            if params.nee != 0 and count and delta == 0:
                if picks_at(params, depth):
                    pk = pick_light_at(scene, p, n, params.mask_row, depth, cur_face, rng)
                    rng = pk.rng
                for li in range(scene.n_lights):
                    u = wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng))
                    # a light the plan proved wholly behind the sensor adds nothing there (mask 0); one
                    # whose direct light there is computed (mask 2) is not sampled there
                    if depth == 0 and params.mask_row >= 0:
                        if scene.light_mask[params.mask_row * scene.n_lights + li] != 1:
                            continue
                    sel = float(1.0)
                    if picks_at(params, depth) and not is_delta(scene.lights[li]):
                        if li != pk.li:
                            continue
                        sel = pk.prob
                    ls = empty_sample()  # geometry from the true point; only rays start at o
                    if o_on != 0 and f_on != 0 and scene.lights[li].kind == _RECT_LIGHT:  # toward r, in its field
                        fd = rect_sample_field(scene.lights[li], p, n, n, f_cos, scene.optics[opt - 1], opt_x, rng)
                        ls = fd.s
                        rng = fd.rng
                    else:
                        ls = sample_light(scene, li, p, ns, u)
                    ls.value = ls.value * (shaping_factor(scene.lights[li], -ls.wi) / sel)
                    if o_on != 0:  # the head reads L·r(ω): r(ω)/cosθ in place of the cosine ls.value carries
                        ls.value = ls.value * optics_weight(scene.optics[opt - 1], opt_x, n, ls.wi)
                    pdf_dir = float(0.0)
                    tint_l = tint  # this sample's lanes: × each lane's BSDF and visibility over the grey ones
                    if gl != 0:  # the BSDF's value and the density its direction samples give wi
                        wi_l = to_local(ls.wi, ns)
                        f_grey = bsdf_f(bs, wi_l, wo_l)
                        ls.value = ls.value * (PI * f_grey)
                        pdf_dir = (1.0 - pm) * bsdf_pdf(bs, wi_l, wo_l)
                        if g_lanes != 0:
                            tint_l = wp.cw_mul(tint_l, lane_ratio(bsdf_lanes(scene, g_face, params.hero, wi_l, wo_l), f_grey))
                        if c_v > 0.0:  # the lobes run with probability 1 − c_v
                            pdf_dir = (1.0 - c_v) * pdf_dir
                    got = wp.vec2(0.0, 0.0)
                    w = float(1.0)
                    if ls.value[0] > 0.0 or ls.value[1] > 0.0:
                        if params.mis != 0 and ls.pdf > 0.0:
                            if gl == 0:
                                pdf_dir = (1.0 - c_v) * pdf_cosine_hemisphere(wp.dot(ls.wi, n))
                                if o_on != 0:
                                    pdf_dir = optics_pdf(scene.optics[opt - 1], opt_x, n, ls.wi)
                                if (gw > 0.0) if wp.static(surfaces) else False:
                                    pdf_dir = matte_dir_pdf(scene.glints, scene.n_glints, p, n, c_v, gw, ls.wi)
                            w = power_heuristic(sel * ls.pdf, pdf_dir)
                        if w > 0.0 or params.tally_pick != 0:
                            count_shadow_ray(scene, params)
                            clear = bool(True)
                            if (scene.surfaces != 0) if wp.static(surfaces) else False:  # through panes, cut-outs: their share
                                o_l = o
                                if sh != 0:  # from the side of the face the light lies on
                                    o_l = spawn_origin(p, o, ls.wi)
                                vis = shadow_ray_pass(scene, o_l, p, li, ls)
                                if params.spectral != 0 and scene.spectral_panes != 0 and vis > 0.0:
                                    tint_l = wp.cw_mul(tint_l, lane_ratio(shadow_lanes(scene, params.hero, o_l, p, li, ls), vis))
                                ls.value = ls.value * vis
                                clear = vis > 0.0
                            else:
                                clear = shadow_ray_clear(scene, o, p, li, ls)
                            if clear:
                                got = ls.value
                                c_light = wp.vec2(0.0, 0.0)
                                if params.spectral != 0 and li == params.emissive_light:
                                    c_light = emissive_contribution(scene, params, ls.tri, (weight * w) * ls.value, tint_l)
                                else:
                                    c_light = light_contribution_dir(scene, params, li, (weight * w) * ls.value, tint_l, ls.wi)
                                total += c_light
                                if params.tally != 0 and depth > 0:
                                    tally_patch(scene, params, prev_row, cur_face, p, c_light)
                    if params.tally_pick != 0:
                        tally_pick(scene, params, li, p, n, depth, weight, got, ls.elem, w)
                        if params.tally_pick == 2 and depth > 0:
                            tally_patch_pick(scene, li, cur_face, p, n, weight, got)
            # -- delta lights and the sun seen in flat mirrors: their image sources (kernels.mirrors); light
            #    reflected on the way, so indirect (counted at a sensor's vertex even without its direct
            #    light). A path from here off a mirror face of the table straight to the sun leaves the sun
            #    out (img_prev at the next vertex): this connection counts it
            img_here = int(0)
            ia_here = int(0)
            c_here = int(-1)  # the curved mirror p lies on
            if (scene.n_curves > 0) if wp.static(surfaces) else False:
                own = wp.where(gl != 0, g_face, cur_face)
                if own >= 0:
                    c_here = scene.face_curve[own]
            if (params.nee != 0 and delta == 0 and params.bounces != 0 and scene.n_mirror_planes + scene.n_curves > 0) if wp.static(surfaces) else False:
                img_here = 1
                for li in range(scene.n_lights):
                    if not has_image(scene.lights[li]):
                        continue
                    for k in range(scene.n_mirror_planes + scene.n_curves):
                        if k >= scene.n_mirror_planes and (pm >= 1.0 or k - scene.n_mirror_planes == c_here):
                            continue  # a pure mirror's value would be 0 (no lobe but the delta); p's own curved mirror
                        u_im = wp.vec2(0.0, 0.0)
                        if is_cone_light(scene.lights[li]):  # drawn for the sun only: others keep their stream
                            u_im = wp.vec2(wp.randf(rng), wp.randf(rng))
                        if k < scene.n_mirror_planes and not image_may_exist(scene, li, k, p):
                            continue  # the light is on the plane's other side: no image, settled without the call
                        im = image_source(scene, li, k, p, ns, o, u_im, sh)
                        if im.traced != 0:  # tallied only where it cast a ray: most are settled before any (the
                            count_shadow_ray(scene, params)  # light on the mirror's other side), at no cost
                        v = im.value
                        if o_on != 0:
                            v = v * optics_weight(scene.optics[opt - 1], opt_x, n, im.wi)
                        tint_m = tint
                        if gl != 0:
                            f_grey = bsdf_f(bs, to_local(im.wi, ns), wo_l)
                            v = v * (PI * f_grey)
                            if g_lanes != 0:
                                f4 = bsdf_lanes(scene, g_face, params.hero, to_local(im.wi, ns), wo_l)
                                tint_m = wp.cw_mul(tint_m, lane_ratio(f4, f_grey))
                        if params.spectral != 0 and (v[0] > 0.0 or v[1] > 0.0):  # the mirror's and the panes' lanes
                            tint_m = image_lanes(scene, params, im, tint_m, o)
                        if v[0] > 0.0 or v[1] > 0.0:
                            total += light_contribution_dir(scene, params, li, weight * v, tint_m, im.wi)
                # -- area lights seen in flat mirrors, sampled from p's mirror image (kernels.mirrors.area_image),
                #    weighed by the power heuristic against the paths that make the same trip (their weight is
                #    taken where they meet the light past the mirror, ia_prev)
                if (params.mis != 0 and c_v <= 0.0 and gw <= 0.0 and not picks_at(params, depth)) if wp.static(surfaces) else False:
                    ia_here = 1
                    for li in range(scene.n_lights):
                        if not has_area_image(scene, scene.lights[li]):
                            continue
                        for k in range(scene.n_mirror_planes):
                            if scene.plane_mirror[k] == 0:
                                continue
                            im = area_image(scene, li, k, p, ns, o, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)), sh)
                            if im.traced != 0:  # tallied only where it cast a ray (as above)
                                count_shadow_ray(scene, params)
                            v = im.value
                            if v[0] > 0.0 or v[1] > 0.0:
                                tint_m = tint
                                pa = float(0.0)  # the path strategy's density of the same trip
                                if gl != 0:
                                    wi_l = to_local(im.wi, ns)
                                    f_grey = bsdf_f(bs, wi_l, wo_l)
                                    v = v * (PI * f_grey)
                                    pa = (1.0 - pm) * bsdf_pdf(bs, wi_l, wo_l)
                                    if g_lanes != 0:
                                        tint_m = wp.cw_mul(tint_m, lane_ratio(bsdf_lanes(scene, g_face, params.hero, wi_l, wo_l), f_grey))
                                elif o_on != 0:  # a modelled head: L·r(ω), its directions drawn by r
                                    v = v * optics_weight(scene.optics[opt - 1], opt_x, n, im.wi)
                                    pa = optics_pdf(scene.optics[opt - 1], opt_x, n, im.wi)
                                else:
                                    pa = pdf_cosine_hemisphere(wp.dot(im.wi, n))
                                w = power_heuristic(im.pdf, pa * area_image_mirror_prob(scene, im))
                                if params.spectral != 0:
                                    tint_m = image_lanes(scene, params, im, tint_m, o)
                                total += light_contribution_dir(scene, params, li, (weight * w) * v, tint_m, im.wi)
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
            if depth > 0 and beta < rr_t:
                q_late = beta / rr_t
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
                    if (scene.surfaces == 0) if wp.static(surfaces) else True:
                        refl = surface_albedo(scene, params, g.face, tint)
                        beta = beta * refl.rho * g.factor
                        tint = refl.tint
                    else:
                        lanes_set = int(0)  # 1: the tint took a lane factor at this step (then renormalised)
                        if gl != 0:
                            # a glossy vertex: f·cosθx·jac / (p_lobes,A + c_v·p_guide,A), the lobes' density
                            # (1 − c_v)(1 − p_mirror)·pdf_bsdf·jac, times the segment's share
                            gwi = to_local(g.wi, ns)
                            p_lobes = (1.0 - c_v) * (1.0 - pm) * bsdf_pdf(bs, gwi, wo_l) * g.jac
                            den = p_lobes + c_v * g.density
                            if den <= 0.0:
                                break
                            f_grey = bsdf_f(bs, gwi, wo_l)
                            beta = beta * (f_grey * gwi[2] * g.jac / den) * g.share
                            if g_lanes != 0:  # the lanes of a coloured glossy vertex (as its direction samples)
                                tint = wp.cw_mul(tint, lane_ratio(bsdf_lanes(scene, g_face, params.hero, gwi, wo_l), f_grey))
                                lanes_set = 1
                        elif gw > 0.0:  # the guide beside the cosine and glint mixture, at y's area
                            cos_gx = wp.dot(g.wi, n)
                            den = c_v * g.density + matte_dir_pdf(scene.glints, scene.n_glints, p, n, c_v, gw, g.wi) * g.jac
                            if den <= 0.0:
                                break
                            beta = beta * (cos_gx * INV_PI * g.jac / den) * g.share
                        else:
                            beta = beta * g.factor
                        if params.spectral != 0 and scene.spectral_panes != 0:  # coloured panes on the segment
                            seg = g.y - o
                            d_seg = wp.length(seg)
                            off_y = offset_length(scene, g.y)
                            if d_seg > off_y:
                                t_grey = transmittance_along(scene, o, g.wi, d_seg - off_y, -1)
                                tint = wp.cw_mul(tint, lane_ratio(transmittance_lanes(scene, params.hero, o, g.wi,
                                                                                      d_seg - off_y, -1), t_grey))
                                lanes_set = 1
                        if lanes_set != 0:  # β takes the lanes' mean, the tint keeps mean 1
                            m = 0.25 * (tint[0] + tint[1] + tint[2] + tint[3])
                            if m > 0.0:
                                beta = beta * m
                                tint = tint / m
                        gl = 0
                        if is_glossy(scene, g.face):  # y scatters by its BSDF, seen from x
                            gl = 1
                            bs = face_bsdf(scene, g.face)
                            wo_g = -g.wi
                            g_face = g.face
                            if params.spectral != 0:
                                g_lanes = coloured_row(scene, g.face)[0]
                        else:
                            refl = surface_albedo(scene, params, g.face, tint)
                            beta = beta * refl.rho
                            tint = refl.tint
                        if beta <= 0.0:
                            break
                    weight = weight_in * beta
                    p = g.y
                    n = g.n
                    cur_face = g.face
                    prev_row = row
                    img_prev = img_here
                    if wp.static(surfaces):
                        o_prev = o
                        c_prev = c_here
                        ia_prev = 0
                    depth += 1
                    continue
            # -- a cosine-weighted direction: E ≈ π·L(ω)
            local = wp.vec3(0.0, 0.0, 1.0)
            wi = spec_d
            g_dir = float(1.0)  # a glossy vertex's f·cosθ/pdf for this direction (β takes it at the hit)
            tint_d = tint  # the lanes along this direction (a coloured glossy vertex's: see below)
            mirror_now = int(0)
            pdf_g = float(0.0)
            gl_x = gl  # whether this vertex is glossy (gl then follows the next one)
            o_pdf = float(0.0)  # a modelled sensor's direction: its density and r/pdf (o_on)
            o_w = float(0.0)
            if delta == 0 and gl != 0:
                if pm > 0.0 and wp.randf(rng) < pm:  # the mirror part: reflectance F over its probability
                    wi = mirror(-wo_g, ns)
                    f_grey = mirror_reflectance(bs, wo_l[2])
                    g_dir = f_grey / pm
                    if c_v > 0.0:  # ... which is (1 − c_v)·p_mirror beside the guide
                        g_dir = g_dir / (1.0 - c_v)
                    mirror_now = 1
                    if g_lanes != 0:
                        tint_d = wp.cw_mul(tint, lane_ratio(mirror_lanes(scene, g_face, params.hero, wo_l[2]), f_grey))
                else:
                    wi_l = bsdf_sample(bs, wo_l, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
                    if wi_l[2] <= 0.0:
                        break
                    pdf_g = (1.0 - pm) * bsdf_pdf(bs, wi_l, wo_l)
                    if c_v > 0.0:
                        pdf_g = (1.0 - c_v) * pdf_g
                    if pdf_g <= 0.0:
                        break
                    f_grey = bsdf_f(bs, wi_l, wo_l)
                    g_dir = f_grey * wi_l[2] / pdf_g
                    wi = to_world(wi_l, ns)
                    if g_lanes != 0:
                        tint_d = wp.cw_mul(tint, lane_ratio(bsdf_lanes(scene, g_face, params.hero, wi_l, wo_l), f_grey))
                if g_lanes != 0:  # β takes the lanes' mean, the tint keeps mean 1 (as surface_albedo)
                    m = 0.25 * (tint_d[0] + tint_d[1] + tint_d[2] + tint_d[3])
                    if m > 0.0:
                        g_dir = g_dir * m
                        tint_d = tint_d / m
            elif delta == 0:
                glint_now = bool(False)
                if (gw > 0.0) if wp.static(surfaces) else False:
                    glint_now = wp.randf(rng) < gw
                if glint_now:  # the glint strategy
                    wi = glint_sample(scene.glints, scene.n_glints, p, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
                    local = to_local(wi, n)
                elif o_on != 0:  # drawn by the head's response (local: its frame, z along n)
                    o_s = sample_optics(scene.optics[opt - 1], wp.vec2(wp.randf(rng), wp.randf(rng)))
                    local = o_s.local
                    wi = optics_to_world(local, opt_x, n)
                    o_pdf = o_s.pdf
                    o_w = o_s.weight
                else:
                    local = sample_cosine_hemisphere(wp.vec2(wp.randf(rng), wp.randf(rng)))
                    wi = to_world(local, n)
                if local[2] <= 0.0:
                    break
            pdf_b = (1.0 - c_v) * local[2] * INV_PI  # this strategy's density: it runs with probability 1 − c
            w_dir = weight * PI / (1.0 - c_v)
            if (gw > 0.0) if wp.static(surfaces) else False:  # E ≈ L·cosθ/p_dir(ω)
                pdf_b = matte_dir_pdf(scene.glints, scene.n_glints, p, n, c_v, gw, wi)
                w_dir = weight * local[2] / pdf_b
            if gl != 0:
                pdf_b = pdf_g
                w_dir = weight * PI * g_dir
            if o_on != 0:  # E_r ≈ L·r(ω)/p_r(ω); the next vertex's weight w_dir·ρ/π: β takes (r/p)/π
                pdf_b = o_pdf
                w_dir = weight * o_w
            o_x = o  # the origin p's image sources used, p and its light normal (o_prev, x_prev, nx_prev next)
            p_x = p
            ns_x = ns
            if (sh != 0) if wp.static(surfaces) else False:  # leave past the face wi heads into
                o = spawn_origin(p, o, wi)
            count_ray(scene, params)
            hit = first_hit(scene, o, wi, RAY_INF)
            event = int(0)
            tint_before = tint_d  # the lanes of lights met before the first coloured pane on this ray
            t_tint = float(RAY_INF)
            hit0 = hit  # the walk's start, replayed for a light met past a weighted or coloured pane (walk_before)
            rng0 = rng
            w_pass = float(1.0)  # the walk's weight (kernels.surfaces.walk): the stop's, and of lights met past t_pass
            t_pass = float(RAY_INF)
            # through panes and cut-outs to where the ray stops; a ray that meets a matte face first (most do)
            # or nothing stops there, with no call down the walk (each call copies the scene record)
            walks = bool(False)
            if (scene.surfaces != 0) if wp.static(surfaces) else False:
                if hit.face >= 0:
                    walks = scene.surf_id[hit.face] >= 0
            if (walks) if wp.static(surfaces) else False:
                lp = pass_through_traced(scene, params, o, wi, hit, rng)  # coloured panes: the same draws, per lane
                rng = lp.rng
                hit = lp.hit
                event = lp.event
                tint_d = wp.cw_mul(tint_d, lp.tint)
                t_tint = lp.t_tint
                w_pass = lp.weight
                t_pass = lp.t_weight
            weigh = params.mis != 0 and params.nee != 0 and delta == 0 and mirror_now == 0  # MIS against p's light samples
            t_hit = hit.t
            face = hit.face
            ng = hit.ng
            # UsdLux area lights in front of the hit (they do not block), met
            # along the same ray as the mesh: a light tested along another line
            # (from p, parallel) was seen past a shade the mesh ray hit.
            for li in range(scene.n_lights):
                l = scene.lights[li]
                t = hit_light_before(l, o, wi, t_hit)  # −1 for lights with no surface
                if t > 0.0 and count and not computed_at(scene, params.mask_row, depth, li):
                    w = float(1.0)
                    if weigh:
                        pdf_one = float(0.0)
                        if o_on != 0 and f_on != 0 and l.kind == _RECT_LIGHT:  # drawn within the head's field
                            pdf_one = rect_pdf_field(l, p, n, f_cos, o + t * wi)
                        else:
                            pdf_one = pdf_light(scene, li, o, ns, wi, t, -1)
                        pdf_l = pick_scale(scene, params, pk, li, p, n, depth) * pdf_one
                        w = power_heuristic(pdf_b, pdf_l)
                    elif (ia_prev != 0 and (mirror_now != 0 or delta != 0) and cur_face >= 0) if wp.static(surfaces) else False:
                        # past a flat mirror from a vertex that sampled this light in it: against that sample
                        pb = image_light_pdf(scene, li, cur_face, x_prev, nx_prev, o, wi, t)
                        w = power_heuristic(pa_prev * wp.where(mirror_now != 0, pm, 1.0), pb)
                    tint_l = tint_before
                    w_l = float(1.0)
                    if (t >= wp.min(t_tint, t_pass)) if wp.static(surfaces) else False:  # past a weighted or coloured pane: those in front of the light only
                        wb = walk_before(scene, params, o, wi, hit0, rng0, t)
                        tint_l = wp.cw_mul(tint_before, wb.tint)
                        w_l = wb.weight
                    total += light_contribution(scene, params, li, (w_dir * w_l * w * shaping_factor(l, -wi)) * l.emission,
                                                tint_l)
            w_dir = w_dir * w_pass  # what the walk stops at, and all past it
            if face < 0:
                # the mirror part of a face of the mirror table (or a pane's reflection there), reached from a
                # vertex that ran the image source: the sun along it was counted there (kernels.mirrors), not
                # again here
                img_skip = bool(False)
                curve_k = int(-1)  # a curved mirror's: left out where the connection lands on this point (kernels.curved)
                if ((mirror_now != 0 or delta != 0) and img_prev != 0 and cur_face >= 0) if wp.static(surfaces) else False:
                    img_skip = scene.face_mirror[cur_face] >= 0
                    if scene.n_curves > 0:
                        curve_k = scene.face_curve[cur_face]
                        if curve_k == c_prev:
                            curve_k = -1  # the vertex before lay on that mirror: it connected nothing through it
                for li in range(scene.n_lights):
                    le = escaped_radiance(scene.lights[li], wi)
                    if img_skip:
                        if is_cone_light(scene.lights[li]):
                            le = wp.vec2(0.0, 0.0)
                    elif (curve_k >= 0) if wp.static(surfaces) else False:
                        if is_cone_light(scene.lights[li]) and (le[0] > 0.0 or le[1] > 0.0):
                            if curve_covers(scene, curve_k, o_prev, p, wi):
                                le = wp.vec2(0.0, 0.0)
                    if (le[0] > 0.0 or le[1] > 0.0) and count and not computed_at(scene, params.mask_row, depth, li):
                        w = float(1.0)
                        if weigh:
                            pdf_l = pick_scale(scene, params, pk, li, p, n, depth) * pdf_light(scene, li, o, ns, wi, RAY_INF, -1)
                            w = power_heuristic(pdf_b, pdf_l)
                        total += light_contribution_dir(scene, params, li, (w_dir * w) * le, tint_d, wi)
                break
            cos_view = -wp.dot(wi, ng)
            if event == ABSORB:
                break
            if event == MIRROR:
                if params.bounces >= 0 and depth >= params.bounces:
                    break
                beta = beta * w_pass  # the pane's reflection weight R + T, and the passes' before it
                weight = weight_in * beta
                if gl != 0:  # the glossy vertex's factor, carried through the delta vertex
                    beta = beta * g_dir
                    weight = weight_in * beta
                    gl = 0
                elif (gw > 0.0) if wp.static(surfaces) else False:
                    # as below, with the direction strategies' mixture p_dir: β takes (cosθ/π)/p_dir
                    beta = beta * (local[2] * INV_PI / pdf_b)
                    weight = weight_in * beta
                elif c_v > 0.0:
                    # the guide never draws a path bent by a pane, so only the cosine strategy (probability
                    # 1 − c) weighs it: β takes 1/(1 − c), and no mixture factor at the vertex it reaches
                    beta = beta / (1.0 - c_v)
                    weight = weight_in * beta
                if o_on != 0:
                    beta = beta * (o_w * INV_PI)
                    weight = weight_in * beta
                tint = tint_d
                p = o + t_hit * wi
                n = wp.where(cos_view > 0.0, ng, -ng)
                spec_d = mirror(wi, ng)
                delta = 1
                cur_face = face
                img_prev = wp.where(mirror_now == 0, img_here, 0)  # a pane's reflection is the image source's too
                if wp.static(surfaces):
                    o_prev = o_x
                    c_prev = c_here
                    ia_prev = wp.where(mirror_now == 0, ia_here, 0)
                    x_prev = p_x
                    nx_prev = ns_x
                    pa_prev = pdf_b * mirror_event_prob(scene, face, wi, ng, 0.0)  # the path takes the pane's reflection
                depth += 1
                continue
            delta = 0
            le = tri_emitted(scene, face, cos_view)
            if (le[0] > 0.0 or le[1] > 0.0) and count and not computed_at(scene, params.mask_row, depth,
                                                                          params.emissive_light):
                w = float(1.0)
                if weigh and params.emissive_light >= 0:
                    # the piece's probability read at the receiver (p, ns) its light samples were drawn for
                    # (the cell of the pieces' table, lights/emissive.py, is a function of those two)
                    w = power_heuristic(pdf_b, pick_scale(scene, params, pk, params.emissive_light, p, n, depth)
                                        * emissive_pdf_at(scene, p, ns, o + t_hit * wi, wi, t_hit, face))
                total += emissive_contribution(scene, params, face, (w_dir * w) * le, tint_d)
            if params.bounces >= 0 and depth >= params.bounces:
                break
            # -- reflect: L_o = ρ/π·E, so the next vertex's weight is w_dir·ρ/π
            #    = weight_in·β·ρ (the roulette comes after that vertex's
            #    next-event estimate, above)
            beta = beta * w_pass  # the passes on the way (1 without panes)
            if gl != 0:
                beta = beta * g_dir
                gl = 0
            if o_on != 0:
                beta = beta * (o_w * INV_PI)
            tint = tint_d
            refl = surface_albedo(scene, params, face, tint)
            if (scene.surfaces != 0 and is_glossy(scene, face)) if wp.static(surfaces) else False:
                # the glossy vertex takes its f·cosθ/pdf when it draws the next direction (grey: tint kept)
                gl = 1
                bs = face_bsdf(scene, face)
                g_face = face
                if params.spectral != 0:
                    g_lanes = coloured_row(scene, face)[0]
                wo_g = -wi
            else:
                beta = beta * refl.rho
                tint = refl.tint
            if (gw > 0.0) if wp.static(surfaces) else False:
                # p_cos,A / (c_v·p_guide,A + p_dir,A): the cosine, glint and guide mixture at y
                jac = wp.abs(cos_view) / (t_hit * t_hit)
                pg = float(0.0)
                if c_v > 0.0:
                    pg = pdf_guide(scene, row, face, o + t_hit * wi)
                beta = beta * (local[2] * INV_PI * jac / (c_v * pg + pdf_b * jac))
            elif c_v > 0.0 and mirror_now == 0:  # one-sample MIS against the guide (a mirror direction: none)
                if gl_x != 0:  # the lobes' area density, (1 − c_v)-weighted already, against the guide's
                    beta = beta * glossy_mixture_factor(c_v, pdf_guide(scene, row, face, o + t_hit * wi),
                                                        pdf_g * wp.abs(cos_view) / (t_hit * t_hit))  # fmt: skip
                else:
                    beta = beta * mixture_factor(c_v, pdf_guide(scene, row, face, o + t_hit * wi),
                                                 local[2] * wp.abs(cos_view) * INV_PI / (t_hit * t_hit))  # fmt: skip
            weight = weight_in * beta
            p = o + t_hit * wi
            n = wp.where(cos_view > 0.0, ng, -ng)
            cur_face = face
            prev_row = row
            img_prev = wp.where(mirror_now == 0, img_here, 0)  # past a mirror part: two reflections, not connected
            if wp.static(surfaces):
                o_prev = o_x
                c_prev = c_here
                ia_prev = wp.where(mirror_now == 0, ia_here, 0)
                x_prev = p_x
                nx_prev = ns_x
                pa_prev = pdf_b
            depth += 1
        return total

    @wp.func
    def vertex_irradiance(
        scene: SceneRec, p_in: wp.vec3, n_in: wp.vec3, weight_in: float, params: TraceParams, skip_first: int, rng_in: wp.uint32
    ) -> wp.vec2:
        """:func:`vertex_estimate` from a sensor or a matte face: weight_in × an estimate of the irradiance."""
        return vertex_estimate(scene, p_in, n_in, weight_in, params, skip_first, rng_in, -1, wp.vec3(0.0, 0.0, 1.0))

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
        # Emitters seen straight along the meter's ray, and the first surface's
        # reflection of the light reaching it straight from emitters, are the
        # direct component; with skip_direct both are left out.
        direct = params.skip_direct == 0
        total = wp.vec2(0.0, 0.0)
        skip_next = params.skip_direct
        tint_r = params.tint  # × the lanes of coloured panes passed or reflected off (spectral mode)
        tint_before = tint_r  # the lanes before the first coloured pane of the last segment, at distance t_tint
        t_tint = float(RAY_INF)
        hit0 = hit  # the last segment's walk start, replayed for a light met past a weighted or coloured pane
        rng0 = rng
        wr = float(1.0)  # the weights of the pane events before the last segment (kernels.surfaces.walk)
        w_seg = float(1.0)  # the last segment's walk weight, and the distance past which it applies
        t_seg = float(RAY_INF)
        if (scene.surfaces != 0) if wp.static(surfaces) else False:
            # through panes and cut-outs; a mirror reflection off a pane sends the ray on (what it then
            # sees was reflected on the way: indirect), each segment's lights counted as it passes them
            for k in range(MAX_MIRRORS):
                ev = int(0)
                tint_before = tint_r
                t_tint = float(RAY_INF)
                hit0 = hit
                rng0 = rng
                lp = pass_through_traced(scene, params, o, d, hit, rng)
                rng = lp.rng
                hit = lp.hit
                ev = lp.event
                tint_r = wp.cw_mul(tint_r, lp.tint)
                t_tint = lp.t_tint
                w_seg = lp.weight
                t_seg = lp.t_weight
                if ev != MIRROR and ev != ABSORB:
                    break
                if direct:
                    total = lights_seen_along(scene, params, total, o, d, hit.t, hit0, rng0, wr, t_seg, tint_before, t_tint)
                if ev == ABSORB or k == MAX_MIRRORS - 1:
                    return total
                wr = wr * w_seg  # the reflection's weight R + T, and the passes' before it
                w_seg = 1.0
                t_seg = RAY_INF
                q = o + hit.t * d
                side = wp.where(wp.dot(d, hit.ng) < 0.0, hit.ng, -hit.ng)
                d = mirror(d, hit.ng)
                o = q + offset_length(scene, q) * side
                direct = True
                skip_next = 0
                count_ray(scene, params)
                hit = first_hit(scene, o, d, RAY_INF)
        t_hit = hit.t
        face = hit.face
        ng = hit.ng
        if direct:
            total = lights_seen_along(scene, params, total, o, d, t_hit, hit0, rng0, wr, t_seg, tint_before, t_tint)
        wr = wr * w_seg  # what the last segment stops at
        if face < 0:
            if direct:
                for li in range(scene.n_lights):
                    total += light_contribution_dir(scene, params, li, wr * escaped_radiance(scene.lights[li], d), tint_r, d)
            return total
        cos_view = -wp.dot(d, ng)
        if direct:
            le = tri_emitted(scene, face, cos_view)
            if le[0] > 0.0 or le[1] > 0.0:
                total += emissive_contribution(scene, params, face, wr * le, tint_r)
        refl = surface_albedo(scene, params, face, tint_r)
        if (scene.surfaces != 0 and is_glossy(scene, face)) if wp.static(surfaces) else False:  # L = ∫ f L cos dω: π·f
            n = wp.where(cos_view > 0.0, ng, -ng)
            prm = params
            prm.optics = 0  # a meter's first surface is a surface: its cosine
            prm.tint = tint_r
            total += vertex_estimate(scene, o + t_hit * d, n, wr * INV_PI, prm, skip_next, rng, face, -d)
        elif refl.rho > 0.0:
            n = wp.where(cos_view > 0.0, ng, -ng)
            prm = params
            prm.optics = 0  # a meter's first surface is a surface: its cosine
            prm.tint = refl.tint
            total += vertex_irradiance(scene, o + t_hit * d, n, (wr * refl.rho) * INV_PI, prm, skip_next, rng)
        return total

    @wp.func
    def split_irradiance(scene: SceneRec, p: wp.vec3, n: wp.vec3, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One estimate of the irradiance on (p, n): with ``params.split_indirect`` = K ≥ 2 (paths, total
        light) the direct light once (next-event estimation and the cosine ray's emitters, bounces 0) plus
        the mean of K indirect paths (each skipping the sensor's own direct light), every part from a
        stream of its own: E = E_d + E_i, so the sum is unbiased, and its variance is v_d + v_i/K for the
        cost c_d + K·c_i (the Neyman allocation of samples between the two, in one pass)."""
        if params.split_indirect <= 1 or params.bounces == 0 or params.skip_direct != 0:
            return vertex_irradiance(scene, p, n, 1.0, params, params.skip_direct, rng_in)
        rng = rng_in
        seed = wp.randi(rng)
        prm = params
        prm.bounces = 0
        total = vertex_irradiance(scene, p, n, 1.0, prm, 0, wp.rand_init(seed, 0))
        inv_k = 1.0 / float(params.split_indirect)
        for k in range(params.split_indirect):
            total += vertex_irradiance(scene, p, n, inv_k, params, 1, wp.rand_init(seed, k + 1))
        return total

    @wp.func
    def sample_irradiance(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One estimate of the irradiance on the sensor's side."""
        return split_irradiance(scene, s.position, s.normal, params, rng_in)

    @wp.func
    def sample_patch(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One estimate of the irradiance at a point drawn uniformly on the patch."""
        rng = rng_in
        u = wp.vec2(wp.randf(rng), wp.randf(rng))
        p = s.position + ((u[0] - 0.5) * s.width) * s.right + ((u[1] - 0.5) * s.height) * s.up
        return vertex_irradiance(scene, p, s.normal, 1.0, params, params.skip_direct, rng)

    @wp.func
    def sample_cylindrical(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One estimate of the mean irradiance on a small cylinder's curved surface.

        The mean over the surface is the mean over its outward normals n(φ), φ
        uniform on [0, 2π): E_z = (1/2π)∫E(n(φ))dφ = (1/π)∫L sinθ dω (θ from the
        axis). So a sample draws φ, then one irradiance sample on (p, n(φ)): the
        directions it draws have density sinθ/π² over the sphere when cosine
        sampled, the weight E_z carries."""
        rng = rng_in
        n = cylinder_normal(s, 2.0 * PI * wp.randf(rng))
        return vertex_irradiance(scene, s.position, n, 1.0, params, params.skip_direct, rng)

    @wp.func
    def sample_semicylindrical(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One estimate of the mean irradiance on the half cylinder facing ``s.right``: φ uniform on
        [−π/2, π/2], E_sc = (1/π)∫E(n(φ))dφ = (1/π)∫L sinθ (1 + cos φ_ω) dω (φ_ω the direction's azimuth from the facing)."""
        rng = rng_in
        n = cylinder_normal(s, PI * (wp.randf(rng) - 0.5))
        return vertex_irradiance(scene, s.position, n, 1.0, params, params.skip_direct, rng)

    samplers = {"sample_irradiance": sample_irradiance, "sample_radiance": sample_radiance, "sample_patch": sample_patch,
                "sample_cylindrical": sample_cylindrical, "sample_semicylindrical": sample_semicylindrical}
    sample_chain = kind_chain(tuple((int(k.kind), samplers[k.sample]) for k in SENSOR_KERNELS), _sample_link, _no_sample)

    @wp.func
    def sample_sensor(scene: SceneRec, s: SensorRec, params: TraceParams, rng_in: wp.uint32) -> wp.vec2:
        """One sample of sensor ``s``'s reading (dispatch over ``SENSOR_KERNELS``)."""
        return sample_chain(scene, s, params, rng_in)

    @wp.kernel(module=trace_module(surfaces))
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
        prm.optics = s.optics
        prm.optics_x = s.right
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

    @wp.kernel(module=trace_module(surfaces))
    def piece_table_kernel(
        scene: SceneRec,
        cell_p: wp.array(dtype=wp.vec3),
        cell_n: wp.array(dtype=wp.vec3),
        per_cell: int,
        rays: int,
        li: int,
        seed: int,
        offset: int,
        out: wp.array(dtype=float),
    ):
        """Entry (c, k) = thread c·n_pieces + k of the emitter pieces' table (``simulator.engine.piece_table``):
        the mean over ``rays`` light samples of piece k (:func:`.lights.emissive.sample_piece`), each from
        one of cell c's ``per_cell`` receivers (points ``cell_p``, unit normals ``cell_n``) in turn, of its
        shadowed value as W + lm/683 per m², through panes and cut-outs at their share: an estimate of
        the piece's irradiance over the cell. Each entry draws from its own random stream."""
        t = wp.tid() + offset
        c = t // scene.n_pieces
        k = t - c * scene.n_pieces
        rng = wp.rand_init(seed, t)
        total = float(0.0)
        for r in range(rays):
            i = c * per_cell + r % per_cell
            x = cell_p[i]
            nx = cell_n[i]
            ls = sample_piece(scene, k, 1.0, x, nx, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
            if ls.value[0] > 0.0 or ls.value[1] > 0.0:
                o = x
                if scene.has_mesh != 0:
                    o = x + offset_length(scene, x) * nx
                vis = float(1.0)
                if (scene.surfaces != 0) if wp.static(surfaces) else False:
                    vis = shadow_ray_pass(scene, o, x, li, ls)
                elif not shadow_ray_clear(scene, o, x, li, ls):
                    vis = 0.0
                total += vis * (wp.max(ls.value[0], 0.0) + LM_TO_W * wp.max(ls.value[1], 0.0))
        out[t] = total / float(rays)

    return Trace(surfaces, vertex_estimate, vertex_irradiance, sample_radiance, samplers, sample_sensor, estimate_kernel,
                 piece_table_kernel)


def trace_for(surfaces: int) -> Trace:
    """The trace variant for a stage whose ``SceneRec.surfaces`` is ``surfaces``: the matte one for 0.

    Built on first use (:func:`make_trace` keeps it), so a run defines the functions of its stage's
    variant only. Its module also holds the variant's probe kernel, which must be defined before the
    module is hashed: the engine loads a variant through ``engine.kernel_modules.trace_module``,
    which defines both. Each variant is a module of its own, and its hash does not depend on whether,
    or in which order, the other was built (the path functions' keys and sources are the same)."""
    return make_trace(surfaces != 0)


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
