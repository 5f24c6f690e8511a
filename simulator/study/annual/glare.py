"""A year of glare at the stage's glare views, from daylight coefficients: the imageless method.

Per occupied hour h, at each glare view (an eye, a view direction, an up;
:mod:`simulator.glare`), DGP = c1·E_v + c2·log10(1 + G/E_v^1.87) + c3
(docs/REFERENCES.md §Glare indices) with E_v and G read without a picture
of the hour:

- **What the eye sees directly** (computed once per view and shading state,
  on the host): the hemisphere in front of the eye as a 256 × 256 half map
  (:data:`GRID`, 0.7° pixels, the glare view's layout:
  :mod:`simulator.glare.view`), a ray per pixel (:mod:`simulator.study.annual.rays`):
  a pixel that reaches the sky through the stage's openings and panes sees
  the Tregenza patch (or the ground below the horizon) of its direction,
  at the share T the faces on the way pass; a pixel whose first opaque face
  is a diffusing shade (:mod:`simulator.study.annual.diffusers`) sees that
  cell's luminance, at the share the faces before it pass. Each slot s (145
  patches, the ground, the cells) gets a_s = Σ T·ω·cos θ over its pixels.
- **E_v** = Σ_s a_s·L_s(h) (the sky, ground and shades seen, exact but for
  the pixels' size) + x_hᵀc (the interreflected light: an irradiance sensor
  at the eye facing the view direction, traced once per state with
  ``component = "indirect"`` for the sky's 146 slots and the cells' emitters;
  x_h the hour's patch levels with the sun's light spread over the patches
  around it, and the cells' levels) + E_n·T_sun·cos σ_sun (the sun's direct
  light, exact: one ray per hour toward it). Its standard error is
  √(x_hᵀ C x_h), the traced part's.
- **Sources** as evalglare finds them (its options on the view's prim,
  :mod:`simulator.glare.sources`): a pixel is a source pixel above the
  absolute threshold (``-b``, 2000 cd/m²); the pixels a view can see sky or
  a shade through are grouped once into regions as evalglare merges pixels
  (within half its search radius); each hour each region's source pixels
  are one source (ω the sum, L the ω-weighted mean, P at the ω·L-weighted
  direction), its pixels at or above ``-Y`` (50,000 cd/m²) another (peak
  extraction, ``-y``); the sun is a disk of 0.533° (:data:`SUN_HALF_ANGLE_RAD`)
  and luminance E_n·T_sun/(π·sin²α), a source of its own (with ``-x``:
  merged into the region it lies in). G = Σ L²ω/P².

What this leaves out, against evalglare on a picture of the hour
(measured in docs/studies.md, "Annual glare"): every surface seen is a
background, never a source, however bright (a sunlit floor or desk at
ρ·E/π, the outdoor ground in the sun, a glossy reflection of the sun), while
its light is in E_v; a patch's luminance is the patch's mean (the Perez sky
over Tregenza's patches, as every annual reading); a region whose source
pixels fall apart in an hour (two bright parts of one window with darker sky
between) stays one source; the sun's interreflected light comes from the
patches around it (as for every annual reading with ``sun_indirect =
"patches"``); a relative threshold (``-b`` ≤ 100, a multiple of the task or
mean luminance) needs the picture: such a view is left out of the year, with a warning.

DGPs (``[annual] glare_index = "dgps"``) is 6.22·10⁻⁵·E_v + 0.184 from the
same E_v. Figures of a year (:func:`glare_metrics`): glare autonomy (the
share of occupied hours with DGP below ``glare_limit``, after Jones 2019),
the occupied hours with DGP above 0.35, 0.40 and 0.45 (Wienold 2009's
perceptible, disturbing and intolerable), and EN 17037's protection from
glare: the highest level (minimum 0.45, medium 0.40, high 0.35) whose DGP
is exceeded in no more than 5% of the occupied hours.

References
----------
N. L. Jones (2019), Fast climate-based glare analysis and spatial mapping,
Proc. Building Simulation 2019; J. Wienold (2009), Dynamic daylight glare
evaluation, Proc. Building Simulation 2009; EN 17037:2018 §5.4;
docs/REFERENCES.md §Glare indices, §Annual glare.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from simulator.glare import indices as ix
from simulator.glare import view as V
from simulator.glare.evaluate import SUN_SEEN, _pixel_half_sizes
from simulator.glare.sources import GlareSettings, _components
from simulator.scene.model import Sensor, SensorKind
from simulator.study.inputs import sky_patches as SP

__all__ = ["GRID", "SUN_HALF_ANGLE_RAD", "DGP_CLASSES", "EN17037_LEVELS", "ViewSky", "eye_sensor", "view_sky", "sun_terms",
           "glare_term", "dgp_hourly", "dgps_hourly", "glare_metrics", "GLARE_METRICS", "annual_views", "hour_scene", "full_view"]

#: the half map of the directly seen sky and shades: width, height (0.7° pixels)
GRID = (256, 256)
#: the sun's angular radius (its disk 0.533° across)
SUN_HALF_ANGLE_RAD = 0.5 * math.radians(0.533)
#: the DGP bounds whose exceedance hours are counted (Wienold 2009: perceptible, disturbing, intolerable)
DGP_CLASSES = (0.35, 0.40, 0.45)
#: EN 17037 protection from glare: level → the DGP exceeded in at most 5% of the usage time
EN17037_LEVELS = ((3, "high", 0.35), (2, "medium", 0.40), (1, "minimum", 0.45))
#: the share of the usage time a level's DGP may be exceeded (EN 17037)
EN17037_SHARE = 0.05
#: hours per chunk of the hourly source sums
_HOURS = 256


@dataclass
class ViewSky:
    """What one view sees directly in one shading state (module docstring).

    Attributes
    ----------
    sensor : Sensor
        The glare view.
    frame : ndarray, shape (3, 3)
        Columns left, up, view.
    settings : GlareSettings
    a : ndarray, shape (146 + C,)
        E_v per unit luminance of each slot (cd/m² → lx).
    dirs, omega : ndarray, shapes (D, 3), (D,)
        The pixels that see sky or a shade.
    sky_slot, cell_slot : ndarray of int, shape (D,)
        The slot each pixel sees through the openings (−1: none) and on a shade (146 + cell; −1: none).
    t_sky, t_cell : ndarray, shape (D,)
        The shares the faces on the way pass.
    region : ndarray of int, shape (D,)
        Each pixel's region (evalglare's merging); ``pixel_region`` (W·H,) the same per map pixel, −1 elsewhere.
    """

    sensor: Sensor
    frame: np.ndarray
    settings: GlareSettings
    a: np.ndarray
    dirs: np.ndarray
    omega: np.ndarray
    sky_slot: np.ndarray
    cell_slot: np.ndarray
    t_sky: np.ndarray
    t_cell: np.ndarray
    region: np.ndarray
    n_regions: int
    pixel_region: np.ndarray

    @property
    def name(self) -> str:
        return self.sensor.name


def eye_sensor(view: Sensor) -> Sensor:
    """An irradiance sensor at the eye facing the view direction: its reading is E_v."""
    n = np.asarray(view.normal, np.float64)
    return Sensor(name=f"{view.name}#eye", kind=SensorKind.IRRADIANCE, position=np.asarray(view.position, np.float64),
                  normal=n / np.linalg.norm(n), source=view.source)  # fmt: skip


def annual_views(views: list) -> tuple[list, list[str]]:
    """The glare views a year can read, and a warning for each it cannot: a relative threshold (``-b`` ≤ 100, a
    multiple of the task or mean luminance) needs the hour's picture."""
    keep, notes = [], []
    for v in views:
        s = v.glare if v.glare is not None else GlareSettings()
        if s.threshold <= 100.0:
            notes.append(f"glare view {v.name} ({v.source}) is not read over the year: its probesim:sensor:evalglare -b "
                         f"{s.threshold:g} is a multiple of the task or mean luminance, which needs the hour's picture "
                         "(give an absolute threshold, above 100 cd/m², for annual glare)")  # fmt: skip
        else:
            keep.append(v)
    return keep, notes


