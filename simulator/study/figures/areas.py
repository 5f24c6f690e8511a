"""EN 12464-1 areas of a study: task, immediate surrounding and background; walls, ceiling; cylindrical illuminance.

An ``[[area]]`` reads the readings of one candidate set (a work-plane grid,
a grid on the walls or the ceiling, a grid of cylindrical receivers) and
judges the maintained figures against the standard's requirements, each
figure with its standard error and a verdict as the zone targets have one
(``pass`` when met by more than 2 standard errors, ``fail`` when missed by
more than 2, else ``unsure``).

Notes
-----
Maintained illuminance: Ē_m = MF·Ē and E_min,m = MF·E_min (the maintenance
factor ``maintenance_factor``, 1 for a new installation); U0 = E_min/Ē does
not change with it. Figures and their errors are those of
:func:`simulator.study.figures.objectives.zone_figures` on MF × the readings.

Task areas (``kind = "task"``, ``task = [x0, y0, x1, y1]``): the points
inside the rectangle; the *immediate surrounding*, the points outside it
within ``surround_m`` (≥ 0.5 m) of it (Chebyshev distance, a band of that
width around a rectangle); the *background*, those farther than that and
within ``surround_m + background_m`` (a band ≥ 3 m wide), all within the
candidate set (the space). Requirements: the task's own ``required_lx`` and
``u0`` (the standard's table for the task); the surrounding, Ē from the
task's by :func:`surround_required_lx` and U0 ≥ 0.40; the background,
Ē ≥ 1/3 of the surrounding's required Ē and U0 ≥ 0.10.

Walls and ceiling (``kind = "walls"`` / ``"ceiling"``): Ē_m ≥ 50 / 30 lx
(75 / 50 lx with ``space = "office"``: offices, education, health care),
U0 ≥ 0.10. Cylindrical (``kind = "cylindrical"``, a set of cylindrical
receivers): Ē_z ≥ 50 lx (or ``required_lx``), U0 ≥ 0.10, and with
``horizontal`` (a horizontal set) the modelling ratio Ē_z/Ē_h of the two
sets' means over the area, judged against 0.30–0.60, its error by the
delta method, σ_r² = r²·((σ_z/Ē_z)² + (σ_h/Ē_h)²) (the sets are traced on
independent streams).

In radiometric studies the same figures apply to W/m² (the lux
requirements then read as W/m² and are rarely meaningful).

References
----------
docs/REFERENCES.md §EN 12464-1 areas, §Cylindrical illuminance.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from simulator.errors import UserError
from simulator.study.figures.objectives import ZoneFigures, compliance, zone_figures

__all__ = ["AreaRow", "surround_required_lx", "area_members", "area_rows", "SURROUND_U0", "BACKGROUND_U0", "AREA_COLUMNS"]

#: the immediate surrounding's and the background's required uniformity
SURROUND_U0 = 0.40
BACKGROUND_U0 = 0.10
#: walls, ceiling, cylindrical: required uniformity
SURFACE_U0 = 0.10
#: walls and ceiling required Ē_m (lx): general, and offices/education/health care
WALL_LX = {"general": 50.0, "office": 75.0}
CEILING_LX = {"general": 30.0, "office": 50.0}
#: cylindrical illuminance required where visual communication matters (lx)
CYLINDRICAL_LX = 50.0
#: the modelling ratio Ē_z/Ē_h's range of good modelling
MODELLING_RANGE = (0.30, 0.60)


def surround_required_lx(task_lx: float) -> float:
    """The immediate surrounding's required Ē from the task's: ≥ 750 → 500, ≥ 500 → 300, ≥ 300 → 200, else the task's."""
    for lo, surround in ((750.0, 500.0), (500.0, 300.0), (300.0, 200.0)):
        if task_lx >= lo:
            return surround
    return float(task_lx)


@dataclass(frozen=True)
class AreaRow:
    """One part of one area in one scenario."""

    area: str
    part: str  #: task | surround | background | walls | ceiling | cylindrical
    scenario: str
    sensors: int
    figures: ZoneFigures | None  #: maintained figures, None where the part holds no point
    required_mean: float
    required_u0: float
    verdicts: dict  #: {"mean": ..., "u0": ...}, "" where no point
    modelling: tuple[float, float] | None = None  #: Ē_z/Ē_h and its standard error
    modelling_verdict: str = ""


AREA_COLUMNS = ("area", "part", "scenario", "sensors", "unit", "maintenance_factor", "mean", "mean_stderr", "min", "min_stderr",
                "u0", "u0_stderr", "required_mean", "required_u0", "mean_verdict", "u0_verdict", "modelling_ratio",
                "modelling_ratio_stderr", "modelling_verdict")  # fmt: skip


def _chebyshev(xy: np.ndarray, rect) -> np.ndarray:
    """Distance (m) from points to a rectangle in the max norm (0 inside)."""
    dx = np.maximum(np.maximum(rect[0] - xy[:, 0], xy[:, 0] - rect[2]), 0.0)
    dy = np.maximum(np.maximum(rect[1] - xy[:, 1], xy[:, 1] - rect[3]), 0.0)
    return np.maximum(dx, dy)


