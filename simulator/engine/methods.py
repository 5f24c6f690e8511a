"""Method and component names, defined once (no Warp here: configs, the
planner and the commands import this cheaply).

A Monte Carlo method is a set of estimator strategies (see
:mod:`simulator.kernels.estimators`): next-event estimation, cosine-weighted
directions, both combined by multiple importance sampling, and
interreflection; ``guided`` is ``path`` whose next vertex is drawn, with
probability c, on the surfaces a pilot found passing light on to the sensors
(:mod:`simulator.engine.guide`). ``analytic`` is the closed form where nothing occludes;
``exact`` the closed form of each RectLight's visible part past a few
occluders (:mod:`simulator.engine.exact`); ``auto`` lets the planner choose
per sensor.
"""

from __future__ import annotations

__all__ = ["METHOD_FLAGS", "GUIDED_METHODS", "MC_METHODS", "HYBRID_METHODS", "READ_METHODS", "METHODS", "COMPONENTS",
           "LIGHT_PICK_MODES", "light_pick_rule", "rr_threshold_rule", "rr_pilot_choice", "sampled_method"]

#: Monte Carlo method → (next-event estimation, cosine directions, MIS, interreflection)
METHOD_FLAGS = {
    "light": (1, 0, 0, False),
    "bsdf": (0, 1, 0, False),
    "mis": (1, 1, 1, False),
    "path": (1, 1, 1, True),
    "guided": (1, 1, 1, True),
}
#: Monte Carlo methods that sample the surface guide besides cosine directions
GUIDED_METHODS = ("guided",)
#: methods with a Monte Carlo kernel
MC_METHODS = tuple(METHOD_FLAGS)
#: the hybrids the planner picks for irradiance sensors that need paths: the direct light of the
#: emitters ``exact`` can read computed on the host, the rest (the reflected light, and the direct
#: light of the other lights) sampled by the paths named after the ``+`` (engine.driver.Engine.run)
HYBRID_METHODS = {"exact+path": "path", "exact+guided": "guided"}
#: methods that read a sensor: the closed form and the Monte Carlo ones
READ_METHODS = ("analytic", "exact", *MC_METHODS)
#: what ``simulation.method`` may ask for
METHODS = ("auto", *READ_METHODS)
#: which light a reading counts
COMPONENTS = ("total", "direct", "indirect")


def sampled_method(method: str) -> str:
    """The Monte Carlo method a method's samples are drawn with (a hybrid's paths; else itself)."""
    return HYBRID_METHODS.get(method, method)


def area_light_count(scene) -> int:
    """Lights a direction can hit (not point lights or angle-0 distant
    lights), emissive surfaces counted as one."""
    emissive = scene.geometry.n_triangles > 0 and bool((scene.geometry.emission > 0).any())
    return sum(not l.is_delta for l in scene.lights) + int(emissive)


#: how next-event estimation samples lights: every light at every vertex;
#: one picked light with area at every vertex; every light at the sensor's
#: own vertex and one picked light at the later ones (kernels.light_pick)
LIGHT_PICK_MODES = {"off": 0, "every": 1, "after_first": 2}


def light_pick_rule(method: str, scene) -> tuple[str, str]:
    """``(mode, reason)``: how ``method`` samples lights at a vertex, one of
    :data:`LIGHT_PICK_MODES`.

    Measured (docs/DESIGN.md §Next-event estimation): at the sensor's own
    vertex every light it sees is worth its ray, so direct-light methods
    keep sampling all of them, and so do paths there; past it most vertices
    see most lights blocked or faint, and one picked light per vertex cut
    the office's variance × time 1.5–2×.
    """
    flags = METHOD_FLAGS.get(method)
    if flags is None or not flags[0]:
        return "off", "no next-event estimation"
    n = area_light_count(scene)
    if n < 2:
        return "off", "at most one light with area: nothing to pick"
    if not flags[3]:
        return "off", "direct light: at the sensor every light it sees is worth its ray"
    return "after_first", (f"{n} lights with area; at the sensor each is worth its ray, past it most are blocked or "
                           "faint, so one is picked by its estimated share")


