"""Which estimator a run uses, and why.

``method = "auto"`` picks the cheapest estimator that the scene allows:
direct light sampling where no surface reflects, full paths where one does.
An explicit method is used as asked.
"""

from __future__ import annotations

import numpy as np

from .errors import UserError
from .scene.model import Scene, Sensor

__all__ = ["choose_method", "MC_METHODS"]

#: methods with a Monte Carlo kernel
MC_METHODS = ("light", "bsdf", "mis", "path")


def choose_method(scene: Scene, sensors: list[Sensor], requested: str, component: str = "total") -> tuple[str, str]:
    """Return ``(method, reason)`` for the run."""
    reflects = scene.geometry.n_triangles > 0 and bool(np.any(scene.geometry.albedo > 0))
    if requested == "auto":
        if component == "indirect":
            return "path", "auto: the indirect component is light reflected on the way: paths"
        if reflects:
            return "path", "auto: surfaces reflect (albedo > 0), so interreflection needs paths"
        return "light", "auto: no surface reflects, so direct light sampling is exact in expectation and cheapest"
    if requested in MC_METHODS:
        if requested != "path" and reflects:
            return requested, f"as requested; direct light only: interreflection is ignored ({requested} does not bounce)"
        return requested, "as requested"
    raise UserError(f"simulation.method: {requested!r} is not available yet (use auto, light, bsdf, mis or path)")
