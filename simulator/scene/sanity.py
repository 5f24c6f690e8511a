"""Where each sensor stands on the stage: the misplaced sensors that would read a plausible wrong number.

A sensor typed in millimetres on a metres stage, one outside the room, one
inside a table slab or one facing the floor it sits on is traced like any
other and gives a number with a small standard error: open sky, 0, or the
underside of the floor. :func:`sensor_warnings` names such sensors before
tracing, one warning line per kind of problem. Pure numpy on the scene's
triangles (no device, no sampling: the same stage and sensors give the
same lines), in milliseconds for the bundled stages.

The checks
----------
Wrong unit
    A sensor more than :data:`FAR_REL` stage diagonals outside the stage's
    box (geometry and the lights that have a place) whose position divided
    by 1000, by 100 or times 0.0254 lies inside it: the position looks like
    millimetres, centimetres or inches where a config's positions are metres
    (whatever the stage's ``metersPerUnit``: the reader scales the stage,
    not the config). Where several would, the one whose point lies nearest
    the box's centre is named first. Nothing else is said of that sensor.
Outside the stage
    A sensor outside that box, grown by :data:`BOX_MARGIN_REL` of its
    diagonal (a sensor on a face of the stage is inside it): nothing of the
    stage is around it (it reads the open sky, the sun, or 0). Named when it
    is far away (:data:`FAR_REL`), or when the box is a room (no side under
    :data:`ROOMY_REL` of the longest) that some other sensor stands in; an
    occluder floating over its sensors (the verify stages) is not a room.
Outside every lit room
    The stage's closed shells (connected components of the welded
    triangles whose every edge is shared by an even number of them,
    :func:`simulator.scene.enclosures.closed_shells`) that are opaque
    (every face matte: no pane, cut-out or modelled surface) and hold a
    light inside them (the parity rule on the light's centre). A sensor
    outside every one of them sees none of their lights' light.
Inside a dark solid
    An opaque closed shell with no light and no emitting face inside it
    passes no light in: a sensor inside it (a table slab, a wall) reads
    exactly 0.
Facing the surface it sits on
    An irradiance or patch sensor whose ray along its normal meets a face
    within :func:`mount_distance_m` (2 mm) sits just behind that face, or
    points into the surface it is mounted on; one lying on an open face (in
    no closed shell) whose front looks away from its normal sits on the
    face's back. The face's prim is named.

Points on the sensor's own side are tested at ``p + delta * n`` (``delta``
a hair, :data:`_NUDGE_REL`), where a sensor's first rays start: a sensor
exactly on a slab's top facing down is inside the slab. Stages with more
than :data:`MAX_TRIANGLES` triangles skip the shell checks, and each check
skips what would cost more than :data:`MAX_PAIRS` ray-triangle tests.
"""

from __future__ import annotations

import weakref

import numpy as np

from simulator.scene.model import LightKind, Scene, Sensor, SensorKind

__all__ = ["sensor_warnings", "stage_box", "outside_gap", "box_text", "mount_distance_m", "FAR_REL", "BOX_MARGIN_REL", "ROOMY_REL",
           "MOUNT_M", "MAX_TRIANGLES", "MAX_PAIRS", "UNIT_GUESSES"]

#: the stage's box is grown by this fraction of its diagonal before a sensor counts as outside it
BOX_MARGIN_REL = 0.01
#: a sensor this many of the box's diagonals outside it is far away (alone outside the box, it is named only then)
FAR_REL = 2.0
#: a box whose shortest side is at least this fraction of its longest is a room (a volume sensors stand in)
ROOMY_REL = 0.1
#: a face this near (m) straight ahead of a sensor is one it sits just behind (smaller stages: see mount_distance_m)
MOUNT_M = 0.002
#: the shell checks are skipped on stages with more triangles than this
MAX_TRIANGLES = 500_000
#: most ray-triangle tests one check makes (beyond that it is skipped)
MAX_PAIRS = 40_000_000
#: the units a position outside the stage may have been typed in: (name, metres per unit)
UNIT_GUESSES = (("millimetres", 1e-3), ("centimetres", 1e-2), ("inches", 0.0254))
#: how far off its own side a sensor's position is nudged for the parity tests, relative to max(1 m, |p|)
_NUDGE_REL = 1e-5
#: the parity rays' direction: +X tilted by generic small angles, so that it grazes no edge of a box or a
#: quad's diagonal, and the triangles it may cross lie in a thin column (found from their boxes)
_RAY = np.array([1.0, 0.7071e-3, 0.5773e-3]) / np.linalg.norm([1.0, 0.7071e-3, 0.5773e-3])
#: shells of at most this many triangles are tested whole against every point (no column filter)
_SMALL_SHELL = 4096
#: pairs of (sensor, triangle) per numpy block
_BLOCK = 1 << 20
#: names listed in one warning line
_NAMED = 3