def view_sky(view: Sensor, rs, diffusers: list, cell_base: list[int], n_slots: int) -> ViewSky:
    """The directly seen part of ``view`` in one state (module docstring).

    ``rs``: the state's :class:`simulator.study.annual.rays.RayScene`; ``diffusers`` its diffusing shades,
    ``cell_base`` the slot of each one's first cell, ``n_slots`` 146 + the state's cells."""
    from simulator.study.annual.rays import cast

    settings = view.glare if view.glare is not None else GlareSettings()
    frame = V.view_frame(view.normal, view.up)
    w, h = GRID
    dirs = V.pixel_centre_directions(w, h, frame).reshape(-1, 3)
    omega = V.pixel_solid_angles(w, h).reshape(-1)
    eye = np.asarray(view.position, np.float64)
    hits = cast(rs, eye, dirs)
    n_pix = len(dirs)
    sky_slot = np.where(hits.through > 0.0, SP.patch_index(dirs), -1)
    cell_slot = np.full(n_pix, -1, np.int64)
    t_cell = np.zeros(n_pix)
    hit_face = hits.face >= 0
    if diffusers and hit_face.any():
        prim_of_hit = np.full(n_pix, -1, np.int64)
        prim_of_hit[hit_face] = rs.prim[hits.face[hit_face]]
        for d, base in zip(diffusers, cell_base):
            ids = [k for k, n in enumerate(rs.prim_names) if n == d.prim]
            on = hit_face & np.isin(prim_of_hit, ids)
            if not on.any():
                continue
            pts = eye + dirs[on] * hits.t[on][:, None]
            c = d.cell_of(pts)
            sel = np.nonzero(on)[0][c >= 0]
            cell_slot[sel] = base + c[c >= 0]
            t_cell[sel] = hits.before[sel]
    cos = np.clip(dirs @ frame[:, 2], 0.0, 1.0)
    a = np.zeros(n_slots)
    sky = sky_slot >= 0
    np.add.at(a, sky_slot[sky], (hits.through * omega * cos)[sky])
    cell = cell_slot >= 0
    np.add.at(a, cell_slot[cell], (t_cell * omega * cos)[cell])
    seen = sky | cell
    idx = np.nonzero(seen)[0]
    half = _pixel_half_sizes((h, w), n_pix)
    region = _components(dirs[idx], 0.5 * settings.search_radius, half[idx]) if len(idx) else np.zeros(0, np.int64)
    pixel_region = np.full(n_pix, -1, np.int64)
    pixel_region[idx] = region
    return ViewSky(view, frame, settings, a, dirs[idx], omega[idx], sky_slot[idx], cell_slot[idx], hits.through[idx], t_cell[idx],
                   region, int(region.max()) + 1 if len(region) else 0, pixel_region)  # fmt: skip


