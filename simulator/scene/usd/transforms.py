"""Prim transforms in the world frame: affine maps, axis scales and orthonormal frames.

Every world quantity goes through ``p_world = s * R_up @ (A_stage @ p + t_stage)``
(see "World frame" in :mod:`simulator.scene.usd`); ``ctx.to_world`` is
``s * R_up`` and ``ctx.xforms`` caches the stage's local-to-world matrices.
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd

from simulator.scene.usd.context import _Context, _not_uniform


def _world_affine(ctx: _Context, prim: Usd.Prim) -> tuple[np.ndarray, np.ndarray]:
    """World map ``p -> A @ p + t`` in metres, Z up.

    USD matrices act on row vectors (``p' = p M``, translation in the last
    row), so the column-vector linear part is ``M[:3, :3].T``.
    """
    try:
        m = np.array(ctx.xforms.GetLocalToWorldTransform(prim), dtype=float)
    except Exception as exc:  # Tf.ErrorException: an xformOpOrder naming an op pxr cannot build, ...
        from simulator.scene.usd.stage import _pxr_reason

        raise ctx.error(prim, f"transform cannot be computed ({_pxr_reason(exc)})") from None
    if not np.all(np.isfinite(m)):
        raise ctx.error(prim, "transform contains NaN or Inf")
    a = ctx.to_world @ m[:3, :3].T
    t = ctx.to_world @ m[3, :3]
    return a, t


def _axis_scales(a: np.ndarray) -> np.ndarray:
    """World length of the prim's unit X, Y, Z axes (metres per local unit)."""
    return np.linalg.norm(a, axis=0)


def _unit(v: np.ndarray) -> np.ndarray | None:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 and math.isfinite(n) else None


def _frame(ctx: _Context, prim: Usd.Prim, a: np.ndarray, right_handed: bool = True) -> np.ndarray:
    """Orthonormal frame whose Z (and X, as far as possible) follow the prim's.

    Gram-Schmidt from Z keeps the emission axis exact; Y = ±(Z x X). With
    ``right_handed`` (portals) Y = Z x X whatever the transform. Without it
    (lights) Y takes the sign of ``det(a)``: a mirroring transform (a
    negative scale) gives a left-handed frame, the prim's own, so a
    direction at local φ in a luminaire's web leaves the world at the
    mirror image of φ, as it does off the mirrored prim (a right-handed
    frame would rotate the web instead: φ 75° would read φ 285°).
    """
    z = _unit(a[:, 2])
    x = None if z is None else _unit(a[:, 0] - np.dot(a[:, 0], z) * z)
    if z is None or x is None:
        raise ctx.error(prim, "transform is degenerate (zero scale); cannot orient it")
    y = np.cross(z, x)
    if not right_handed and np.linalg.det(a) < 0:
        y = -y
    return np.column_stack([x, y, z])


def _mean_scale(ctx: _Context, prim: Usd.Prim, scales: np.ndarray, what: str) -> float:
    """Mean of the given axis scales; warn when they differ (shape becomes round again)."""
    if _not_uniform(np.ptp(scales), float(np.max(scales))):
        ctx.warn(f"{prim.GetPath()}: non-uniform scale on a {what}; using the mean scale")
    return float(np.mean(scales))
