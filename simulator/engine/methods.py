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

__all__ = ["METHOD_FLAGS", "GUIDED_METHODS", "MC_METHODS", "READ_METHODS", "METHODS", "COMPONENTS"]

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
#: methods that read a sensor: the closed form and the Monte Carlo ones
READ_METHODS = ("analytic", "exact", *MC_METHODS)
#: what ``simulation.method`` may ask for
METHODS = ("auto", *READ_METHODS)
#: which light a reading counts
COMPONENTS = ("total", "direct", "indirect")