@dataclass
class SunTerms:
    """The sun at one view every hour (shape (H,) each): its direct E_v, its disk's luminance as seen (0: not
    seen), its solid angle, position index and the region its direction falls in (−1: none)."""

    ev: np.ndarray
    luminance: np.ndarray
    omega: float
    position_index: np.ndarray
    direction: np.ndarray
    region: np.ndarray


def sun_terms(vs: ViewSky, rs, sun_dir: np.ndarray, dni_lx: np.ndarray) -> SunTerms:
    """The sun's part of every hour at ``vs``'s eye: one ray toward it per hour with the sun up and in front."""
    from simulator.study.annual.rays import cast

    n_h = len(sun_dir)
    view, up = vs.frame[:, 2], vs.frame[:, 1]
    cos = sun_dir @ view
    front = (np.asarray(dni_lx) > 0.0) & (cos > 0.0)
    t = np.zeros(n_h)
    if front.any():
        t[front] = cast(rs, np.asarray(vs.sensor.position, np.float64), sun_dir[front]).through
    alpha = SUN_HALF_ANGLE_RAD
    disk = math.pi * math.sin(alpha) ** 2
    omega = 2.0 * math.pi * 2.0 * math.sin(0.5 * alpha) ** 2  # 2π(1 − cos α) without cancellation
    seen = front & (t > SUN_SEEN)
    lum = np.where(seen, np.asarray(dni_lx) * t / disk, 0.0)
    p = np.ones(n_h)
    if seen.any():
        p[seen] = ix.position_index(sun_dir[seen], view, up)
    row, col, _ = V.pixel_of_directions(sun_dir, GRID[0], GRID[1], vs.frame)
    region = np.where(seen, vs.pixel_region[row * GRID[0] + col], -1)
    return SunTerms(np.asarray(dni_lx) * t * np.maximum(cos, 0.0), lum, omega, p, sun_dir, region)


