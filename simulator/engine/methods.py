"""Method and component names, defined once (no Warp here: configs, the
planner and the commands import this cheaply).

A Monte Carlo method is a set of estimator strategies (see
:mod:`simulator.kernels.estimators`): next-event estimation, cosine-weighted
directions, both combined by multiple importance sampling, and
interreflection. ``analytic`` is the closed form where nothing occludes;
``exact`` the closed form of each RectLight's visible part past a few
occluders (:mod:`simulator.engine.exact`); ``auto`` lets the planner choose
per sensor.
"""

from __future__ import annotations

__all__ = ["METHOD_FLAGS", "MC_METHODS", "READ_METHODS", "METHODS", "COMPONENTS", "light_pick_rule"]

#: Monte Carlo method → (next-event estimation, cosine directions, MIS, interreflection)
METHOD_FLAGS = {
    "light": (1, 0, 0, False),
    "bsdf": (0, 1, 0, False),
    "mis": (1, 1, 1, False),
    "path": (1, 1, 1, True),
}
#: methods with a Monte Carlo kernel
MC_METHODS = tuple(METHOD_FLAGS)
#: methods that read a sensor: the closed form and the Monte Carlo ones
READ_METHODS = ("analytic", "exact", *MC_METHODS)
#: what ``simulation.method`` may ask for
METHODS = ("auto", *READ_METHODS)
#: which light a reading counts
COMPONENTS = ("total", "direct", "indirect")


def area_light_count(scene) -> int:
    """Lights a direction can hit (not point lights or angle-0 distant
    lights), emissive surfaces counted as one."""
    emissive = scene.geometry.n_triangles > 0 and bool((scene.geometry.emission > 0).any())
    return sum(not l.is_delta for l in scene.lights) + int(emissive)


def light_pick_rule(method: str, scene) -> tuple[bool, str]:
    """Whether next-event estimation samples one light with area per vertex,
    picked by its estimated share (``kernels.light_pick``), or every light;
    and why.

    Measured (``probesim bench``, docs/DESIGN.md §Next-event estimation):
    with paths every vertex past the first sees most lights blocked or
    faint, and one picked light per vertex cut the office's time to 1% RMS;
    direct-light methods read the sensor's own vertex, where every light it
    sees is worth its ray, so they keep sampling all of them.
    """
    flags = METHOD_FLAGS.get(method)
    if flags is None or not flags[0]:
        return False, "no next-event estimation"
    n = area_light_count(scene)
    if n < 2:
        return False, "at most one light with area: nothing to pick"
    if not flags[3]:
        return False, "direct light: every light sampled at the sensor"
    return True, f"{n} lights with area: one picked per vertex by its estimated share"