_SHELLS: dict[int, tuple] = {}  # id(geometry) -> (weakref to it, its _Topology)


def sensor_warnings(scene: Scene, sensors: list[Sensor]) -> list[str]:
    """One warning line per kind of misplacement found among ``sensors`` (empty when none is).

    Parameters
    ----------
    scene : Scene
        The stage as read (world metres).
    sensors : list of Sensor
        Every sensor of the run (config, grid and stage-authored).

    Returns
    -------
    list of str
        Lines naming the sensors (up to three, then a count) and what is
        wrong, in the order of the module docstring's checks.
    """
    if not sensors or scene.geometry.n_triangles == 0:
        return []
    pos = np.array([s.position for s in sensors], np.float64).reshape(-1, 3)
    top = _topology(scene.geometry)
    box = stage_box(scene)
    gap = outside_gap(pos, box)
    diag = float(np.linalg.norm(box[1] - box[0]))
    far = gap > FAR_REL * diag
    units = [_unit_of(p, box) if f else None for p, f in zip(pos, far)]
    out = _unit_lines(sensors, pos, box, units)
    # a sensor outside the box is odd where it stands far away, or where the box is a room (no side under
    # ROOMY_REL of the longest: not an occluder floating over its sensors) that other sensors stand in
    side = box[1] - box[0]
    roomy = float(side.min()) >= ROOMY_REL * float(side.max()) and bool(np.any(gap <= 0))
    odd = (gap > 0) & np.array([u is None for u in units]) & (far | roomy)
    if odd.any():
        out.append(f"{_names(sensors, np.flatnonzero(odd))} outside the stage's bounds ({box_text(box)}) by up to "
                   f"{float(gap[odd].max()):.3g} m: nothing of the stage is around {_them(np.flatnonzero(odd))} "
                   "(the open sky, the sun or 0 is read)")
    rest = [i for i, u in enumerate(units) if u is None]  # a wrong unit is the one thing said of a sensor
    sensors, pos = [sensors[i] for i in rest], pos[rest]
    origin = _nudged(sensors, pos)
    if top.shells is not None and sensors:
        out += _shell_lines(scene, top, sensors, origin)
    if sensors:
        out += _facing_lines(scene, top, sensors, pos, origin, box)
    return out


