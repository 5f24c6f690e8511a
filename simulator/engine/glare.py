"""Glare views on the engine: the traced half map, each sun's disk, the delta lights.

A view (a GLARE sensor, :mod:`simulator.glare`) is read in two parts, both
on a copy of the stage in which every sun (a DistantLight with an angle) is
a delta light of the same normal illuminance, E⊥ = L·π·sin²α:

1. **The map.** The probe kernel over the hemisphere in front of the eye
   (:mod:`simulator.glare.view`: a lat-long layout of the front half only,
   in the view's frame). No direction sample sees a delta sun, so the sun
   is never spread over a pixel, while every surface it lights is lit as
   before (next-event estimation toward the disk's centre instead of over
   the disk: irradiance differs by O(α²) ≈ 2·10⁻⁵ where the whole disk is
   in sight; a penumbra is sharpened to a shadow edge). Passes are drawn in
   batches until DGP's standard error meets the view's ``dgp_stderr`` (or
   the pass cap, a time limit or a stop). Standard errors: the delta method
   of :mod:`simulator.glare.evaluate` counts the noise of the pixels a
   source is made of, not how the sources found move with it (a pixel near
   the threshold in one run and out in the next; a sunlit floor at 2,500
   cd/m² against evalglare's 2,000). So each batch draws its passes in
   :data:`JACKKNIFE_GROUPS` groups, the view is evaluated again leaving each
   group out, and each figure's standard error is the larger of the delta
   method's and the delete-one-group jackknife's (measured on the office:
   docs/DESIGN.md §Glare).
2. **Delta lights**: the probe kernel's delta mode gives their exact
   contributions to its 19 integrands at the eye, f_q(ω_l)·E_l summed over
   the lights, each E_l the light's normal illuminance there after every
   face on its segment (0 behind an opaque one, a pane's transmittance at
   that incidence through glazing: :func:`simulator.kernels.surfaces.transmittance_along`).
   The directions ω_l are known, so the E_l come from the 19 equations by
   least squares (exact while the lights' directions are distinct and at
   most 19). A sun's E_l makes its disk a source of luminance
   E_l/(π·sin²α) over Ω = 2π(1 − cos α), in its direction: its visibility
   and what glazing passes, exactly, at the disk's centre (a disk half
   hidden by an edge counts as its centre does). Every delta light adds
   E_l·max(0, ω_l·v) to E_v; a point light (no size) is never a source and
   is named in a warning when in view.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from simulator.engine import probes as P
from simulator.engine.stats import RunningStats
from simulator.glare import view as V
from simulator.glare.evaluate import GlareEstimate, SunReading, evaluate, pixel_stats
from simulator.glare.sources import GlareSettings
from simulator.scene.model import LightKind, Scene, Sensor

__all__ = ["MIN_GLARE_PASSES", "GlareResult", "suns_of", "glare_scene", "run_glare"]

#: passes of the first batch (directions per pixel): each pixel's variance needs at least two
MIN_GLARE_PASSES = 4
#: pass groups of the jackknife: every batch draws a multiple of this many passes, one share per group
JACKKNIFE_GROUPS = 4


@dataclass
class GlareResult:
    """One view's reading.

    Attributes
    ----------
    sensor : Sensor
    frame : ndarray, shape (3, 3)
        Columns left, up, view (world frame).
    estimate : GlareEstimate
        E_v, DGP, DGPs, UGR, the sources, with standard errors.
    luminance, luminance_stderr : ndarray, shape (H, W)
        The traced map's mean luminance per pixel (cd/m², no sun in it) and its standard error.
    suns : list of SunReading
        The suns in front of the eye, each a disk of the luminance seen at its centre.
    settings : GlareSettings
    passes, samples : int
        Directions per pixel, and in all.
    seconds : float
    target_met : bool
        DGP's standard error reached ``settings.dgp_stderr``.
    non_finite : int
    warnings : list of str
    interrupted : bool
    """

    sensor: Sensor
    frame: np.ndarray
    estimate: GlareEstimate
    luminance: np.ndarray
    luminance_stderr: np.ndarray
    suns: list[SunReading]
    settings: GlareSettings
    passes: int
    samples: int
    seconds: float
    target_met: bool
    non_finite: int = 0
    warnings: list[str] = field(default_factory=list)
    interrupted: bool = False


def suns_of(scene: Scene) -> list:
    """The stage's suns: DistantLights with an angle (a disk) that emit."""
    return [l for l in scene.lights if l.kind == LightKind.DISTANT and l.half_angle > 0.0 and max(l.emission) > 0.0]


