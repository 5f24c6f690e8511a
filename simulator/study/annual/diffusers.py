"""Diffusing shades: a flat shade prim that passes τ·E/π into the room, E the light on its outer face.

A roller blind or fabric shade scatters what it passes: IES LM-83-12 §2.2.7
models a shade without measured data as a *diffuse* transmittance (the
fabric's visible transmittance less its openness; 5% where unknown), for
sunlight and skylight alike. The kernels transmit light straight through
panes and gaps only, so a diffusing shade is read in two steps, each an
ordinary trace of the study (light is linear in emission):

1. **Outside.** The shade's rectangle is cut into cells of at most
   :data:`CELL_M` a side; at each cell's centre, :data:`OFFSET_M` outside
   its face, an irradiance sensor facing out reads the cell's outer
   irradiance E_c(h) by the sky's daylight coefficients (direct and
   interreflected, in the state's sky traces), the exact direct sun
   (:mod:`simulator.study.annual.sunlight`) and the sun's interreflected light
   from the patches around it.
2. **Inside.** Each cell's room side is a Lambertian emitter of luminance
   L_c(h) = τ·E_c(h)/π (a perfect diffuser: all it passes leaves as from a
   uniform diffuser, whatever the incidence): a RectLight of the cell's size
   :data:`OFFSET_M` inside its face, facing the room, traced once as a light
   group of its own at an authored luminance L_auth; every hour recombines
   its coefficients with L_c(h)/L_auth.

The shade prim itself is what the stage says it is (an opaque matte blind of
its colour, or a translucent layer whose gaps are an openness factor passed
straight by the kernels): it reflects the room's light and the sky's, and
blocks the rest. Its front face (the triangles' normal) faces the room.

Left out: the light the room sends back through the shade, and the cell's
variation across its area (one outer sensor at its centre).

References
----------
IES LM-83-12 (2012), §2.2.7; docs/REFERENCES.md §Operable shading.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, replace

import numpy as np

from simulator.errors import UserError
from simulator.scene.model import Light, LightKind, Sensor, SensorKind

__all__ = ["CELL_M", "OFFSET_M", "Diffuser", "diffusers_of", "cell_lights", "outer_sensors", "lights_digest", "with_lights"]

#: the longest side of a shade's cell, metres
CELL_M = 0.75
#: how far from the shade's face its outer sensors and inner emitters sit, metres
OFFSET_M = 0.002
#: how far a shade prim's points may lie off its plane, or its area from its rectangle's, relative
_FLAT_TOL = 1e-3


@dataclass(frozen=True)
class Diffuser:
    """A diffusing shade in one state (module docstring).

    Attributes
    ----------
    prim : str
    transmittance : float
        τ, its diffuse visible transmittance.
    centre, u, v, normal : ndarray, shape (3,)
        The rectangle's centre and unit axes; ``normal`` faces the room (u × v = −normal).
    width, height : float
        Along u and v, metres.
    cells : tuple of int
        (nu, nv).
    """

    prim: str
    transmittance: float
    centre: np.ndarray
    u: np.ndarray
    v: np.ndarray
    normal: np.ndarray
    width: float
    height: float
    cells: tuple[int, int]

    @property
    def n_cells(self) -> int:
        return self.cells[0] * self.cells[1]

    def cell_centres(self) -> np.ndarray:
        """(C, 3): cell (i, j) at index j·nu + i."""
        nu, nv = self.cells
        a = (np.arange(nu) + 0.5) / nu - 0.5
        b = (np.arange(nv) + 0.5) / nv - 0.5
        aa, bb = np.meshgrid(a * self.width, b * self.height)
        return self.centre + aa.reshape(-1, 1) * self.u + bb.reshape(-1, 1) * self.v

    def cell_of(self, points: np.ndarray) -> np.ndarray:
        """The cell each point on the shade lies in (−1 outside its rectangle), shape (N,)."""
        p = np.asarray(points, np.float64) - self.centre
        a = p @ self.u / self.width + 0.5
        b = p @ self.v / self.height + 0.5
        nu, nv = self.cells
        i = np.floor(a * nu).astype(np.int64)
        j = np.floor(b * nv).astype(np.int64)
        inside = (a >= 0) & (a <= 1) & (b >= 0) & (b <= 1)
        return np.where(inside, np.clip(j, 0, nv - 1) * nu + np.clip(i, 0, nu - 1), -1)

    def cell_names(self) -> list[str]:
        nu, _ = self.cells
        return [f"{self.prim}#cell[{k % nu},{k // nu}]" for k in range(self.n_cells)]


def _rectangle(points: np.ndarray, tris: np.ndarray, normal: np.ndarray, key: str) -> tuple:
    """(centre, u, v, width, height) of the least-area rectangle around a flat prim's triangles (in the
    directions of their edges), checked to be the prim's own outline."""
    e = np.concatenate([points[tris[:, 1]] - points[tris[:, 0]], points[tris[:, 2]] - points[tris[:, 1]],
                        points[tris[:, 0]] - points[tris[:, 2]]])  # fmt: skip
    e = e - np.outer(e @ normal, normal)
    e = e[np.linalg.norm(e, axis=1) > 1e-9]
    area = 0.5 * float(np.sum(np.linalg.norm(np.cross(points[tris[:, 1]] - points[tris[:, 0]],
                                                      points[tris[:, 2]] - points[tris[:, 0]]), axis=1)))  # fmt: skip
    pts = points[np.unique(tris)]
    best = None
    for d in e:
        u = d / np.linalg.norm(d)
        v = np.cross(normal, u)
        a, b = pts @ u, pts @ v
        w, h = float(a.max() - a.min()), float(b.max() - b.min())
        if best is None or w * h < best[0] - 1e-12:
            c = 0.5 * (a.max() + a.min()) * u + 0.5 * (b.max() + b.min()) * v + float(pts[0] @ normal) * normal
            best = (w * h, c, u, v, w, h)
    if best is None or best[0] <= 0 or abs(area - best[0]) > _FLAT_TOL * best[0] + 1e-9:
        raise UserError(f"{key}: the prim is not a flat rectangle (its faces cover {area:.4g} m² of the "
                        f"{0.0 if best is None else best[0]:.4g} m² rectangle around them)")  # fmt: skip
    return best[1:]