def area_members(area, ids: np.ndarray, xy: np.ndarray) -> dict[str, np.ndarray]:
    """Candidate indices of each part of ``area``; ``ids`` (N,) the set's indices, ``xy`` (N, 2) their positions."""
    if area.kind != "task":
        if area.region is None:
            return {area.kind: ids}
        r = area.region
        inside = (xy[:, 0] >= r[0]) & (xy[:, 0] <= r[2]) & (xy[:, 1] >= r[1]) & (xy[:, 1] <= r[3])
        return {area.kind: ids[inside]}
    d = _chebyshev(xy, area.task)
    eps = 1e-9
    return {"task": ids[d <= eps], "surround": ids[(d > eps) & (d <= area.surround_m + eps)],
            "background": ids[(d > area.surround_m + eps) & (d <= area.surround_m + area.background_m + eps)]}  # fmt: skip


def _requirements(area) -> dict[str, tuple[float, float]]:
    if area.kind == "task":
        s = surround_required_lx(area.required_lx)
        return {"task": (area.required_lx, area.u0), "surround": (s, SURROUND_U0), "background": (s / 3.0, BACKGROUND_U0)}
    default = {"walls": WALL_LX[area.space], "ceiling": CEILING_LX[area.space], "cylindrical": CYLINDRICAL_LX}[area.kind]
    return {area.kind: (area.required_lx or default, area.u0 or SURFACE_U0)}


def _ratio_verdict(r: float, se: float) -> str:
    lo, hi = MODELLING_RANGE
    margin = min(r - lo, hi - r)
    return "pass" if margin > 2 * se else ("fail" if margin < -2 * se else "unsure")


def area_rows(study, sets, candidates, scenarios, mean: np.ndarray, stderr: np.ndarray, label: str) -> list[AreaRow]:
    """Every area's parts in every scenario (see Notes of the module).

    Raises
    ------
    UserError
        A task area with no candidate point inside it, a cylindrical area on a set that is not cylindrical,
        a set that is, for a horizontal area, or a ``horizontal`` set that does not cover the area.
    """
    ch = 1 if study.light_units == "photometric" else 0
    index = {c.sensor.name: i for i, c in enumerate(candidates)}
    rows: list[AreaRow] = []
    for k, a in enumerate(study.area):
        key = f"{label}: area[{k}]"
        cs = next(s for s in sets if s.name == a.candidates)
        ids = np.array([index[c.sensor.name] for c in cs.candidates])
        xy = np.array([c.position[:2] for c in cs.candidates])
        cyl = cs.kind in ("cylindrical", "semicylindrical")
        if (a.kind == "cylindrical") != cyl:
            raise UserError(f"{key}.candidates: a {a.kind} area needs a {'cylindrical' if a.kind == 'cylindrical' else 'plane (irradiance)'} "
                            f"set; {a.candidates!r} is {cs.kind}")  # fmt: skip
        parts = area_members(a, ids, xy)
        if not len(next(iter(parts.values()))):
            raise UserError(f"{key}: no {a.candidates!r} candidate lies inside its {'task' if a.kind == 'task' else 'region'}")
        hz = None
        if a.horizontal is not None:
            hs = next(s for s in sets if s.name == a.horizontal)
            if hs.kind != "irradiance":
                raise UserError(f"{key}.horizontal: {a.horizontal!r} is a {hs.kind} set, not irradiance")
            hids = np.array([index[c.sensor.name] for c in hs.candidates])
            hxy = np.array([c.position[:2] for c in hs.candidates])
            hz = next(iter(area_members(a, hids, hxy).values()))
            if not len(hz):
                raise UserError(f"{key}.horizontal: no {a.horizontal!r} candidate lies inside the area")
        req = _requirements(a)
        mf = a.maintenance_factor
        for j, sc in enumerate(scenarios):
            for part, members in parts.items():
                rm, ru = req[part]
                if not len(members):
                    rows.append(AreaRow(a.name, part, sc.name, 0, None, rm, ru, {"mean": "", "u0": ""}))
                    continue
                f = zone_figures(mf * mean[j, members, ch], mf * stderr[j, members, ch])
                verdicts = compliance(f, {"mean": rm, "u0": ru})
                model = None
                mv = ""
                if hz is not None:
                    ez, ez_se = f.mean, f.mean_se
                    hm = float(np.mean(mf * mean[j, hz, ch]))
                    hse = float(np.sqrt(np.sum((mf * stderr[j, hz, ch]) ** 2)) / len(hz))
                    if hm > 0 and ez > 0:
                        r = ez / hm
                        rse = r * float(np.hypot(ez_se / ez, hse / hm))
                        model, mv = (r, rse), _ratio_verdict(r, rse)
                rows.append(AreaRow(a.name, part, sc.name, len(members), f, rm, ru, verdicts, model, mv))
    return rows