def stage_box(scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned box (metres) around the stage's triangles and the lights that have a place
    (not distant or dome lights), not grown."""
    pts = [np.stack(_topology(scene.geometry).box)]
    pts += [l.position[None, :] for l in scene.lights if l.kind not in (LightKind.DOME, LightKind.DISTANT)]
    allp = np.concatenate(pts)
    return allp.min(axis=0), allp.max(axis=0)


def outside_gap(pos: np.ndarray, box: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """How far (m) each point (N, 3) lies outside ``box`` grown by :data:`BOX_MARGIN_REL` of its
    diagonal, along the axis it is farthest out on; zero or negative inside."""
    lo, hi = _grown(box)
    return np.max(np.maximum(lo - pos, pos - hi), axis=1)


def mount_distance_m(box: tuple[np.ndarray, np.ndarray]) -> float:
    """How near (m) a face straight ahead of a sensor counts as one it sits just behind: 2 mm, or a
    five-hundredth of the stage's diagonal on a stage smaller than 1 m."""
    return float(min(MOUNT_M, 0.002 * np.linalg.norm(box[1] - box[0])))


class _Topology:
    """What the checks need of a geometry, computed once per geometry object: triangle corners and
    boxes, and the closed shells (None above :data:`MAX_TRIANGLES`) with their boxes."""

    def __init__(self, g):
        self.tris = np.asarray(g.points, np.float64)[np.asarray(g.triangles)]  # (T, 3, 3)
        self.lo, self.hi = self.tris.min(axis=1), self.tris.max(axis=1)
        self.shells = None
        if g.n_triangles <= MAX_TRIANGLES:
            from simulator.scene.enclosures import closed_shells

            self.shells = closed_shells(g.points, g.triangles)
        self.in_shell = np.zeros(g.n_triangles, bool)
        for ids in self.shells or []:
            self.in_shell[ids] = True
        self.box = (self.lo.min(axis=0), self.hi.max(axis=0)) if len(self.tris) else (np.zeros(3), np.zeros(3))
        # triangles sorted by their lowest x, the wide ones (over 1% of the stage's x extent) apart: the ones
        # whose box reaches a point are a contiguous run of the narrow ones, plus some of the wide ones
        wide = (self.hi[:, 0] - self.lo[:, 0]) > 0.01 * float(self.box[1][0] - self.box[0][0])
        self.wide = np.flatnonzero(wide)
        narrow = np.flatnonzero(~wide)
        self.narrow = narrow[np.argsort(self.lo[narrow, 0], kind="stable")]
        self.narrow_lo_x = self.lo[self.narrow, 0]
        self.narrow_ext_x = float((self.hi[narrow, 0] - self.lo[narrow, 0]).max()) if len(narrow) else 0.0

    def near(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """Indices of the triangles whose box overlaps the box ``[lo, hi]``, shape (3,) each (m)."""
        a, b = np.searchsorted(self.narrow_lo_x, [lo[0] - self.narrow_ext_x, hi[0]], side="left")
        ids = np.concatenate([self.narrow[a:b], self.wide])
        keep = np.all((self.hi[ids] >= lo) & (self.lo[ids] <= hi), axis=1)
        return ids[keep]


def _topology(g) -> _Topology:
    kept = _SHELLS.get(id(g))
    if kept is not None and kept[0]() is g:
        return kept[1]
    for k in [k for k, v in _SHELLS.items() if v[0]() is None]:
        del _SHELLS[k]
    top = _Topology(g)
    _SHELLS[id(g)] = (weakref.ref(g), top)
    return top


def _grown(box):
    lo, hi = box
    m = BOX_MARGIN_REL * float(np.linalg.norm(hi - lo)) + 1e-9 * max(1.0, float(np.max(np.abs([lo, hi]))))
    return lo - m, hi + m


def _unit_of(p: np.ndarray, box) -> tuple[str, float, tuple[str, ...]] | None:
    """The unit of :data:`UNIT_GUESSES` in which ``p`` (far outside the box) would lie inside it, nearest the
    box's centre (in units of its sides) where several would, and the others that would too."""
    lo, hi = _grown(box)
    centre, half = (box[0] + box[1]) / 2, np.maximum((box[1] - box[0]) / 2, 1e-9)
    fits = []
    for name, f in UNIT_GUESSES:
        q = p * f
        if np.all(q >= lo) and np.all(q <= hi):
            fits.append((float(np.max(np.abs(q - centre) / half)), name, f))
    if not fits:
        return None
    fits.sort()
    return fits[0][1], fits[0][2], tuple(n for _, n, _ in fits[1:])


def _unit_lines(sensors, pos, box, units) -> list[str]:
    by_unit: dict[tuple, list[int]] = {}
    for i, u in enumerate(units):
        if u is not None:
            by_unit.setdefault(u, []).append(i)
    out = []
    for (name, f, also), ids in by_unit.items():
        p = pos[ids[0]]
        alt = f" (or {' or '.join(also)})" if also else ""
        out.append(f"{_names(sensors, ids)} far outside the stage ({box_text(box)}): a position such as {_vec(p)} looks like "
                   f"{name}{alt} ({_vec(p * f)} m lies inside the stage); positions in a config are metres")
    return out


def _shell_lines(scene: Scene, top: _Topology, sensors, origin) -> list[str]:
    """Sensors inside an opaque closed shell that holds no light, and those outside every lit one."""
    g = scene.geometry
    if not top.shells:
        return []
    lights = [(l.name, _light_centre(l)) for l in scene.lights if l.kind not in (LightKind.DOME, LightKind.DISTANT)]
    lp = np.array([p for _, p in lights], np.float64).reshape(-1, 3)
    emit = np.flatnonzero(np.any(g.emission > 0, axis=1))
    glow = _nudged_faces(top, emit[:256]) if len(emit) else np.zeros((0, 3))
    matte = np.ones(g.n_triangles, bool) if g.surface_id is None else np.asarray(g.surface_id) < 0
    dark: dict[int, list[int]] = {}  # shell number -> sensors inside it
    lit_shells, in_lit = [], np.zeros(len(sensors), bool)
    for k, ids in enumerate(top.shells):
        if not np.all(matte[ids]):
            continue  # a pane or a cut-out lets light through: not a wall to reason about
        lo, hi = top.lo[ids].min(axis=0), top.hi[ids].max(axis=0)
        in_l, in_g, in_s = (_in_shell(x, lo, hi, top, ids) for x in (lp, glow, origin))
        if in_l is None or in_g is None:
            continue  # too large to test: no claim either way
        held = [lights[j][0] for j in np.flatnonzero(in_l)]
        glows = bool(np.any(in_g))
        emits_itself = bool(np.any(g.emission[ids] > 0))
        if in_s is None:  # its sensors not tested: none is said to be inside it, nor outside it
            in_lit[np.all((origin >= lo) & (origin <= hi), axis=1)] = True
            continue
        ins = np.flatnonzero(in_s)
        if held or glows or emits_itself:
            if held:
                lit_shells.append((k, held))
            in_lit[ins] = True
        elif len(ins):
            dark[k] = [int(i) for i in ins]
    out = []
    for k, ids in dark.items():
        out.append(f"{_names(sensors, ids)} inside the closed surface of {_prims_of(g, top.shells[k])}, which holds no light: "
                   f"no light reaches {_them(ids)} (0 is read)")
    away = np.flatnonzero(~in_lit)
    if lit_shells and len(away):
        held = sorted({n for _, names in lit_shells for n in names})
        rooms = ", ".join(_prims_of(g, top.shells[k]) for k, _ in lit_shells[:2]) + (" ..." if len(lit_shells) > 2 else "")
        out.append(f"{_names(sensors, away)} outside every closed room that holds a light ({rooms}, holding "
                   f"{', '.join(held[:_NAMED])}{' ...' if len(held) > _NAMED else ''}): none of their light reaches {_them(away)}")
    return out


def _in_shell(pts: np.ndarray, lo, hi, top: _Topology, ids: np.ndarray) -> np.ndarray | None:
    """(N,) bool: each point lies inside the closed shell of triangles ``ids`` (the parity of a ray along
    :data:`_RAY`). A small shell is tested whole against every point in its box; on a large one each
    point tests only the triangles whose boxes its ray's thin column meets. A shell whose test would
    exceed :data:`MAX_PAIRS` ray-triangle pairs is not tested: None."""
    out = np.zeros(len(pts), bool)
    box_in = np.flatnonzero(np.all((pts >= lo) & (pts <= hi), axis=1))
    if len(box_in) * len(ids) > MAX_PAIRS:
        return None
    if len(box_in) == 0:
        return out
    if len(ids) <= _SMALL_SHELL:
        tris = top.tris[ids]
        for a, b in _blocks(len(box_in), len(tris)):
            t = _ray_t(pts[box_in[a:b]], np.broadcast_to(_RAY, (b - a, 3)), tris)
            out[box_in[a:b]] = np.count_nonzero(t > 0, axis=1) % 2 == 1
        return out
    t_lo, t_hi = top.lo[ids], top.hi[ids]
    drift = float(hi[0] - lo[0]) * float(np.max(np.abs(_RAY[1:]))) / _RAY[0] + 1e-9  # the ray's y, z change across the shell
    for i in box_in:
        p = pts[i]
        near = np.flatnonzero((t_hi[:, 0] >= p[0]) & (t_lo[:, 1] <= p[1] + drift) & (t_hi[:, 1] >= p[1] - drift)
                              & (t_lo[:, 2] <= p[2] + drift) & (t_hi[:, 2] >= p[2] - drift))
        t = _ray_t(p[None], _RAY[None], top.tris[ids[near]])
        out[i] = np.count_nonzero(t > 0) % 2 == 1
    return out


def _facing_lines(scene: Scene, top: _Topology, sensors, pos, origin, box) -> list[str]:  # noqa: C901
    """Irradiance and patch sensors that sit just behind a face straight ahead, or on an open face's back."""
    g = scene.geometry
    reach = mount_distance_m(box)
    ids = np.array([i for i, s in enumerate(sensors) if s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH)], int)
    if len(ids) == 0:
        return []
    n = np.array([sensors[i].normal for i in ids], np.float64)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    hair = _NUDGE_REL * np.maximum(1.0, np.max(np.abs(pos[ids]), axis=1))[:, None]
    behind: dict[int, list[tuple[int, float]]] = {}  # prim index -> (sensor, distance)
    on_back: dict[int, list[int]] = {}  # prim index -> sensors lying on that open face, facing its back
    budget = MAX_PAIRS
    step = 64 if len(top.tris) <= 20_000 else 1  # many triangles: each sensor finds its own few
    for start in range(0, len(ids), step):
        blk = slice(start, start + step)
        p, d, o = pos[ids[blk]], n[blk], origin[ids[blk]]
        near = top.near(p.min(axis=0) - reach, p.max(axis=0) + reach)
        budget -= 2 * len(p) * len(near)
        if len(near) == 0 or budget < 0:
            continue
        tris = top.tris[near]
        t, face = _first_hits(o, d, tris, reach)  # ahead of where its rays start
        for j in np.flatnonzero(face >= 0):
            behind.setdefault(int(g.prim[near[face[j]]]), []).append((int(ids[start + j]), float(t[j])))
        # on a face: a short segment through p along the normal meets it; an open face whose front looks
        # away from the sensor's normal is sat on from behind
        t2, face2 = _first_hits(p + hair[blk] * d, -d, tris, 2.0 * float(hair[blk].max()))
        for j in np.flatnonzero((face2 >= 0) & (face < 0)):
            f = near[face2[j]]
            if top.in_shell[f]:
                continue  # a closed shell's faces: its inside is told by parity, not by which way they face
            ng = np.cross(top.tris[f, 1] - top.tris[f, 0], top.tris[f, 2] - top.tris[f, 0])
            if float(ng @ d[j]) < 0.0:
                on_back.setdefault(int(g.prim[f]), []).append(int(ids[start + j]))
    out = []
    for prim, hits in behind.items():
        mm = min(t for _, t in hits) * 1e3
        out.append(f"{_names(sensors, [i for i, _ in hits], ('faces', 'face'))} {g.prim_names[prim]} {mm:.3g} mm ahead "
                   "along its normal: it sits just behind that face, or points into the surface it is mounted on "
                   "(flip the normal or move it to the lit side)")
    for prim, ids_ in on_back.items():
        out.append(f"{_names(sensors, ids_, ('sits', 'sit'))} on {g.prim_names[prim]} facing its back (the normal points "
                   "into the surface it is mounted on; it reads what lies behind the face): flip the normal if the "
                   "front is the side meant")
    return out


def _nudged(sensors, pos: np.ndarray) -> np.ndarray:
    """Where each sensor's first rays start: a hair along its normal (kinds that face one side, as the
    kernels push a sensor's rays), else its position."""
    sided = np.array([s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH, SensorKind.RADIANCE) for s in sensors])
    n = np.array([s.normal for s in sensors], np.float64).reshape(-1, 3)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    hair = _NUDGE_REL * np.maximum(1.0, np.max(np.abs(pos), axis=1, keepdims=True))
    return pos + np.where(sided[:, None], hair * n, 0.0)


