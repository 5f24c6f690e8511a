"""The luminaire schedule of a report: each kind of luminaire on the stage, how many, and the lumens each emits.

A light's lumens are those it emits as traced,
:func:`simulator.scene.light_flux.emitted_flux` (the run record's figure:
emission × the kind's G, its shaping integrated exactly against the
interpolant the kernels trace). Emissive geometry (a mesh light) emits
Σ π·A·L over its emitting triangles, doubled for a two-sided one.

Dome and distant lights are the sky and the sun, not luminaires: they are
listed apart (:func:`daylight_sources`).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np

from simulator.scene.light_flux import emitted_flux
from simulator.scene.model import LightKind

__all__ = ["emitted", "LuminaireRow", "luminaire_schedule", "daylight_sources"]

#: what a designer calls each kind
KIND_NAMES = {LightKind.POINT: "point light", LightKind.SPHERE: "sphere light", LightKind.RECT: "rectangular panel",
              LightKind.DISK: "disc", LightKind.CYLINDER: "linear (cylinder) lamp", LightKind.EMISSIVE: "luminous surface"}  # fmt: skip


def emitted(light) -> tuple[float, float]:
    """``(W, lm)`` a light emits as traced; NaN for the sky and the sun (no finite flux)."""
    flux = emitted_flux(light)
    return (float("nan"), float("nan")) if flux is None else flux


def _mesh_lights(geometry) -> dict[str, tuple[float, float]]:
    """Prim → (W, lm) of the emitting triangles (π·A·L per face that emits)."""
    g = geometry
    if not g.n_triangles:
        return {}
    lit = np.flatnonzero(np.any(g.emission > 0, axis=1))
    if not len(lit):
        return {}
    p = g.points[g.triangles[lit]]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    sides = np.where(g.two_sided[lit], 2.0, 1.0)
    flux = math.pi * (area * sides)[:, None] * g.emission[lit]
    prims = g.prim[lit] if len(g.prim) == g.n_triangles else np.zeros(len(lit), np.int64)
    out: dict[str, tuple[float, float]] = {}
    for pid in np.unique(prims):
        s = flux[prims == pid].sum(axis=0)
        name = g.prim_names[int(pid)] if int(pid) < len(g.prim_names) else f"prim {int(pid)}"
        out[name] = (float(s[0]), float(s[1]))
    return out


@dataclass(frozen=True)
class LuminaireRow:
    """One kind of luminaire: same kind, size, output and photometric file."""

    kind: str  #: what it is, with its size ("rectangular panel 0.60 × 0.60 m")
    count: int
    lumens: float  #: each, lm
    watts: float  #: each, radiant W
    ies: str  #: the photometric file's name, "" when none
    prims: tuple[str, ...]  #: the lights' prim paths


def _size(light) -> str:
    k = light.kind
    if k == LightKind.RECT:
        return f" {light.width:.2f} × {light.height:.2f} m"
    if k in (LightKind.DISK, LightKind.SPHERE):
        return f" ⌀ {2 * light.radius:.2f} m"
    if k == LightKind.CYLINDER:
        return f" ⌀ {2 * light.radius:.3f} m × {light.length:.2f} m"
    return ""


def luminaire_schedule(scene) -> list[LuminaireRow]:
    """The stage's luminaires grouped by kind, size, lumens (to 4 digits) and IES file, in first-prim order."""
    groups: dict[tuple, list] = {}
    for l in scene.lights:
        if l.kind in (LightKind.DOME, LightKind.DISTANT, LightKind.EMISSIVE):
            continue
        w, lm = emitted(l)
        ies = l.shaping.ies if l.shaping is not None else None
        src = os.path.basename(getattr(ies, "source", "") or "") if ies is not None else ""
        key = (KIND_NAMES[l.kind] + _size(l), float(f"{lm:.4g}"), src)
        groups.setdefault(key, []).append((l.name, w, lm))
    rows = [LuminaireRow(k[0], len(v), v[0][2], v[0][1], k[2], tuple(n for n, _, _ in v)) for k, v in groups.items()]
    for name, (w, lm) in _mesh_lights(scene.geometry).items():
        rows.append(LuminaireRow(KIND_NAMES[LightKind.EMISSIVE], 1, lm, w, "", (name,)))
    return rows


def daylight_sources(scene) -> list[str]:
    """The sky (dome) and sun (distant) lights' prim paths."""
    return [l.name for l in scene.lights if l.kind in (LightKind.DOME, LightKind.DISTANT)]