def diffusers_of(scene, spec: dict, label: str) -> list[Diffuser]:
    """The diffusing shades of ``spec`` (prim path → τ) present in ``scene``, in ``spec``'s order."""
    g = scene.geometry
    names = list(g.prim_names)
    prim_of = np.asarray(g.prim)
    out = []
    for path, tau in spec.items():
        key = f"{label}: shading.diffusers.{path}"
        idx = [k for k, n in enumerate(names) if n == path]
        faces = np.nonzero(np.isin(prim_of, idx))[0] if idx else np.zeros(0, np.int64)
        if not len(faces):
            continue
        pts = np.asarray(g.points, np.float64)
        tris = np.asarray(g.triangles)[faces]
        nrm = np.cross(pts[tris[:, 1]] - pts[tris[:, 0]], pts[tris[:, 2]] - pts[tris[:, 0]]).sum(axis=0)
        if not np.linalg.norm(nrm) > 0:
            raise UserError(f"{key}: the prim's faces have no area")
        n = nrm / np.linalg.norm(nrm)
        off = (pts[np.unique(tris)] - pts[tris[0, 0]]) @ n
        if np.max(np.abs(off)) > _FLAT_TOL * max(1.0, float(np.ptp(pts[np.unique(tris)], axis=0).max())):
            raise UserError(f"{key}: the prim is not flat (its points lie up to {np.max(np.abs(off)):.3g} m off its plane)")
        c, u, v, w, h = _rectangle(pts, tris, n, key)
        v = np.cross(u, n)  # u × v = −n: a RectLight in the frame (u, v, −n) emits along n, into the room
        cells = (max(1, math.ceil(w / CELL_M - 1e-9)), max(1, math.ceil(h / CELL_M - 1e-9)))
        out.append(Diffuser(path, float(tau), np.asarray(c, np.float64), u, v, n, float(w), float(h), cells))
    return out


def outer_sensors(d: Diffuser) -> list[Sensor]:
    """An irradiance sensor facing out, :data:`OFFSET_M` outside the centre of each cell."""
    return [Sensor(name=f"{nm}#outer", kind=SensorKind.IRRADIANCE, position=c - OFFSET_M * d.normal, normal=-d.normal.copy(),
                   source=d.prim) for c, nm in zip(d.cell_centres(), d.cell_names())]  # fmt: skip


def cell_lights(d: Diffuser, luminance_cd_m2: float, dome: Light) -> list[Light]:
    """A RectLight per cell, :data:`OFFSET_M` inside the shade, emitting ``luminance_cd_m2`` toward the room
    (the radiometric twin in the dome's ratio, its spectrum the dome's)."""
    ratio = float(dome.emission[0]) / float(dome.emission[1]) if dome.emission[1] > 0 else 1.0 / 683.0
    frame = np.column_stack([d.u, d.v, -d.normal])  # right-handed (u × v = −n), emitting along its −Z: into the room
    nu, nv = d.cells
    out = []
    for c, nm in zip(d.cell_centres(), d.cell_names()):
        out.append(Light(nm, LightKind.RECT, c + OFFSET_M * d.normal, frame, (luminance_cd_m2 * ratio, luminance_cd_m2),
                         width=d.width / nu, height=d.height / nv, spectrum=dome.spectrum, color=dome.color))  # fmt: skip
    return out


def lights_digest(lights: list[Light]) -> str:
    """A SHA-256 of the lights' geometry and emission, for chunk ids."""
    text = "|".join(f"{l.name};{int(l.kind)};{np.round(l.position, 9).tolist()};{np.round(l.frame, 9).tolist()};"
                    f"{l.emission!r};{l.width!r};{l.height!r};{l.spectrum!r}" for l in lights)  # fmt: skip
    return hashlib.sha256(text.encode()).hexdigest()


def with_lights(scene, lights: list[Light]):
    """``scene`` with ``lights`` added."""
    return replace(scene, lights=list(scene.lights) + list(lights))