def glare_scene(scene: Scene) -> Scene:
    """A copy of ``scene`` whose suns are delta lights of the same normal illuminance E⊥ = L·π·sin²α
    (radiometric and photometric), so that no direction sample sees a disk (module docstring)."""
    lights = []
    suns = {id(l) for l in suns_of(scene)}
    for l in scene.lights:
        if id(l) in suns:
            k = math.pi * math.sin(l.half_angle) ** 2
            l = dataclasses.replace(l, half_angle=0.0, emission=(l.emission[0] * k, l.emission[1] * k))
        lights.append(l)
    return dataclasses.replace(scene, lights=lights, sensors=[])


def _delta_lights(scene: Scene) -> list:
    return [l for l in scene.lights if l.is_delta and max(l.emission) > 0.0]


def _integrands(w: np.ndarray) -> np.ndarray:
    """f_q(ω) of the probe kernel's first 19 integrands (:mod:`simulator.kernels.probe`), shape (19, L)."""
    x, y, z = w[:, 0], w[:, 1], w[:, 2]
    sh0, sh1, sh2, sh20, sh22 = 0.28209479177387814, 0.4886025119029199, 1.0925484305920792, 0.31539156525252005, 0.5462742152960396
    return np.array([
        np.ones_like(x), np.maximum(0, x), np.maximum(0, -x), np.maximum(0, y), np.maximum(0, -y), np.maximum(0, z),
        np.maximum(0, -z), x, y, z, np.full_like(x, sh0), sh1 * y, sh1 * z, sh1 * x, sh2 * x * y, sh2 * y * z,
        sh20 * (3 * z * z - 1), sh2 * x * z, sh22 * (x * x - y * y),
    ])  # fmt: skip


def _directions(lights: list, eye: np.ndarray) -> np.ndarray:
    """Unit direction from the eye toward each delta light, shape (L, 3)."""
    w = []
    for l in lights:
        if l.kind == LightKind.POINT:
            v = np.asarray(l.position, np.float64) - eye
            n = float(np.linalg.norm(v))
            w.append(v / n if n > 0 else np.array([0.0, 0.0, 1.0]))
        else:
            w.append(np.asarray(l.frame[:, 2], np.float64))
    return np.array(w).reshape(-1, 3)


def _delta_split(engine, lights: list, eye: np.ndarray, seed: int) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """Each delta light's normal illuminance at ``eye`` (L, 2) (module docstring, part 2), their
    directions (L, 3), and notes on a split that is not exact."""
    if not lights:
        return np.zeros((0, 2)), np.zeros((0, 3)), []
    rec = engine.probe_record()
    rec.position = _vec3(eye)
    rec.width, rec.height = 1, 1
    rec.key = 0
    d = engine.probe_delta(rec, engine.trace_params("light", seed))[:19]  # (19, 2)
    w = _directions(lights, eye)
    f = _integrands(w)
    e, *_ = np.linalg.lstsq(f, d, rcond=None)
    notes = []
    if len(lights) > 19 or np.linalg.matrix_rank(f, tol=1e-6) < len(lights):
        notes.append(f"{len(lights)} delta lights in too few distinct directions to tell apart at the eye: "
                     "their E_v and the suns' luminance are shared among them")  # fmt: skip
    return np.maximum(e, 0.0), w, notes


def _vec3(v):
    from simulator.engine.device import warp

    return warp().vec3(*map(float, v))


def _sun_readings(suns: list, e: np.ndarray, w: np.ndarray, view: np.ndarray) -> list[SunReading]:
    """Each sun in front of the eye as a disk: luminance E_l/(π·sin²α) over Ω, deterministic."""
    out = []
    for l, el, wl in zip(suns, e, w):
        if float(wl @ view) <= 0.0:
            continue
        k = math.pi * math.sin(l.half_angle) ** 2
        omega = 2.0 * math.pi * 2.0 * math.sin(0.5 * l.half_angle) ** 2  # 2π(1 − cos α) without cancellation
        mean = el / k
        out.append(SunReading(l.name, wl.copy(), omega, mean, np.zeros(2), mean * mean, float(l.emission[1])))
    return out