def _light_centre(light) -> np.ndarray:
    """A light's centre, a hair toward where it emits for one-sided lights (a RectLight flush with a ceiling)."""
    p = np.asarray(light.position, np.float64)
    if light.kind in (LightKind.RECT, LightKind.DISK):
        p = p - _NUDGE_REL * max(1.0, float(np.max(np.abs(p)))) * np.asarray(light.frame, np.float64)[:, 2]
    return p


def _nudged_faces(top: _Topology, faces: np.ndarray) -> np.ndarray:
    """Centroids of emitting faces, a hair off their front (where they emit)."""
    tri = top.tris[faces]
    c = tri.mean(axis=1)
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    return c + _NUDGE_REL * np.maximum(1.0, np.max(np.abs(c), axis=1, keepdims=True)) * n


def _first_hits(o: np.ndarray, d: np.ndarray, tris: np.ndarray, t_max: float) -> tuple[np.ndarray, np.ndarray]:
    """Distance (m) and triangle (index into ``tris``, -1: none) of each ray's first hit within ``t_max``.

    A face whose plane holds the origin is not met (as the kernels' rays skip it): a sensor exactly on
    a face sees past it, to the side its normal faces."""
    t_first = np.full(len(o), np.inf)
    face = np.full(len(o), -1, np.int64)
    for a, b in _blocks(len(o), len(tris)):
        t = _ray_t(o[a:b], d[a:b], tris)
        t = np.where((t > 0) & (t <= t_max), t, np.inf)
        k = np.argmin(t, axis=1)
        tk = t[np.arange(b - a), k]
        hit = np.isfinite(tk)
        t_first[a:b] = np.where(hit, tk, np.inf)
        face[a:b] = np.where(hit, k, -1)
    return t_first, face


