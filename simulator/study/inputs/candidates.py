"""Candidate sensors generated on the stage: grids on flat prims, or explicit lists.

A grid lies in the plane of each named prim, offset ``height_m`` along the
prim's front normal (a floor faces up, so 0.8 m gives the work plane; a
ceiling faces down, so 0.02 m gives points just below it), inside the prim's
bounding rectangle in that plane shrunk by the wall band, at the cell
centres of an explicit or EN 12464-1 spacing (:mod:`simulator.study.inputs.en12464`).
Points whose foot on the prim falls outside its triangles are dropped (an
L-shaped floor), and so are points inside the world-axis bounding box of any
``drop_inside`` prim (furniture; a box is conservative for rotated pieces).

Sensors face the prim's front normal: ``irradiance`` sensors have the cosine
response; ``photosensor`` candidates are radiance meters averaging the
radiance within a cone of ``half_angle_deg`` around that normal (a uniform
restricted field of view, the response of a shielded ceiling photocell).
"""

from __future__ import annotations

import fnmatch
import math
from dataclasses import dataclass, field

from pathlib import Path

import numpy as np

from simulator.config.capacity import too_many_sensors
from simulator.errors import UserError
from simulator.scene.model import Scene, Sensor, SensorKind
from simulator.study.inputs.en12464 import Grid, en12464_grid, explicit_grid
from simulator.study.schema import CandidateSpec

__all__ = ["Candidate", "CandidateSet", "build_candidates", "candidate_warnings", "match_prims"]

# flatness: unit normals within this of the mean, vertices within this distance (m) of the plane
_FLAT_COS = 0.9995
_FLAT_DIST_M = 1e-4


@dataclass
class Candidate:
    """One candidate sensor.

    Attributes
    ----------
    sensor : Sensor
        What the engine reads (name unique in the study).
    set_name : str
        The ``[[candidates]]`` it came from.
    cell : tuple of int or None
        ``(i, j)`` grid cell on its prim, None for an explicit point.
    prim : str
        Prim path it was gridded on, "" for an explicit point.
    """

    sensor: Sensor
    set_name: str
    cell: tuple[int, int] | None
    prim: str

    @property
    def position(self) -> np.ndarray:
        return self.sensor.position


@dataclass
class CandidateSet:
    """A ``[[candidates]]`` table expanded: its points and how they were laid out."""

    name: str
    kind: str
    candidates: list[Candidate]
    grids: dict[str, Grid]  #: prim path -> grid used on it
    dropped_inside: int = 0  #: points dropped inside ``drop_inside`` prims
    dropped_outside: int = 0  #: points whose foot is off the prim
    dropped_points: list = field(default_factory=list)  #: positions (ndarray (3,)) of the points dropped inside ``drop_inside`` prims


def match_prims(names: list[str], pattern: str) -> list[int]:
    """Indices of ``names`` equal to ``pattern``, below it (``pattern/...``),
    or matching it as an fnmatch pattern (``*`` also crosses ``/``)."""
    return [i for i, n in enumerate(names) if n == pattern or n.startswith(pattern.rstrip("/") + "/") or fnmatch.fnmatchcase(n, pattern)]


