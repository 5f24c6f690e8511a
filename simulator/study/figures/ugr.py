"""UGR at the observers of EN 12464-1 areas: the luminaires as seen, the background traced.

An ``[[area]]`` with ``ugr_limit`` (the standard's UGR_L for the task, e.g.
19 for writing and reading in offices) is judged by the unified glare
rating of the study's luminaires at its observers (CIE 117-1995;
docs/REFERENCES.md §Glare indices), in every scenario::

    UGR = 8·log10(0.25/L_b · Σ_i L_i²·ω_i/P_i²),   L_b = E_ind/π.

- **Observers**: ``observers = [[x, y, z, dx, dy, dz], ...]`` (an eye and a
  view direction, up +Z), or by default one at the middle of each side of
  the task rectangle, 1.2 m above the floor (a seated eye: the floor is the
  area's work-plane points less their set's ``height_m``), looking level
  across the area (CIE 117's observer at a wall looking along the room).
- **Luminaires**: every light of the light groups that hold no sky or sun
  (lamps), lit at the scenario's level: a RectLight, DiskLight or
  SphereLight of luminance L_i toward the eye (its radiance × its shaping
  toward the eye × the level), ω_i the solid angle of its emitting surface
  in sight: the rectangle or disk cut into 8 × 8 cells (a disk: 8 rings × 32
  sectors), each cell's solid angle exact (Van Oosterom and Strackee's
  triangle formula) and counted when the segment from the eye to its
  centre meets no face; a sphere's cap, 2π(1 − √(1 − (r/d)²)), if its centre is
  in sight. Only luminaires in front of the eye whose emitting side faces it.
  P_i, the position index at the luminaire's centre (:mod:`simulator.glare.indices`).
  A point light (no size) is named once and left out. Exact: no variance.
- **Background**: L_b = E_ind/π, E_ind the indirect illuminance at the eye on
  the plane facing the view (light reflected at least once): an irradiance
  sensor per observer, traced with ``component = "indirect"`` per trace
  group of lamps alone (daylight is left out: EN 12464-1's UGR is the
  lighting installation's), recombined per scenario like every reading.
  Its standard error gives UGR's: σ_UGR = 8/ln 10 · σ_E/E_ind.
- **Verdict** per observer and scenario: ``pass`` when UGR is below the limit
  by more than 2 standard errors, ``fail`` when above it by more, else
  ``unsure``; an area's verdict in a scenario is its worst observer's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from simulator.errors import UserError
from simulator.glare.indices import position_index, ugr
from simulator.scene.model import LightKind, Sensor, SensorKind

__all__ = ["EYE_HEIGHT_M", "Observer", "UgrRow", "UGR_COLUMNS", "observers_of", "observer_sensors", "lamp_groups",
           "luminaire_terms", "ugr_rows"]  # fmt: skip

#: a seated eye above the floor (CIE 117's tables), metres
EYE_HEIGHT_M = 1.2
#: cells per side of a rectangle, rings and sectors of a disk, when the part in sight is counted
CELLS = 8
SECTORS = 32
_UP = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class Observer:
    """An eye of an area: where, and the way it looks (level, up +Z)."""

    area: str
    index: int
    position: np.ndarray
    direction: np.ndarray

    @property
    def name(self) -> str:
        return f"{self.area}:observer{self.index}"


@dataclass(frozen=True)
class UgrRow:
    """One observer in one scenario."""

    area: str
    observer: Observer
    scenario: str
    ugr: float
    ugr_stderr: float
    background_cd_m2: float
    indirect_lx: float
    indirect_stderr_lx: float
    luminaires: int  #: luminaires in sight, lit
    limit: float
    verdict: str


UGR_COLUMNS = ("area", "observer", "x", "y", "z", "dx", "dy", "dz", "scenario", "ugr", "ugr_stderr", "ugr_limit", "verdict",
               "background_luminance_cd_m2", "indirect_illuminance_lx", "indirect_illuminance_stderr_lx", "luminaires_seen")  # fmt: skip


def observers_of(study, sets, label: str) -> list[Observer]:
    """The observers of every area with a ``ugr_limit`` (module docstring), in area order.

    Raises
    ------
    UserError
        A default observer asked of an area without a task rectangle, or of a set of explicit points (no floor).
    """
    out = []
    specs = {c.name: c for c in study.candidates}
    for k, a in enumerate(study.area):
        if a.ugr_limit is None:
            continue
        if a.observers:
            for i, o in enumerate(a.observers):
                d = np.array(o[3:], np.float64)
                n = float(np.linalg.norm(d))
                if not n > 0.0 or abs(d[2]) / n > 1.0 - 1e-9:
                    raise UserError(f"{label}: area[{k}].observers[{i}]: the view direction must have length and not be vertical")
                out.append(Observer(a.name, i, np.array(o[:3], np.float64), d / n))
            continue
        spec = specs[a.candidates]
        cs = next(s for s in sets if s.name == a.candidates)
        if a.task is None or spec.on is None:
            raise UserError(f"{label}: area[{k}]: give observers = [[x, y, z, dx, dy, dz], ...] (the default ones stand at "
                            "the sides of a task rectangle, 1.2 m above the floor of a set laid on prims)")  # fmt: skip
        floor = float(np.mean([c.position[2] for c in cs.candidates])) - spec.height_m
        x0, y0, x1, y1 = a.task
        xc, yc, z = 0.5 * (x0 + x1), 0.5 * (y0 + y1), floor + EYE_HEIGHT_M
        for i, (p, d) in enumerate((((xc, y0, z), (0, 1, 0)), ((x1, yc, z), (-1, 0, 0)), ((xc, y1, z), (0, -1, 0)),
                                    ((x0, yc, z), (1, 0, 0)))):  # fmt: skip
            out.append(Observer(a.name, i, np.array(p, np.float64), np.array(d, np.float64)))
    return out


def observer_sensors(observers: list[Observer]) -> list[Sensor]:
    """The irradiance sensors whose indirect readings give each observer's E_ind (facing the view)."""
    return [Sensor(o.name, SensorKind.IRRADIANCE, o.position.copy(), o.direction.copy(), source=o.name) for o in observers]