def glare_term(vs: ViewSky, lum: np.ndarray, sun: SunTerms) -> np.ndarray:
    """G = Σ L²ω/P² of every hour (H,), from the slots' luminances ``lum`` (H, 146 + C), cd/m² (module docstring)."""
    s = vs.settings
    thr = float(s.threshold)
    peak = float(s.peak_cd_m2) if s.peak_extraction else math.inf
    view, up = vs.frame[:, 2], vs.frame[:, 1]
    n_h = lum.shape[0]
    g = np.zeros(n_h)
    sky = np.maximum(vs.sky_slot, 0)
    cell = np.maximum(vs.cell_slot, 0)
    ws = np.where(vs.sky_slot >= 0, vs.t_sky, 0.0)
    wc = np.where(vs.cell_slot >= 0, vs.t_cell, 0.0)
    merged_sun = (not s.peak_extraction) & (sun.region >= 0)
    for lo in range(0, n_h, _HOURS):
        hi = min(lo + _HOURS, n_h)
        L = lum[lo:hi][:, sky] * ws + lum[lo:hi][:, cell] * wc  # (h, D)
        for r in range(vs.n_regions):
            m = vs.region == r
            lr, om, dr = L[:, m], vs.omega[m], vs.dirs[m]
            parts = [(lr > thr) & (lr < peak)] + ([lr >= peak] if s.peak_extraction else [])
            for k, mask in enumerate(parts):
                x = np.where(mask, lr, 0.0)
                S = x @ om
                W = mask.astype(np.float64) @ om
                C = (x * om) @ dr
                if k == 0:
                    js = merged_sun[lo:hi] & (sun.region[lo:hi] == r)
                    if js.any():  # without peak extraction the sun joins the region it lies in
                        ls = sun.luminance[lo:hi][js]
                        S[js] += ls * sun.omega
                        W[js] += sun.omega
                        C[js] += (ls * sun.omega)[:, None] * sun.direction[lo:hi][js]
                ok = W > 0.0
                if not ok.any():
                    continue
                nc = np.linalg.norm(C[ok], axis=1, keepdims=True)
                p = ix.position_index(C[ok] / np.where(nc > 0, nc, 1.0), view, up)
                g[lo:hi][ok] += S[ok] ** 2 / (W[ok] * p**2)
    alone = (sun.luminance > thr) & ~merged_sun
    g[alone] += sun.luminance[alone] ** 2 * sun.omega / sun.position_index[alone] ** 2
    return g