def _without(total: RunningStats, part: RunningStats) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(count, mean, m2)`` of the samples of ``total`` not in ``part`` (Chan's merge run backwards:
    n_a = n − n_b, μ_a = (n·μ − n_b·μ_b)/n_a, M_a = M − M_b − (μ_b − μ_a)²·n_a·n_b/n)."""
    n = total.count.astype(np.float64)[:, None]
    nb = part.count.astype(np.float64)[:, None]
    na = n - nb
    mean = (n * total.mean - nb * part.mean) / na
    m2 = total.m2 - part.m2 - (part.mean - mean) ** 2 * na * nb / n
    return total.count - part.count, mean, np.maximum(m2, 0.0)


def _jackknife(est: GlareEstimate, leave_out: list[GlareEstimate]) -> None:
    """Standard errors that also count how the sources found move with the noise: the delete-one-group
    jackknife over the K pass groups, √((K − 1)/K·Σ(θ_(g) − θ̄)²), each figure's standard error the larger of
    it and the delta method's (module docstring)."""
    k = len(leave_out)
    for name, se_name in (("dgp", "dgp_stderr"), ("dgps", "dgps_stderr"), ("ugr", "ugr_stderr"),
                          ("ev_lx", "ev_stderr_lx"), ("ev_W_m2", "ev_stderr_W_m2")):  # fmt: skip
        x = np.array([getattr(e, name) for e in leave_out], np.float64)
        if not np.all(np.isfinite(x)):
            continue
        jack = math.sqrt((k - 1) / k * float(((x - x.mean()) ** 2).sum()))
        est.jackknife[se_name] = jack
        setattr(est, se_name, max(getattr(est, se_name), jack))


def _view_record(engine, sensor: Sensor, frame: np.ndarray, key: int):
    rec = engine.probe_record()
    w, h = sensor.resolution
    lon0, dlon, lat0, dlat = V.hemisphere_layout(w, h)
    rec.position = _vec3(sensor.position)
    rec.ex, rec.ey, rec.ez = _vec3(frame[:, 0]), _vec3(frame[:, 1]), _vec3(frame[:, 2])
    rec.width, rec.height = int(w), int(h)
    rec.lon0, rec.dlon, rec.lat0, rec.dlat = lon0, dlon, lat0, dlat
    rec.key = int(key)
    return rec