# Russian roulette weight window (kernels.estimators.vertex_irradiance): a
# path's throughput β never falls below the threshold t; below it the path
# survives with probability β/t and β is lifted back to t. Plain roulette
# (t = 1) leaves every path weight 1, so the path's length makes the noise; a
# lower t follows paths without roulette while β ≥ t, ln t/ln ρ more bounces.
# Measured with one picked light per vertex, as variance × rays per sample
# relative to the best threshold tried (1.00; lower is better), path on the
# bundled configs:
#
#   config (area-weighted ρ̄)     0.005  0.01  0.02  0.05  0.1   0.25  0.5   1
#   office (0.23), 48 samples      -      -     -    1.05  1.00  1.15  1.33  1.23
#   quickstart (0.58), 256         -      -     -    1.20  1.08  1.00  1.21  2.22
#   furnace ρ = 0.5, 2048          1.50   1.34  1.20  1.03  1.00  1.28  2.32  5.46
#   furnace ρ = 0.9, 1024          1.23   1.11  1.00  1.07  1.66  5.23  14.5  32.5
#   furnace ρ = 0.95, 512          1.14   1.06  1.00  1.35  2.76  9.73  23.0  60.2
#   CIE 171 5.8, ρ = 0.5, 2048     1.64   1.47  1.30  1.05  1.00  1.03  1.56  3.46
#   CIE 171 5.8, ρ = 0.8, 1024     1.44   1.30  1.16  1.03  1.00  1.71  3.79  8.91
#   integrating sphere ρ = 0.8     1.00   3.35  11.9  62.6  199   956   2640  6760
#
# (fixed seeds, variance from the readings' own standard errors; a shared
# 2-core machine, so CPU times were not used; measured with the roulette
# before a vertex's next-event estimate, since moved after it: docs/DESIGN.md
# §Russian roulette.) No single
# value wins: a room wants 0.1–0.25, an enclosure of high albedo 0.02 or
# less. The rule t = min(0.1, 0.2·(1 − ρ̄)), at least 0.01, with ρ̄ the
# scene's area-weighted albedo, is within ~10% of the best on every row but
# the integrating sphere, where the walls see the lamp from everywhere, so
# the light each bounce adds by next-event estimation hardly varies and the
# roulette's own noise is all there is (the rule's 0.04 gains ~5× over 0.1
# there; 0.005 would gain 60× more, which a rule by albedo alone cannot see:
# the engine's pilot, rr_pilot_choice below, finds it).
#: the threshold of a scene of low albedo (and the cap of the rule)
RR_THRESHOLD_MAX = 0.1
#: t = RR_SLOPE·(1 − ρ̄) below the cap
RR_SLOPE = 0.2
#: the smallest threshold the rule gives (ρ̄ → 1: paths ~ln t/ln ρ̄ long)
RR_THRESHOLD_MIN = 0.01


def mean_albedo(scene) -> float:
    """Area-weighted mean albedo ρ̄ of the scene's triangles (0 without any)."""
    import numpy as np

    from simulator.scene.vectors import cross3

    g = scene.geometry
    if g.n_triangles == 0:
        return 0.0
    p0, p1, p2 = (np.take(g.points, g.triangles[:, k], axis=0) for k in range(3))  # as points[triangles], faster
    area = 0.5 * np.linalg.norm(cross3(p1 - p0, p2 - p0), axis=1)
    total = float(area.sum())
    return float((area * g.albedo).sum() / total) if total > 0 else 0.0