def dgp_hourly(ev: np.ndarray, g: np.ndarray, low_light: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """DGP (capped at 1) and dDGP/dE_v (0 where capped) of every hour, from E_v (lx) and G (docs/REFERENCES.md §Glare indices)."""
    ev = np.asarray(ev, np.float64)
    a = ix.DGP_EV_EXPONENT
    pos = ev > 0.0
    e = np.where(pos, ev, 1.0)
    x = np.where(pos, np.maximum(g, 0.0) / e**a, 0.0)
    d0 = ix.DGP_C1 * np.where(pos, ev, 0.0) + ix.DGP_C2 * np.log10(1.0 + x) + ix.DGP_C3
    de = np.where(pos, ix.DGP_C1 - ix.DGP_C2 / math.log(10.0) * a * x / ((1.0 + x) * e), ix.DGP_C1)
    if low_light:
        z = 0.024 * ev - 4.0
        f = np.where(ev < 1000.0, 1.0 / (1.0 + np.exp(-z)), 1.0)
        de = f * de + np.where(ev < 1000.0, 0.024 * f * (1.0 - f) * d0, 0.0)
        d0 = f * d0
    return np.minimum(d0, 1.0), np.where(d0 < 1.0, de, 0.0)


def dgps_hourly(ev: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """DGPs (capped at 1) and its slope."""
    d = ix.DGPS_SLOPE * np.asarray(ev, np.float64) + ix.DGPS_OFFSET
    return np.minimum(d, 1.0), np.where(d < 1.0, ix.DGPS_SLOPE, 0.0)


#: key -> (unit, definition) of a view's rows in annual_metrics.csv
GLARE_METRICS = {
    "GA": ("%", "glare autonomy: share of occupied hours with the index below glare_limit"),
    "hours_above_0.35": ("h", "occupied hours with the index above 0.35 (perceptible glare or worse)"),
    "hours_above_0.40": ("h", "occupied hours with the index above 0.40 (disturbing or worse)"),
    "hours_above_0.45": ("h", "occupied hours with the index above 0.45 (intolerable)"),
    "EN17037_glare": ("0-3", "EN 17037 protection from glare: 3 high, 2 medium, 1 minimum, 0 none (index above "
                             "0.35/0.40/0.45 in at most 5% of the occupied hours)"),
}


def glare_metrics(dgp: np.ndarray, occupied: np.ndarray, limit: float, hour_weight: float = 1.0) -> dict[str, float]:
    """A view's year (module docstring): the rows of :data:`GLARE_METRICS`."""
    d = np.asarray(dgp)[np.asarray(occupied, bool)]
    n = max(len(d), 1)
    out = {"GA": 100.0 * float(np.sum(d < limit)) / n}
    for b in DGP_CLASSES:
        out[f"hours_above_{b:.2f}"] = float(np.sum(d > b)) * hour_weight
    level = 0
    for code, _, b in EN17037_LEVELS:
        if float(np.sum(d > b)) / n <= EN17037_SHARE:
            level = code
            break
    out["EN17037_glare"] = float(level)
    return out


def hour_scene(state_scene, dome, group: str, levels: np.ndarray, sun_dir: np.ndarray, dni_lx: float,
               cells: list | None = None, lum_cells: np.ndarray | None = None):  # fmt: skip
    """One hour of the year as an ordinary scene, for a glare view's full trace of it (the check of the
    imageless figures): the state's stage without its lights but the sky's DomeLight, its texels at their
    patch's level of the hour (``levels``, (146,): L_p/L_dome and the ground's), the sun a disk of 0.533°
    with the hour's normal illuminance, and a diffusing shade's cells at their luminance of the hour."""
    from dataclasses import replace

    from simulator.scene.model import Light, LightKind
    from simulator.study.figures.glare_views import _patch_dome
    from simulator.study.inputs.sun import sun_frame
    from simulator.study.trace.groups import group_scene

    lv = {f"{group}/p{k:03d}": float(levels[k]) for k in range(SP.N_PATCHES)}
    lv[f"{group}/ground"] = float(levels[SP.N_PATCHES])
    lights = [_patch_dome(dome, lv, group)]
    ratio = float(dome.emission[0]) / float(dome.emission[1]) if dome.emission[1] > 0 else 1.0 / 683.0
    if dni_lx > 0.0 and sun_dir[2] > 0.0:
        lum = float(dni_lx) / (math.pi * math.sin(SUN_HALF_ANGLE_RAD) ** 2)
        lights.append(Light("/Sun", LightKind.DISTANT, np.zeros(3), sun_frame(sun_dir), (lum * ratio, lum),
                            half_angle=SUN_HALF_ANGLE_RAD))  # fmt: skip
    for light, lum in zip(cells or [], [] if lum_cells is None else lum_cells):
        lights.append(replace(light, emission=(float(lum) * ratio, float(lum))))
    return replace(group_scene(state_scene, []), lights=lights)


def full_view(res, study, hour: int, view: int, seed: int):
    """The glare view ``view`` traced on hour ``hour`` of an annual result (its chosen state, :func:`hour_scene`):
    a :class:`simulator.engine.glare.GlareResult`, the figures the imageless method stands in for."""
    from simulator.engine.driver import Engine, load_kernels
    from simulator.engine.glare import run_glare
    from simulator.plan.planner import probe_method

    det = res.detail
    k = int(res.state[hour]) if res.state is not None else 0
    st, plan, y = det["states"][k], det["plans"][k], det["years"][k]
    vw = [s for s in st.scene.sensors if s.kind == SensorKind.GLARE][view]
    scene = hour_scene(st.scene, det["dome"], study.annual.sky_group, res.sky_levels[hour], res.skies.sun_dir[hour],
                       float(res.skies.dni_lx[hour]), plan.cells, None if y.lum_cells is None else y.lum_cells[hour])  # fmt: skip
    sim = study.simulation
    load_kernels(sim.device, scene)
    method, _ = probe_method(scene, sim.method, sim.component)
    (r,) = run_glare(scene, [vw], method, lambda s, ss: Engine(s, ss, device=sim.device, threads=sim.threads), seed=seed,
                     max_depth=sim.max_depth)  # fmt: skip
    return r