def lamp_groups(scene, groups: dict[str, list[str]]) -> list[str]:
    """The light groups whose every light is a lamp (no DomeLight, no DistantLight)."""
    kind = {l.name: l.kind for l in scene.lights}
    return [g for g, names in groups.items() if names and all(kind.get(n) not in (LightKind.DOME, LightKind.DISTANT) for n in names)]


def _triangle_solid_angle(eye: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Solid angles of triangles (…, 3) seen from ``eye`` (Van Oosterom and Strackee 1983), unsigned."""
    ra, rb, rc = a - eye, b - eye, c - eye
    la, lb, lc = (np.linalg.norm(r, axis=-1) for r in (ra, rb, rc))
    num = np.abs(np.einsum("...i,...i->...", ra, np.cross(rb, rc)))
    den = la * lb * lc + np.einsum("...i,...i->...", ra, rb) * lc + np.einsum("...i,...i->...", ra, rc) * lb \
        + np.einsum("...i,...i->...", rb, rc) * la  # fmt: skip
    return 2.0 * np.arctan2(num, den)


def _cells(light) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A rect or disk light's emitting surface as triangles (a, b, c) and the centre of the cell each belongs to."""
    c0 = np.asarray(light.position, np.float64)
    ex, ey = light.frame[:, 0], light.frame[:, 1]
    tri_a, tri_b, tri_c, centres = [], [], [], []
    if light.kind == LightKind.RECT:
        us = np.linspace(-0.5, 0.5, CELLS + 1) * light.width
        vs = np.linspace(-0.5, 0.5, CELLS + 1) * light.height
        for i in range(CELLS):
            for j in range(CELLS):
                p = [c0 + us[i + di] * ex + vs[j + dj] * ey for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                cen = c0 + 0.5 * (us[i] + us[i + 1]) * ex + 0.5 * (vs[j] + vs[j + 1]) * ey
                tri_a += [p[0], p[0]]
                tri_b += [p[1], p[2]]
                tri_c += [p[2], p[3]]
                centres += [cen, cen]
    else:  # a disk: rings × sectors, each cell two triangles (the innermost one)
        rs = np.linspace(0.0, light.radius, CELLS + 1)
        ph = np.linspace(0.0, 2.0 * math.pi, SECTORS + 1)
        for i in range(CELLS):
            for j in range(SECTORS):
                q = lambda r, f: c0 + r * (math.cos(f) * ex + math.sin(f) * ey)  # noqa: E731
                p = [q(rs[i], ph[j]), q(rs[i + 1], ph[j]), q(rs[i + 1], ph[j + 1]), q(rs[i], ph[j + 1])]
                cen = q(0.5 * (rs[i] + rs[i + 1]), 0.5 * (ph[j] + ph[j + 1]))
                tri_a += [p[0], p[0]]
                tri_b += [p[1], p[2]]
                tri_c += [p[2], p[3]]
                centres += [cen, cen]
    return np.array(tri_a), np.array(tri_b), np.array(tri_c), np.array(centres)


def _segments_clear(eye: np.ndarray, targets: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """True where the segment from ``eye`` to each target meets no triangle (Möller–Trumbore, float64)."""
    out = np.ones(len(targets), bool)
    if len(tris) == 0:
        return out
    v0 = tris[:, 0]
    e1, e2 = tris[:, 1] - v0, tris[:, 2] - v0
    for k, t in enumerate(targets):
        d = t - eye
        dist = float(np.linalg.norm(d))
        d = d / dist
        pvec = np.cross(d, e2)
        det = np.einsum("tk,tk->t", e1, pvec)
        ok = np.abs(det) > 1e-14
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tvec = eye - v0
        u = np.einsum("tk,tk->t", tvec, pvec) * inv
        qvec = np.cross(tvec, e1)
        v = (qvec @ d) * inv
        tt = np.einsum("tk,tk->t", qvec, e2) * inv
        out[k] = not np.any(ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (tt > 1e-6) & (tt < dist * (1 - 1e-6)))
    return out


def luminaire_terms(scene, lights: list, observer: Observer) -> tuple[list[tuple[str, float, float, float]], list[str]]:
    """``(light, L per unit level (cd/m²), ω in sight (sr), P)`` of each luminaire the observer sees, and the names of
    lights left out (no size)."""
    g = scene.geometry
    tris = np.asarray(g.points, np.float64)[np.asarray(g.triangles)] if g.n_triangles else np.zeros((0, 3, 3))
    eye, view = observer.position, observer.direction
    up = _UP - float(_UP @ view) * view
    up /= np.linalg.norm(up)
    out, skipped = [], []
    for l in lights:
        c = np.asarray(l.position, np.float64)
        to_eye = eye - c
        dist = float(np.linalg.norm(to_eye))
        if dist <= 0.0:
            continue
        w = -to_eye / dist  # from the eye toward the luminaire
        if float(w @ view) <= 0.0:
            continue
        if l.kind in (LightKind.RECT, LightKind.DISK):
            if float(to_eye @ -l.frame[:, 2]) <= 0.0:  # behind its emitting side (it emits along −Z)
                continue
            a, b, cc, cen = _cells(l)
            omega = _triangle_solid_angle(eye, a, b, cc)
            clear = _segments_clear(eye, cen[::2], tris)
            om = float((omega.reshape(-1, 2).sum(axis=1) * clear).sum())
        elif l.kind == LightKind.SPHERE and l.radius > 0 and dist > l.radius:
            om = 2.0 * math.pi * (1.0 - math.sqrt(1.0 - (l.radius / dist) ** 2))
            om *= float(_segments_clear(eye, (c - l.radius * w)[None, :], tris)[0])
        else:
            skipped.append(l.name)
            continue
        if om <= 0.0:
            continue
        lum = float(l.emission[1])
        if l.shaping is not None:
            th = math.acos(max(-1.0, min(1.0, float(to_eye / dist @ -l.frame[:, 2]))))
            ph = math.atan2(float(to_eye @ l.frame[:, 1]), float(to_eye @ l.frame[:, 0]))
            lum *= float(l.shaping.factor(th, ph))
        out.append((l.name, lum, om, float(position_index(w, view, up))))
    return out, skipped


def ugr_rows(study, observers: list[Observer], scenarios, e_ind: np.ndarray, e_ind_se: np.ndarray, terms: list,
             level_of_light) -> list[UgrRow]:  # fmt: skip
    """Every observer's UGR in every scenario (module docstring).

    Parameters
    ----------
    e_ind, e_ind_se : ndarray, shape (J, O)
        Indirect illuminance at each observer (lx) per scenario and its standard error.
    terms : list
        Per observer, :func:`luminaire_terms`'s list.
    level_of_light : callable
        ``level_of_light(scenario, light name)`` → the light's level in the scenario (0 when off).
    """
    limits = {a.name: a.ugr_limit for a in study.area if a.ugr_limit is not None}
    rows = []
    for j, sc in enumerate(scenarios):
        for o, obs in enumerate(observers):
            g, seen = 0.0, 0
            for name, lum, om, p in terms[o]:
                lv = level_of_light(sc, name)
                if lv > 0:
                    g += (lv * lum) ** 2 * om / p**2
                    seen += 1
            e, se = float(e_ind[j, o]), float(e_ind_se[j, o])
            lb = e / math.pi
            u = ugr(lb, g)
            u_se = 8.0 / math.log(10.0) * se / e if (g > 0 and e > 0) else 0.0
            lim = limits[obs.area]
            if not math.isfinite(u):
                verdict = "unsure"
            else:
                margin = lim - u
                verdict = "pass" if margin > 2 * u_se else ("fail" if margin < -2 * u_se else "unsure")
            rows.append(UgrRow(obs.area, obs, sc.name, u, u_se, lb, e, se, seen, lim, verdict))
    return rows