def _ray_t(o: np.ndarray, d: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Möller–Trumbore for every (ray, triangle): the hit distance, shape (R, T); 0 where there is no hit.

    A hit nearer than 1e-9 of max(1 m, |o|) is none (the origin's own face)."""
    v0 = tris[:, 0]
    e1, e2 = tris[:, 1] - v0, tris[:, 2] - v0
    h = np.cross(d[:, None, :], e2[None])  # (R, T, 3)
    det = np.einsum("tk,rtk->rt", e1, h)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = o[:, None, :] - v0[None]
    u = inv * np.einsum("rtk,rtk->rt", s, h)
    q = np.cross(s, e1[None])
    v = inv * np.einsum("rk,rtk->rt", d, q)
    t = inv * np.einsum("tk,rtk->rt", e2, q)
    t_min = 1e-9 * np.maximum(1.0, np.max(np.abs(o), axis=1))[:, None]
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > t_min)
    return np.where(hit, t, 0.0)


def _blocks(n_rays: int, n_tris: int):
    step = max(1, _BLOCK // max(1, n_tris))
    for a in range(0, n_rays, step):
        yield a, min(n_rays, a + step)


def _names(sensors, ids, verb: tuple[str, str] = ("lies", "lie")) -> str:
    """``sensor 'a' lies`` / ``3 sensors ('a', 'b', 'c') lie`` / ``12 sensors ('a', 'b', 'c', ...) lie``."""
    ids = list(dict.fromkeys(ids))
    if len(ids) == 1:
        s = sensors[ids[0]]
        return f"sensor {s.name!r}{_where(s)} {verb[0]}"
    shown = ", ".join(repr(sensors[i].name) for i in ids[:_NAMED]) + (", ..." if len(ids) > _NAMED else "")
    return f"{len(ids)} sensors ({shown}) {verb[1]}"


def _where(s: Sensor) -> str:
    if s.grid:
        return f" (grid {s.grid!r})"
    return f" ({s.source})" if s.source and s.source != s.name else ""


def _prims_of(g, tri_ids: np.ndarray) -> str:
    names = [g.prim_names[i] for i in np.unique(g.prim[tri_ids])]
    return ", ".join(names[:2]) + (" ..." if len(names) > 2 else "")


def _vec(p) -> str:
    return "(" + ", ".join(f"{x:.4g}" for x in p) + ")"


def box_text(box) -> str:
    """``x 0..5, y 0..4, z 0..2.8 m`` (a float32 hair off zero is shown as 0)."""
    lo, hi = box
    tiny = 1e-6 * max(1.0, float(np.max(np.abs([lo, hi]))))
    c = lambda x: 0.0 if abs(x) < tiny else float(x)  # noqa: E731
    return ", ".join(f"{a} {c(l):.3g}..{c(h):.3g}" for a, l, h in zip("xyz", lo, hi)) + " m"


def _them(ids) -> str:
    return "it" if len(set(ids)) == 1 else "them"