def _plane_axes(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """In-plane unit axes (u, v): u along world X where it can be, v turned
    toward +Y (or +Z), so cell ``[i, j]`` grows with x and y on a floor and a
    ceiling alike."""
    ref = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = ref - np.dot(ref, n) * n
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    if v[1] < -1e-12 or (abs(v[1]) <= 1e-12 and v[2] < 0):
        v = -v
    return u, v


def _inside_triangles_2d(pts: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """(N,) bool: 2-D points ``pts`` (N, 2) inside any triangle ``tris`` (T, 3, 2) (edges count)."""
    inside = np.zeros(len(pts), bool)
    for a, b, c in tris:
        d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if abs(d) < 1e-15:
            continue
        w1 = ((b[0] - pts[:, 0]) * (c[1] - pts[:, 1]) - (b[1] - pts[:, 1]) * (c[0] - pts[:, 0])) / d
        w2 = ((c[0] - pts[:, 0]) * (a[1] - pts[:, 1]) - (c[1] - pts[:, 1]) * (a[0] - pts[:, 0])) / d
        w3 = 1.0 - w1 - w2
        inside |= (w1 >= -1e-9) & (w2 >= -1e-9) & (w3 >= -1e-9)
    return inside


def _boxes(scene: Scene, patterns: list[str], label: str) -> list[tuple[np.ndarray, np.ndarray]]:
    g = scene.geometry
    out = []
    for k, pat in enumerate(patterns):
        ids = match_prims(g.prim_names, pat)
        if not ids:
            raise UserError(f"{label}.drop_inside[{k}]: no geometry prim matches {pat!r}")
        for pid in ids:
            pts = g.points[g.triangles[g.prim == pid].reshape(-1)]
            out.append((pts.min(axis=0), pts.max(axis=0)))
    return out


def _check_setting(model, spec: CandidateSpec, label: str) -> None:
    """A set's ``gain`` and ``integration_ms`` must be the part's: one line naming the key."""
    if model.electronics is None:
        if spec.gain is not None or spec.integration_ms is not None:
            key = "gain" if spec.gain is not None else "integration_ms"
            raise UserError(f"{label}.{key}: model {model.name!r} has no electronics")
        return
    model.electronics.check_setting(spec.gain, spec.integration_ms, label)


def _sensor(spec: CandidateSpec, name: str, position: np.ndarray, normal: np.ndarray, source: str,
            model=None) -> Sensor:
    if model is not None:  # a real head: its angular response in place of the cosine or the cone
        return Sensor(name=name, kind=SensorKind.IRRADIANCE, position=position, normal=normal, source=source,
                      optics=model.angular, model=model, gain=spec.gain, integration_ms=spec.integration_ms)
    if spec.kind in ("cylindrical", "semicylindrical"):  # the axis along the prim's normal (a floor: vertical)
        axis = normal / np.linalg.norm(normal)
        ref = np.asarray(spec.facing, float) if spec.facing is not None else np.array([1.0, 0.0, 0.0])
        ref = ref - float(ref @ axis) * axis
        if np.linalg.norm(ref) < 1e-6:
            if spec.facing is not None:
                raise UserError(f"{source}: facing is parallel to the cylinders' axis (the prim's normal)")
            ref = np.array([0.0, 1.0, 0.0]) - axis[1] * axis
        kind = SensorKind.CYLINDRICAL if spec.kind == "cylindrical" else SensorKind.SEMICYLINDRICAL
        return Sensor(name=name, kind=kind, position=position, normal=ref / np.linalg.norm(ref), up=axis.copy(), source=source)
    if spec.kind == "photosensor":
        return Sensor(name=name, kind=SensorKind.RADIANCE, position=position, normal=normal,
                      half_angle=math.radians(spec.half_angle_deg), source=source)  # fmt: skip
    return Sensor(name=name, kind=SensorKind.IRRADIANCE, position=position, normal=normal, source=source)


def _grid_on_prim(scene: Scene, spec: CandidateSpec, pid: int, label: str, multi: bool, model=None):
    g = scene.geometry
    prim = g.prim_names[pid]
    tri = g.points[g.triangles[g.prim == pid]]  # (T, 3, 3)
    cr = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    area2 = np.linalg.norm(cr, axis=1)
    if not (area2 > 0).any():
        raise UserError(f"{label}.on: prim {prim} has no area to put a grid on")
    n = cr.sum(axis=0)
    n_len = float(np.linalg.norm(n))
    n = n / n_len if n_len > 0 else n
    unit = cr[area2 > 0] / area2[area2 > 0, None]
    origin = tri[0, 0]
    if n_len < _FLAT_COS * area2.sum() or (unit @ n).min() < _FLAT_COS or np.abs((tri.reshape(-1, 3) - origin) @ n).max() > _FLAT_DIST_M:
        raise UserError(f"{label}.on: prim {prim} is not flat; a grid needs a planar prim (a floor, a ceiling, a desk top)")
    u, v = _plane_axes(n)
    uv = np.stack([(tri.reshape(-1, 3) - origin) @ u, (tri.reshape(-1, 3) - origin) @ v], axis=1)
    lo, hi = uv.min(axis=0) + spec.wall_band_m, uv.max(axis=0) - spec.wall_band_m
    size = hi - lo
    if (size <= 1e-9).any():
        raise UserError(f"{label}.wall_band_m: a {spec.wall_band_m:g} m band leaves nothing of prim {prim}")
    try:
        grid = en12464_grid(*size) if spec.spacing_m == "en12464" else explicit_grid(size[0], size[1], float(spec.spacing_m))
    except ValueError as exc:
        raise UserError(f"{label}.spacing_m: {exc} (prim {prim})") from None
    why = too_many_sensors(grid.n_u * grid.n_v)  # before a cell is built: billions would fill the memory first
    if why is not None:
        raise UserError(f"{label}.spacing_m: {grid.n_u:,} x {grid.n_v:,} cells on prim {prim}: {why}; use a coarser spacing")
    cells = [(i, j) for j in range(grid.n_v) for i in range(grid.n_u)]
    c2 = np.array([[lo[0] + (i + 0.5) * grid.pitch_u_m, lo[1] + (j + 0.5) * grid.pitch_v_m] for i, j in cells])
    on_prim = _inside_triangles_2d(c2, uv.reshape(-1, 3, 2))
    pos = origin + c2[:, :1] * u + c2[:, 1:] * v + spec.height_m * n
    leaf = prim.rsplit("/", 1)[-1]
    stem = f"{spec.name}/{leaf}" if multi else spec.name
    out = [
        Candidate(_sensor(spec, f"{stem}[{i},{j}]", pos[k], n.copy(), f"{label} on {prim}", model), spec.name, (i, j), prim)
        for k, (i, j) in enumerate(cells) if on_prim[k]
    ]  # fmt: skip
    return out, grid, int((~on_prim).sum())


def build_candidates(scene: Scene, specs: list[CandidateSpec], file_label: str) -> list[CandidateSet]:
    """Expand every ``[[candidates]]`` table on the scene.

    Raises
    ------
    UserError
        A prim pattern that matches no geometry, a prim that is not flat, a
        wall band wider than the prim, a set left with no points, or a sensor
        name used twice.
    """
    sets: list[CandidateSet] = []
    seen: set[str] = set()
    for k, spec in enumerate(specs):
        label = f"{file_label}: candidates[{k}]"
        boxes = _boxes(scene, spec.drop_inside, label)
        model = None
        if spec.model is not None:  # a bundled name or a .toml beside the study file
            from simulator.sensor_models.model import load_model

            model = load_model(spec.model, Path(file_label).parent, f"{label}.model")
            _check_setting(model, spec, label)
        cands: list[Candidate] = []
        grids: dict[str, Grid] = {}
        outside = 0
        if spec.on is not None:
            pids: list[int] = []
            for j, pat in enumerate(spec.on):
                ids = match_prims(scene.geometry.prim_names, pat)
                if not ids:
                    raise UserError(f"{label}.on[{j}]: no geometry prim matches {pat!r}")
                pids += [i for i in ids if i not in pids]
            for pid in pids:
                c, grid, off = _grid_on_prim(scene, spec, pid, label, len(pids) > 1, model)
                cands += c
                grids[scene.geometry.prim_names[pid]] = grid
                outside += off
        else:
            nrm = np.asarray(spec.normal, float)
            nrm /= np.linalg.norm(nrm)
            for j, p in enumerate(spec.points):
                cands.append(Candidate(_sensor(spec, f"{spec.name}[{j}]", np.asarray(p, float), nrm.copy(), f"{label}.points[{j}]",
                                               model),
                                       spec.name, None, ""))  # fmt: skip
        keep = [c for c in cands if not any(np.all(c.position >= lo - 1e-9) and np.all(c.position <= hi + 1e-9) for lo, hi in boxes)]
        if not keep:
            raise UserError(f"{label}: no candidate points are left (after the wall band and drop_inside)")
        for c in keep:
            if c.sensor.name in seen:
                raise UserError(f"{label}: sensor name {c.sensor.name!r} is used twice")
            seen.add(c.sensor.name)
        kept = {id(c) for c in keep}
        dropped = [c.position.copy() for c in cands if id(c) not in kept]
        sets.append(CandidateSet(spec.name, spec.kind, keep, grids, len(cands) - len(keep), outside, dropped))
    return sets


def candidate_warnings(scene: Scene, specs: list[CandidateSpec], sets: list[CandidateSet], file_label: str) -> list[str]:
    """Where the candidates stand: a grid whose plane lies outside the stage (``height_m`` puts a work
    plane above the ceiling, or a typed-in value is not in metres), then the checks of
    :func:`simulator.scene.sanity.sensor_warnings` on every other candidate.

    Raises
    ------
    UserError
        A grid whose every point lies more than :data:`simulator.scene.sanity.FAR_REL` of the stage's
        diagonals outside the stage's box: it is near nothing of the stage.
    """
    from simulator.scene.sanity import FAR_REL, box_text, outside_gap, sensor_warnings, stage_box

    box = stage_box(scene)
    diag = float(np.linalg.norm(box[1] - box[0]))
    out, rest = [], []
    for k, (spec, cs) in enumerate(zip(specs, sets)):
        pts = np.array([c.position for c in cs.candidates], np.float64).reshape(-1, 3)
        gap = outside_gap(pts, box)
        if spec.on is None or not np.all(gap > 0):
            rest += [c.sensor for c in cs.candidates]
            continue
        prims = ", ".join(list(cs.grids)[:2]) + (" ..." if len(cs.grids) > 2 else "")
        msg = (f"{file_label}: candidates[{k}].height_m: {spec.height_m:g} m from {prims} puts the {spec.name!r} grid "
               f"outside the stage ({box_text(box)}) by {float(gap.min()):.3g} m")
        if float(gap.min()) > FAR_REL * diag:
            raise UserError(msg + ", near nothing of it (height_m is in metres)")
        out.append(msg + ": a work plane above the ceiling or below the floor reads the open sky or 0")
    return out + sensor_warnings(scene, rest)