def rr_threshold_rule(scene) -> tuple[float, str]:
    """The Russian roulette threshold for paths in ``scene`` and why (see
    the measurements above)."""
    rho = mean_albedo(scene)
    t = min(RR_THRESHOLD_MAX, max(RR_THRESHOLD_MIN, RR_SLOPE * (1.0 - rho)))
    rule = f"min({RR_THRESHOLD_MAX:g}, {RR_SLOPE:g}·(1 − ρ̄)), ρ̄ = {rho:.2f}"
    return t, f"Russian roulette below throughput {t:.3g}: {rule}, lowered where a pilot measures that it pays"


#: the pilot (rr_pilot_choice) tries thresholds t/RR_PILOT_STEP, t/RR_PILOT_STEP², …
RR_PILOT_STEP = 4.0
#: … at most this many below the rule's
RR_PILOT_STEPS = 3
#: a lower threshold is taken only when it divides variance × rays per sample by this much
RR_PILOT_GAIN = 2.0
#: … or, in an adaptive run, the rays its noisiest sensor spends to the target by this much (a
#: step costs at most its longer paths, ≤ 1.3× the rays, where the pilot's noise misleads it)
RR_PILOT_TARGET_GAIN = 1.2


def rr_pilot_choice(t_rule: float, measure, first_batch: int | None = None, z: float = 1.96,
                    rel_error: float | None = None) -> tuple[float, list[tuple[float, float, float, float]]]:
    """The roulette threshold a pilot measures best, starting from the rule's.

    Parameters
    ----------
    t_rule : float
        The rule's threshold (:func:`rr_threshold_rule`).
    measure : callable
        ``measure(t) -> (relvar_mean, relvar_max, rays)``: over the pilot's
        sensors, the mean and the largest relative variance per sample
        (stderr²·n/mean²), and rays traced per sample, at threshold ``t``.
    first_batch : int, optional
        With ``rel_error``: the samples every sensor draws anyway (an adaptive
        run's floor: its first batch where the config sets ``samples``, else
        the fewest the engine's own first batch draws).
    z, rel_error : float, optional
        An adaptive run's target z·stderr ≤ rel_error·|mean|.

    Returns
    -------
    t : float
        The threshold chosen.
    tried : list of (t, relvar_mean, relvar_max, rays)
        What the pilot measured, in the order tried.

    Notes
    -----
    The threshold is lowered by :data:`RR_PILOT_STEP` while that divides the
    cost by at least :data:`RR_PILOT_GAIN` (:data:`RR_PILOT_TARGET_GAIN` in
    an adaptive run; a margin over the pilot's own
    noise: lowering t only lengthens the paths where the roulette is not
    most of the noise), at most :data:`RR_PILOT_STEPS` times. A fixed-budget
    run's cost at equal error is relvar × rays per sample. An adaptive run's
    is tuned to its target: the rays its noisiest sensor spends,
    rays × max(first_batch, z²·relvar_max/rel_error²), so the search stops
    as soon as that sensor would meet the target within ``first_batch``
    samples (a lower t could then save no samples, only lengthen them).
    """
    adaptive = rel_error is not None and first_batch is not None

    def need(rv_max: float) -> float:
        return z * z * rv_max / rel_error**2

    def cost(rv: float, rv_max: float, rays: float) -> float:
        return rays * max(first_batch, need(rv_max)) if adaptive else rv * rays

    t = t_rule
    rv, rv_max, rays = measure(t)
    tried = [(t, rv, rv_max, rays)]
    for _ in range(RR_PILOT_STEPS):
        if (adaptive and need(rv_max) <= first_batch) or not rv > 0:
            break
        t_next = t / RR_PILOT_STEP
        rv_n, rv_max_n, rays_n = measure(t_next)
        tried.append((t_next, rv_n, rv_max_n, rays_n))
        if not cost(rv_n, rv_max_n, rays_n) * (RR_PILOT_TARGET_GAIN if adaptive else RR_PILOT_GAIN) <= cost(rv, rv_max, rays):
            break
        t, rv, rv_max, rays = t_next, rv_n, rv_max_n, rays_n
    return t, tried