def run_glare(scene: Scene, views: list[Sensor], method: str, make_engine: Callable, *, seed: int,
              stream_ids: list[int] | None = None, max_depth: int = -1, max_passes: int = 4096,
              time_limit_s: float | None = None, progress: Callable | None = None, stop=None) -> list[GlareResult]:  # fmt: skip
    """Read glare views (GLARE sensors, each carrying its :class:`GlareSettings` in ``sensor.glare``).

    Parameters
    ----------
    scene : Scene
        The stage as authored.
    views : list of Sensor
    method : str
        light, bsdf, mis, path or guided (the run's probe method).
    make_engine : callable
        ``make_engine(scene, sensors)`` → an :class:`~simulator.engine.driver.Engine` on the run's device,
        with the run's spectral tables (the scene handed to it is ``scene`` with its suns made delta:
        the same lights in the same order).
    seed : int
    stream_ids : list of int, optional
        Random-stream index of each view (its index among the run's sensors).
    max_depth : int
    max_passes : int
        Most passes (directions per pixel) a view draws.
    time_limit_s : float, optional
        No new batch after this many seconds from the start of the call.
    progress : callable, optional
        Receives ``(views done, views, samples so far, seconds)`` after each batch.
    stop : StopFlag, optional
        Once requested, the view being read keeps its batches (``interrupted``) and no other is started.

    Returns
    -------
    list of GlareResult
        One per view read, in order.
    """
    t_start = time.perf_counter()
    stream_ids = list(range(len(views))) if stream_ids is None else list(stream_ids)
    view_scene = glare_scene(scene)
    view_engine = make_engine(view_scene, [])
    params = view_engine.trace_params(method, seed, max_depth, "total")
    originals = {l.name: l for l in suns_of(scene)}  # with their angle (the view scene's are delta)
    sun_ids = set(originals)
    deltas = _delta_lights(view_scene)  # the suns (made delta) and the stage's own delta lights
    is_sun = np.array([l.name in sun_ids for l in deltas], bool)
    out: list[GlareResult] = []
    total = 0
    for k, s in enumerate(views):
        if stop is not None and stop.requested:
            break
        t0 = time.perf_counter()
        settings: GlareSettings = s.glare if s.glare is not None else GlareSettings()
        frame = V.view_frame(s.normal, s.up)
        w, h = s.resolution
        n_pix = int(w) * int(h)
        omega = V.pixel_solid_angles(w, h).reshape(-1)
        dirs = V.pixel_centre_directions(w, h, frame).reshape(-1, 3)
        warnings: list[str] = []
        e, w_l, notes = _delta_split(view_engine, deltas, np.asarray(s.position, np.float64), seed)
        warnings += [f"glare view {s.name}: {n}" for n in notes]
        cos = np.maximum(0.0, w_l @ frame[:, 2])
        points = ~is_sun
        delta = (cos[points, None] * e[points]).sum(axis=0) if points.any() else np.zeros(2)
        for l, c, el in zip([l for l, p in zip(deltas, points) if p], cos[points], e[points]):
            if c > 0 and el[1] > 0:
                warnings.append(f"glare view {s.name}: {l.name} has no size: it adds to E_v but is not a glare source")
        suns = _sun_readings([originals[l.name] for l, x in zip(deltas, is_sun) if x], e[is_sun], w_l[is_sun], frame[:, 2])
        rec = _view_record(view_engine, s, frame, P.stream_key(seed, stream_ids[k]))
        stats = None
        passes, batch, bad = 0, MIN_GLARE_PASSES, 0
        met = interrupted = False
        est = None
        groups: list[RunningStats] = []
        view_dir = frame[:, 2]

        def estimate(count, mean, m2):
            return evaluate(pixel_stats(count, mean, m2, view_dir), omega, dirs, frame, suns, delta, settings, (h, w))

        while True:
            # a batch is JACKKNIFE_GROUPS launches of batch/K passes each, one per group
            m = batch // JACKKNIFE_GROUPS
            for g in range(JACKKNIFE_GROUPS):
                counts, means, m2s, b = view_engine.probe_passes(rec, params, passes + g * m, m)
                if len(groups) < JACKKNIFE_GROUPS:
                    groups.append(RunningStats(n_pix, means.shape[1]))
                if stats is None:
                    stats = RunningStats(n_pix, means.shape[1])
                groups[g].merge(np.arange(n_pix), counts, means, m2s)
                stats.merge(np.arange(n_pix), counts, means, m2s)
                bad += int(b)
            passes += batch
            total += batch * n_pix
            est = estimate(stats.count, stats.mean, stats.m2)
            _jackknife(est, [estimate(*_without(stats, grp)) for grp in groups])
            if progress is not None:
                progress(k, len(views), total, time.perf_counter() - t_start)
            if est.dgp_stderr <= settings.dgp_stderr:
                met = True
                break
            if stop is not None and stop.requested:
                interrupted = True
                break
            if passes >= max_passes or (time_limit_s is not None and time.perf_counter() - t_start >= time_limit_s):
                break
            need = math.ceil(1.1 * passes * (est.dgp_stderr / settings.dgp_stderr) ** 2)
            batch = int(min(max(need - passes, MIN_GLARE_PASSES), 4 * passes, max_passes - passes))
            batch = max(JACKKNIFE_GROUPS, batch - batch % JACKKNIFE_GROUPS)
        if bad:
            warnings.append(f"glare view {s.name}: {bad} non-finite samples were counted as 0")
        if not met:
            warnings.append(f"glare view {s.name}: DGP's standard error {est.dgp_stderr:.4f} is above its target "
                            f"{settings.dgp_stderr:g} after {passes} passes")  # fmt: skip
        se = stats.stderr()[:, 1]
        out.append(GlareResult(
            sensor=s, frame=frame, estimate=est, luminance=stats.mean[:, 1].reshape(h, w).copy(),
            luminance_stderr=np.where(np.isfinite(se), se, 0.0).reshape(h, w), suns=suns, settings=settings,
            passes=passes, samples=passes * n_pix, seconds=time.perf_counter() - t0,
            target_met=met, non_finite=bad, warnings=warnings, interrupted=interrupted,
        ))  # fmt: skip
    return out
