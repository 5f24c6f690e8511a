"""``probesim verify``: the reference suite, run through the normal pipeline.

Every case is a bundled config (``configs/*.toml``) on a bundled stage
(``stages/*.usda``), so every case is also an example a user can run with
``probesim run``. The suite reads each config with
:func:`simulator.config.loader.load_config`, the stage with
:func:`simulator.pipeline.load_scene`, collects the sensors with
:func:`simulator.pipeline.collect_sensors`, traces them with
:class:`simulator.engine.driver.Engine`, and compares each reading with its
expected value. It writes none of the configs' CSVs.

Expected values are computed here, from :mod:`simulator.reference.closed_forms` and
the light, surface and sensor parameters the stage reader produced; each
function names its formula and source. The only typed-in numbers are the
published CIE 171:2006 table values, shown beside the exact ones for
comparison.

Pass criterion per reading (``judge``): the error is within 1% of the
expected value AND within 4 standard errors plus a float32 slack of 2e-6
relative (the kernels compute in float32, so a zero-variance reading of a
delta light is exact only to that precision). Four standard errors is a
6e-5 two-sided false-alarm chance per reading for a correct estimator; the
1% bound is the project's accuracy target (CIE 171:2006 validations commonly
use 5% per point). A case whose expected value is 0 must read 0.

Each run is adaptive: sensors stop when their 95% confidence half-width is
under ``Case.rel_target`` of the reading (``REL_TARGET``, 0.2%, so stderr
≤ 0.1%; 0.4% for the slow interreflection cases and for every case with
``--quick``), so that the 1% bound is at least five standard errors wide and
a noisy reading cannot pass the 4σ test merely by being noisy.

Photometric cases run again with ``light_units = "radiometric"``, where the
stage's numbers are W m⁻² sr⁻¹ (W/sr, W/m²), and those rows compare the
radiometric (W) channel.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from simulator.reference import closed_forms as cf
from simulator.config.loader import RunConfig, load_config
from simulator.bundled import configs_dir as bundled_configs_dir
from simulator.errors import UserError
from simulator.scene.model import Light, LightKind, Scene, Sensor, SensorKind, patch_width_axis

__all__ = [
    "REL_TOL",
    "K_SIGMA",
    "FLOAT32_SLACK",
    "REL_TARGET",
    "REL_TARGET_QUICK",
    "Case",
    "CASES",
    "Row",
    "SuiteResult",
    "default_configs_dir",
    "judge",
    "expected_values",
    "run_case",
    "run_suite",
    "format_row",
    "format_header",
    "format_summary",
    "csv_text",
    "write_csv",
]

#: a reading must be within this fraction of the expected value
REL_TOL = 0.01
#: ... and within this many standard errors (plus FLOAT32_SLACK)
K_SIGMA = 4.0
#: float32 arithmetic in the kernels: relative slack on top of K_SIGMA·stderr
FLOAT32_SLACK = 2e-6
#: adaptive stopping: 95% half-width under this fraction of the reading (stderr ≤ 0.1%)
REL_TARGET = 0.002
#: the slow (interreflection) cases, and every case with --quick: stderr ≤ 0.2%,
#: so 1% is still five standard errors
REL_TARGET_QUICK = 0.004
#: per-sensor sample cap of the adaptive runs
MAX_SAMPLES = 1 << 24
MAX_SAMPLES_QUICK = 1 << 21
#: first batch per sensor
FIRST_BATCH = 1 << 14

_UNITS = {
    (SensorKind.IRRADIANCE, 0): "W/m²",
    (SensorKind.IRRADIANCE, 1): "lx",
    (SensorKind.RADIANCE, 0): "W/m²/sr",
    (SensorKind.RADIANCE, 1): "cd/m²",
    (SensorKind.PATCH, 0): "W",
    (SensorKind.PATCH, 1): "lm",
}


def _unit(s: Sensor, ch: int, flux: bool) -> str:
    kind = s.kind if (s.kind != SensorKind.PATCH or flux) else SensorKind.IRRADIANCE
    return _UNITS[(kind, ch)]


# --------------------------------------------------------------------------- registry types


@dataclass
class CaseContext:
    """What an expected-value function sees: the case's scene, as read, and a
    way to read another config's scene (a case that must match another)."""

    cfg: RunConfig
    scene: Scene
    configs_dir: Path
    _refs: dict = field(default_factory=dict)

    def reference_scene(self, config_name: str) -> Scene:
        """The scene of another bundled config, read in this case's light units."""
        key = (config_name, self.cfg.light_units)
        if key not in self._refs:
            from simulator.pipeline import load_scene

            ref = load_config(self.configs_dir / config_name)
            self._refs[key] = load_scene(dataclasses.replace(ref, light_units=self.cfg.light_units))
        return self._refs[key]


#: (context, sensor, channel) → expected reading, the quantity the kernel
#: estimates: irradiance (W/m², lx), radiance (W m⁻² sr⁻¹, cd/m²) or, for a
#: patch, its mean irradiance (the table shows flux = mean × area unless the
#: case says otherwise)
ExpectedFn = Callable[[CaseContext, Sensor, int], float]
#: (context, sensor, channel) → a short comment for the table ("" for none)
NoteFn = Callable[[CaseContext, Sensor, int], str]


@dataclass(frozen=True)
class Case:
    """One reference case.

    Attributes
    ----------
    name : str
        Name in the table.
    config : str
        Config file name in the configs folder.
    method : str
        Estimator: light, bsdf, mis or path.
    expected : ExpectedFn
        Expected reading of each sensor.
    light_units : str or None
        Overrides the config's ``light_units`` (None: as the config says).
    note : NoteFn or None
        Comment per receiver (published values, model deviations).
    optional : bool
        The config may be absent (work in progress): the case is skipped with
        a printed note instead of failing.
    variants : tuple of (str, str)
        Variant selections (set, variant) that replace the config's.
    patch_flux : bool
        Report a patch's flux (W, lm); False: its mean irradiance (W/m², lx).
    rel_target : float
        Adaptive target: 95% half-width over the reading (stderr ≈ half of it).
    quick : bool
        Part of the ``--quick`` run.
    """

    name: str
    config: str
    method: str
    expected: ExpectedFn
    light_units: str | None = None
    note: NoteFn | None = None
    optional: bool = False
    variants: tuple[tuple[str, str], ...] = ()
    patch_flux: bool = True
    rel_target: float = REL_TARGET
    quick: bool = True


@dataclass
class Row:
    """One reading compared with its expected value."""

    case: str
    receiver: str
    unit: str
    expected: float
    measured: float
    stderr: float
    samples: int
    method: str
    passed: bool
    note: str = ""

    @property
    def error(self) -> float:
        return self.measured - self.expected

    @property
    def error_pct(self) -> float:
        """Error in % of |expected| (NaN when expected is 0)."""
        return 100.0 * self.error / abs(self.expected) if self.expected != 0 else math.nan

    @property
    def exact(self) -> bool:
        """The reading equals the expected value to float32 precision
        (FLOAT32_SLACK), a closer agreement than its standard error can
        resolve: a zero-variance reading, or one whose error is float32
        rounding larger than K_SIGMA of its tiny standard error."""
        within = abs(self.error) <= FLOAT32_SLACK * abs(self.expected) + 1e-12
        return within and (self.stderr == 0 or abs(self.error) > K_SIGMA * self.stderr)

    @property
    def error_sigma(self) -> float:
        """Error in standard errors (0 for an exact reading, ±inf when stderr is 0 and it is not)."""
        if math.isnan(self.error) or math.isnan(self.stderr):
            return math.nan
        if self.stderr > 0:
            return self.error / self.stderr
        return 0.0 if self.error == 0 else math.copysign(math.inf, self.error)


@dataclass
class SuiteResult:
    rows: list[Row]
    skipped: list[str]
    cases_run: list[str]
    wall_s: float

    @property
    def passed(self) -> bool:
        return all(r.passed for r in self.rows)


def judge(expected: float, measured: float, stderr: float) -> bool:
    """True when ``measured`` is within 1% of ``expected`` and within
    4·stderr + 2e-6·|expected| of it (see the module docstring)."""
    err = abs(measured - expected)
    if not (math.isfinite(measured) and math.isfinite(stderr)):
        return False
    within_rel = err <= REL_TOL * abs(expected) if expected != 0 else err <= 1e-12
    within_sigma = err <= K_SIGMA * stderr + FLOAT32_SLACK * abs(expected) + 1e-12
    return within_rel and within_sigma


# --------------------------------------------------------------------------- geometry helpers


def _one_light(scene: Scene, kind: LightKind) -> Light:
    lights = [l for l in scene.lights if l.kind == kind]
    if len(lights) != 1:
        raise UserError(f"{scene.path}: the reference case expects exactly one {kind.name} light, found {len(lights)}")
    return lights[0]


def _patch_vertices(s: Sensor) -> np.ndarray:
    """Corners of a patch sensor, counter-clockwise about its normal, metres."""
    right = patch_width_axis(s.up, s.normal)
    hw, hh = 0.5 * s.size[0], 0.5 * s.size[1]
    c = s.position
    return np.array([c - hw * right - hh * s.up, c + hw * right - hh * s.up, c + hw * right + hh * s.up, c - hw * right + hh * s.up])


def _cone_rim(direction: np.ndarray, half_angle: float, n: int = 64) -> np.ndarray:
    """Unit directions on the rim of a cone (and its axis), shape (n + 1, 3)."""
    d = direction / np.linalg.norm(direction)
    helper = np.array([1.0, 0.0, 0.0]) if abs(d[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    a = np.cross(d, helper)
    a /= np.linalg.norm(a)
    b = np.cross(d, a)
    phi = 2 * np.pi * np.arange(n) / n
    rim = np.cos(half_angle) * d + np.sin(half_angle) * (np.cos(phi)[:, None] * a + np.sin(phi)[:, None] * b)
    return np.vstack([d, rim])


def _ray_hits_triangles(o: np.ndarray, d: np.ndarray, tri: np.ndarray, t_max: float = math.inf) -> bool:
    """Any hit of the ray o + t·d, 0 < t < t_max, on triangles ``tri`` (T, 3, 3)
    (Möller–Trumbore in float64, both faces)."""
    if len(tri) == 0:
        return False
    e1 = tri[:, 1] - tri[:, 0]
    e2 = tri[:, 2] - tri[:, 0]
    pv = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, pv)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    tv = o - tri[:, 0]
    u = np.einsum("ij,ij->i", tv, pv) * inv
    qv = np.cross(tv, e1)
    v = (qv @ d) * inv
    t = np.einsum("ij,ij->i", e2, qv) * inv
    return bool(np.any(ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < t_max)))


def _points_in_polygon_2d(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Even–odd rule for points (N, 2) in a simple polygon (V, 2)."""
    x, y = pts[:, 0:1], pts[:, 1:2]
    x0, y0 = poly[:, 0], poly[:, 1]
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    crosses = ((y0 <= y) != (y1 <= y)) & (x < x0 + (y - y0) * (x1 - x0) / np.where(y1 != y0, y1 - y0, 1.0))
    return np.count_nonzero(crosses, axis=1) % 2 == 1


def _cone_lands_inside(s: Sensor, plane_point, plane_normal, inside: Callable[[np.ndarray], np.ndarray]) -> bool:
    """Whether every ray of a radiance meter's cone (rim and axis) meets the
    plane in front of the meter at a point for which ``inside`` holds."""
    dirs = _cone_rim(s.normal, s.half_angle)
    denom = dirs @ plane_normal
    if np.any(np.abs(denom) < 1e-12):
        return False
    t = ((np.asarray(plane_point) - s.position) @ plane_normal) / denom
    if np.any(t <= 0):
        return False
    return bool(np.all(inside(s.position + t[:, None] * dirs)))


def _no_closed_form(ctx: CaseContext, s: Sensor, why: str) -> UserError:
    return UserError(f"{ctx.cfg.path}: {s.name}: no closed form for this receiver ({why})")


# --------------------------------------------------------------------------- expected values


def _point(ctx: CaseContext, s: Sensor, ch: int, scene: Scene | None = None) -> float:
    """Isotropic point source. Irradiance: E = I·cosξ/d² (inverse-square cosine
    law, docs/REFERENCES.md §Point source). Patch: flux Φ = I·Ω with Ω the patch's
    solid angle (Van Oosterom & Strackee), over its area."""
    l = _one_light(scene or ctx.scene, LightKind.POINT)
    intensity = l.emission[ch]
    if s.kind == SensorKind.PATCH:
        return float(cf.point_flux_through_polygon(intensity, l.position, _patch_vertices(s))) / (s.size[0] * s.size[1])
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.point_irradiance(intensity, l.position, s.position, s.normal))
    raise _no_closed_form(ctx, s, "a radiance meter cannot see a point light")


def _point_cm_yup(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """The same stage authored in centimetres with Y up must read exactly what
    point.usda (metres, Z up) reads: the closed form of :func:`_point`
    evaluated with the light of point.toml's stage."""
    return _point(ctx, s, ch, scene=ctx.reference_scene("point.toml"))


def _sphere(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Uniform sphere light: E = π·L·sin²σ·cosθ above the horizon, the
    straddling formula across it (Howell's catalogue; docs/REFERENCES.md
    §Uniform sphere). A radiance meter whose cone lies inside the sphere's disc reads L."""
    l = _one_light(ctx.scene, LightKind.SPHERE)
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.sphere_irradiance(l.emission[ch], l.position, l.radius, s.position, s.normal))
    if s.kind == SensorKind.RADIANCE:
        to_c = l.position - s.position
        d = np.linalg.norm(to_c)
        angle = math.acos(np.clip(np.dot(to_c / d, s.normal), -1.0, 1.0))
        if angle + s.half_angle <= math.asin(min(1.0, l.radius / d)):
            return l.emission[ch]
        raise _no_closed_form(ctx, s, "the meter's cone is not inside the sphere's disc")
    raise _no_closed_form(ctx, s, "patch")


def _rect(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Rect light. A receiver parallel to it and facing it: corner rectangles
    (Howell's catalogue, parallel rectangle from above a corner, added and
    subtracted; docs/REFERENCES.md §Parallel rectangle). Any other receiver:
    Lambert's contour formula after clipping to its upper hemisphere
    (docs/REFERENCES.md §Lambert's polygon formula). A meter whose cone lands inside the
    rectangle reads L."""
    l = _one_light(ctx.scene, LightKind.RECT)
    L = l.emission[ch]
    ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
    if s.kind == SensorKind.IRRADIANCE:
        rel = l.position - s.position
        height = float(rel @ ez)
        if np.dot(s.normal, ez) > 1.0 - 1e-12 and height > 0:  # parallel, facing the light
            cx, cy = float(rel @ ex), float(rel @ ey)
            return float(cf.rect_irradiance_parallel(L, cx - l.width / 2, cx + l.width / 2, cy - l.height / 2, cy + l.height / 2, height))
        verts = cf.rect_light_vertices(l.position, ex, ey, l.width, l.height)
        return float(cf.polygon_irradiance(L, verts, s.position, s.normal, one_sided_normal=-ez))
    if s.kind == SensorKind.RADIANCE:

        def inside(q):
            r = q - l.position
            return (np.abs(r @ ex) <= l.width / 2) & (np.abs(r @ ey) <= l.height / 2)

        if np.dot(s.normal, ez) > 0 and _cone_lands_inside(s, l.position, ez, inside):
            return L
        raise _no_closed_form(ctx, s, "the meter's cone does not land inside the rectangle")
    raise _no_closed_form(ctx, s, "patch")


#: sides of the polygons that bracket a disk light (see :func:`_disk`)
DISK_POLYGON_SIDES = 8192


def _disk_polygon(l: Light, circumscribed: bool) -> np.ndarray:
    phi = 2 * np.pi * np.arange(DISK_POLYGON_SIDES) / DISK_POLYGON_SIDES
    r = l.radius / math.cos(math.pi / DISK_POLYGON_SIDES) if circumscribed else l.radius
    return l.position + r * (np.cos(phi)[:, None] * l.frame[:, 0] + np.sin(phi)[:, None] * l.frame[:, 1])


def _disk_bracket(l: Light, s: Sensor, ch: int) -> tuple[float, float]:
    """(inscribed, circumscribed) polygon irradiance of a disk light. The
    integrand cos⁺θ is ≥ 0 and inscribed ⊂ disk ⊂ circumscribed, so the two
    bracket the disk's irradiance: E_in ≤ E ≤ E_out."""
    ez = l.frame[:, 2]
    e = [
        float(cf.polygon_irradiance(l.emission[ch], _disk_polygon(l, c), s.position, s.normal, one_sided_normal=-ez))
        for c in (False, True)
    ]
    return e[0], e[1]


def _disk(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Disk light. On its axis: E = π·L·R²/(R²+h²)·cosω (Howell's catalogue,
    coaxial disk, element tilted). Parallel, off the axis: E = π·L·F with the
    offset-disk configuration factor (Howell; docs/REFERENCES.md §Parallel disk).
    Any other receiver (perpendicular, or with the disk partly below its
    horizon): Lambert's contour formula on the inscribed and circumscribed
    8192-gons, which bracket the exact value (their relative gap is about
    (π/8192)² ≈ 1.5e-7); the midpoint is used."""
    l = _one_light(ctx.scene, LightKind.DISK)
    if s.kind != SensorKind.IRRADIANCE:
        raise _no_closed_form(ctx, s, "only irradiance receivers")
    ez = l.frame[:, 2]
    rel = l.position - s.position
    h = float(rel @ ez)
    offset = float(np.linalg.norm(rel - h * ez))
    if h > 0 and offset < 1e-12 * max(1.0, h):
        tilt = math.acos(float(np.clip(np.dot(s.normal, ez), -1.0, 1.0)))
        if tilt <= 0.5 * math.pi - math.atan2(l.radius, h):  # disk wholly above the horizon
            return float(cf.disk_irradiance_on_axis(l.emission[ch], l.radius, h, tilt=tilt))
    if h > 0 and np.dot(s.normal, ez) > 1.0 - 1e-12:
        return float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, h, offset))
    lo, hi = _disk_bracket(l, s, ch)
    return 0.5 * (lo + hi)


def _disk_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l = _one_light(ctx.scene, LightKind.DISK)
    ez = l.frame[:, 2]
    rel = l.position - s.position
    h = float(rel @ ez)
    if h > 0 and (np.linalg.norm(rel - h * ez) < 1e-12 * max(1.0, h) or np.dot(s.normal, ez) > 1.0 - 1e-12):
        return ""
    lo, hi = _disk_bracket(l, s, ch)
    return f"polygon bracket ±{0.5 * (hi - lo) / max(abs(hi), 1e-300):.1e}" if hi > 0 else ""


def _distant_occluder(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Delta distant light: E = E⊥·cosξ where the ray toward the light is
    clear, 0 where the stage's geometry blocks it (docs/REFERENCES.md
    §Point source, I/d² → E⊥). The shadow test is a float64 Möller–Trumbore over
    every triangle of the stage, independent of the engine's BVH."""
    l = _one_light(ctx.scene, LightKind.DISTANT)
    if l.half_angle != 0.0 or s.kind != SensorKind.IRRADIANCE:
        raise _no_closed_form(ctx, s, "a delta distant light and irradiance receivers only")
    g = ctx.scene.geometry
    toward = l.frame[:, 2]
    if _ray_hits_triangles(s.position, toward, g.points[g.triangles]):
        return 0.0
    return l.emission[ch] * max(0.0, float(np.dot(s.normal, toward)))


def _ground_is_black_plane(scene: Scene) -> bool:
    g = scene.geometry
    return g.n_triangles > 0 and bool(np.all(g.points[:, 2] == 0.0)) and bool(np.all(g.albedo == 0))


def _dome(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Uniform sky over a black ground: E = π·L·(1 + cos β)/2 for a receiver
    tilted β from the zenith (docs/REFERENCES.md §Uniform environment); a meter
    whose cone is wholly above the horizon reads L. The ground is 20 km across,
    so from 1 m up the sky seen past its edge is below 1e-4 rad of elevation."""
    l = _one_light(ctx.scene, LightKind.DOME)
    if not _ground_is_black_plane(ctx.scene):
        raise UserError(f"{ctx.scene.path}: the dome case expects a black ground at z = 0 and nothing else")
    if s.position[2] < 0:
        raise _no_closed_form(ctx, s, "below the ground")
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.dome_irradiance(l.emission[ch], math.acos(float(np.clip(s.normal[2], -1.0, 1.0)))))
    if s.kind == SensorKind.RADIANCE and math.acos(float(np.clip(s.normal[2], -1.0, 1.0))) + s.half_angle < 0.5 * math.pi:
        return l.emission[ch]
    raise _no_closed_form(ctx, s, "radiance meter looking at the ground")


def _overcast_rows(ctx: CaseContext) -> tuple:
    """(dome light, its map's row values) for a sky map uniform in azimuth,
    whose lat-long pole the stage turned to the zenith (+Z)."""
    l = _one_light(ctx.scene, LightKind.DOME)
    m = l.texture_map
    if m is None or ctx.scene.geometry.n_triangles:
        raise UserError(f"{ctx.scene.path}: the overcast case expects one textured DomeLight and no geometry")
    if not np.allclose(m, m[:, :1]) or float(l.frame[2, 1]) < 1.0 - 1e-9:
        raise UserError(f"{ctx.scene.path}: the overcast case expects a map uniform in azimuth with its pole at +Z")
    return l, m[:, 0].astype(float)


def _overcast(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """The CIE standard overcast sky stored as lat-long rows (each the exact
    solid-angle mean of L_z(1 + 2cosθ)/3): horizontal and vertical receivers
    read the row-exact sums of ∫L·cosγ dω
    (closed_forms.latlong_rows_illuminance); a meter whose cone lies inside the
    top row reads that row's luminance."""
    l, rows = _overcast_rows(ctx)
    if s.kind == SensorKind.IRRADIANCE and abs(abs(s.normal[2]) - 1.0) < 1e-12 and s.normal[2] > 0:
        return l.emission[ch] * cf.latlong_rows_illuminance(rows)
    if s.kind == SensorKind.IRRADIANCE and abs(s.normal[2]) < 1e-12:
        return l.emission[ch] * cf.latlong_rows_illuminance(rows, vertical=True)
    if s.kind == SensorKind.RADIANCE and s.normal[2] > 0 and math.acos(min(1.0, s.normal[2])) + s.half_angle < math.pi / len(rows):
        return l.emission[ch] * rows[0]
    raise _no_closed_form(ctx, s, "only horizontal, vertical and zenith receivers")


def _overcast_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l, rows = _overcast_rows(ctx)
    if s.kind != SensorKind.IRRADIANCE:
        return ""
    vertical = abs(s.normal[2]) < 1e-12
    sky = l.emission[ch] * rows[0] / float(cf.cie_overcast_row_means(1.0, len(rows))[0])  # L_z
    cont = cf.cie_overcast_illuminance(sky, vertical=vertical)
    return f"continuous CIE sky {cont:.5g} (map {_overcast(ctx, s, ch) / cont - 1.0:+.2%})"


def _emissive_polygon(scene: Scene) -> tuple[np.ndarray, np.ndarray, tuple[float, float]]:
    """(vertices in authored order, front-face normal, emitted radiance pair)
    of a stage whose only geometry is one emissive, albedo-0 polygon."""
    g = scene.geometry
    if len(g.prim_names) != 1 or g.n_triangles == 0:
        raise UserError(f"{scene.path}: the polygon case expects exactly one emissive Mesh")
    if np.any(g.albedo != 0) or np.any(g.two_sided) or np.ptp(g.emission, axis=0).max() != 0:
        raise UserError(f"{scene.path}: the polygon must be one-sided, black (albedo 0) and uniformly emissive")
    verts = g.points  # one prim: its points in authored (face) order
    newell = 0.5 * np.cross(verts, np.roll(verts, -1, axis=0)).sum(axis=0)  # area vector along the winding
    return verts, newell / np.linalg.norm(newell), (float(g.emission[0, 0]), float(g.emission[0, 1]))


def _polygon(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Emissive polygon, front face only: Lambert's contour formula,
    E = (L/2)·|Σ γ_i n·û_i|, after Sutherland–Hodgman clipping to the
    receiver's upper hemisphere (Lambert 1760; Arvo 1995; docs/REFERENCES.md
    §Lambert's polygon formula). A meter whose cone lands inside the polygon reads L."""
    verts, front, emission = _emissive_polygon(ctx.scene)
    L = emission[ch]
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.polygon_irradiance(L, verts, s.position, s.normal, one_sided_normal=front))
    if s.kind == SensorKind.RADIANCE:
        a = verts[1] - verts[0]
        a /= np.linalg.norm(a)
        b = np.cross(front, a)
        poly2 = np.column_stack([(verts - verts[0]) @ a, (verts - verts[0]) @ b])

        def inside(q):
            r = q - verts[0]
            return _points_in_polygon_2d(np.column_stack([r @ a, r @ b]), poly2)

        if np.dot(s.normal, front) < 0 and _cone_lands_inside(s, verts[0], front, inside):
            return L
        raise _no_closed_form(ctx, s, "the meter's cone does not land on the polygon's front")
    raise _no_closed_form(ctx, s, "patch")


def _radiance_floor(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A Lambertian floor (f = ρ/π) under a delta sun: E = E⊥·cosξ, and the
    floor's radiance, the same toward every direction, is L = ρ·E/π
    (docs/REFERENCES.md §Reflection equation, f = ρ/π). The floor is the only
    surface, so no other light reaches it or the meters."""
    l = _one_light(ctx.scene, LightKind.DISTANT)
    g = ctx.scene.geometry
    if l.half_angle != 0.0 or g.n_triangles == 0 or np.ptp(g.albedo) != 0 or np.any(g.points[:, 2] != 0.0):
        raise UserError(f"{ctx.scene.path}: the radiance-floor case expects one flat floor at z = 0 and a delta sun")
    toward = l.frame[:, 2]
    e_floor = l.emission[ch] * max(0.0, float(toward[2]))
    if s.kind == SensorKind.IRRADIANCE:
        return l.emission[ch] * max(0.0, float(np.dot(s.normal, toward)))
    if s.kind == SensorKind.RADIANCE:
        lo, hi = g.points.min(axis=0), g.points.max(axis=0)

        def on_floor(q):
            return np.all((q[:, :2] >= lo[:2]) & (q[:, :2] <= hi[:2]), axis=1)

        if _cone_lands_inside(s, np.zeros(3), np.array([0.0, 0.0, 1.0]), on_floor):
            return float(g.albedo[0]) * e_floor / math.pi
        raise _no_closed_form(ctx, s, "the meter's cone does not land on the floor")
    raise _no_closed_form(ctx, s, "patch")


#: the CIE 171:2006 case 5.2 source is modelled by a small disk; its exact
#: irradiance must stay this close to the point-source value (relative)
CIE171_5_2_MODEL_LIMIT = 2e-7


def _cie171_disk(ctx: CaseContext) -> tuple[Light, cf.CIE171PointSourceGrid]:
    l = _one_light(ctx.scene, LightKind.DISK)
    grid = cf.cie171_point_source_grid()
    if not np.allclose(l.position, grid.source, atol=1e-9) or l.frame[2, 2] < 1.0 - 1e-12:
        raise UserError(f"{ctx.scene.path}: the CIE 171 5.2 source must sit at {tuple(grid.source)} m facing down")
    return l, grid


def _cie171_index(ctx: CaseContext, s: Sensor, grid) -> int:
    if s.name not in grid.names:
        raise _no_closed_form(ctx, s, f"not one of the CIE 171 5.2 receivers {', '.join(grid.names)}")
    i = grid.names.index(s.name)
    if not np.allclose(s.position, grid.positions[i], atol=1e-12) or s.normal[2] < 1.0 - 1e-12:
        raise UserError(f"{ctx.cfg.path}: sensor {s.name} must sit at {tuple(grid.positions[i])} facing up")
    return i


def _cie171_5_2(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """CIE 171:2006 case 5.2, exact: E = I0·h²/d⁴ for a Lambertian point
    source I(θ) = I0·cosθ (closed_forms.cie171_point_source_grid), scaled by
    the stage's I0 = L·πr² over the case's 1000 cd (so that radiometric mode,
    where the same numbers are W/sr, is checked too). The stage's 1 mm disk
    departs from a point by at most (r/h)² ≈ 1.1e-7 (the exact offset-disk
    factor, Howell; checked against CIE171_5_2_MODEL_LIMIT here)."""
    l, grid = _cie171_disk(ctx)
    i = _cie171_index(ctx, s, grid)
    i0 = l.emission[ch] * math.pi * l.radius**2  # on-axis intensity of a flat Lambertian emitter: L·A
    e_point = grid.exact_lx[i] * i0 / grid.intensity_cd
    e_disk = float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, grid.height_m, np.linalg.norm(grid.offsets[i])))
    if abs(e_disk / e_point - 1.0) > CIE171_5_2_MODEL_LIMIT:
        raise UserError(
            f"{ctx.scene.path}: the disk that models the CIE 171 5.2 point source is too large: "
            f"it departs from a point by {e_disk / e_point - 1.0:.1e} at {s.name}"
        )
    return e_point


def _cie171_5_2_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l, grid = _cie171_disk(ctx)
    i = _cie171_index(ctx, s, grid)
    e_disk = float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, grid.height_m, np.linalg.norm(grid.offsets[i])))
    e_point = grid.exact_lx[i] * l.emission[ch] * math.pi * l.radius**2 / grid.intensity_cd
    return f"CIE table {grid.published_lx[i]:g}; disk/point {e_disk / e_point - 1.0:+.1e}"


# -- shaped (UsdLuxShapingAPI) point-like luminaires: self-contained cases


def _shaped_point(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A shaped point light (spot cone, focus, IES profile): E = I(ω)·cosψ/d²
    with I(ω) = emission × LightShaping.factor(θ, φ), θ from the light's −Z
    axis, φ from its +X toward +Y (the numpy twin of the kernel's factor:
    cone with smoothstep softness, focus, the IES file's bilinear
    interpolation; OpenUSD user guide "ShapingAPI"). Sums every light."""
    if s.kind != SensorKind.IRRADIANCE:
        raise _no_closed_form(ctx, s, "only irradiance sensors")
    total = 0.0
    for l in ctx.scene.lights:
        if l.kind != LightKind.POINT:
            raise UserError(f"{ctx.scene.path}: the shaped-luminaire case expects point lights only, found {l.kind.name}")
        d = s.position - l.position
        dist = float(np.linalg.norm(d))
        w = d / dist
        cos_psi = float(-w @ s.normal)
        if cos_psi <= 0:
            continue
        f = 1.0
        if l.shaping is not None:
            ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
            theta = math.acos(float(np.clip(-w @ ez, -1.0, 1.0)))
            phi = math.atan2(float(w @ ey), float(w @ ex))
            f = float(l.shaping.factor(theta, phi))
        total += l.emission[ch] * f * cos_psi / dist**2
    return total


def _cie171_5_2_ies_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    grid = cf.cie171_point_source_grid()
    if s.name not in grid.names:
        return ""
    i = grid.names.index(s.name)
    return f"CIE table {grid.published_lx[i]:g}; exact cosine {grid.exact_lx[i]:.5f}" if ch == 1 else ""


# -- enclosures (interreflection): configs may be absent while they are being built


def _uniform_surface(scene: Scene) -> tuple[float, tuple[float, float]]:
    g = scene.geometry
    if g.n_triangles == 0 or np.ptp(g.albedo) != 0:
        raise UserError(f"{scene.path}: the enclosure case expects surfaces of one albedo")
    return float(g.albedo[0]), (float(g.emission[:, 0].max()), float(g.emission[:, 1].max()))


def _furnace(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Closed furnace, every wall emitting L_e with albedo ρ: L = L_e/(1 − ρ)
    everywhere and E = π·L_e/(1 − ρ) (docs/REFERENCES.md §Furnace)."""
    rho, emission = _uniform_surface(ctx.scene)
    if np.ptp(ctx.scene.geometry.emission[:, ch]) != 0:
        raise UserError(f"{ctx.scene.path}: the furnace case expects every wall to emit the same radiance")
    component = ctx.cfg.simulation.component
    total_l = float(cf.furnace_radiance(emission[ch], rho))
    l_value = {"total": total_l, "direct": emission[ch], "indirect": total_l - emission[ch]}[component]
    if s.kind == SensorKind.RADIANCE:
        return l_value
    if s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH):
        return math.pi * l_value
    raise _no_closed_form(ctx, s, "unknown sensor kind")


def _integrating_sphere(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Integrating sphere of albedo ρ with an isotropic point source (flux
    Φ = 4π·I) inside: the light reflected at least once reaches every wall
    point alike, ρΦ/((1 − ρ)·S) with S the wall area (docs/REFERENCES.md
    §Integrating sphere: Φ/(4πR²)·ρ/(1 − ρ) for S = 4πR²; the surface mean is
    exact for any closed enclosure, closed_forms.cie171_indirect_illuminance,
    and uniform on a sphere). The direct part is the point source's own
    E = I·cosξ/d² at the receiver (a patch: I·Ω/area), which equals Φ/(4πR²)
    on the wall of an ideal sphere with the source at its centre."""
    rho, _ = _uniform_surface(ctx.scene)
    l = _one_light(ctx.scene, LightKind.POINT)
    g = ctx.scene.geometry
    p = g.points[g.triangles]
    area = float(0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum())
    flux = 4.0 * math.pi * l.emission[ch]
    reflected = float(cf.cie171_indirect_illuminance(flux, rho, area))
    if s.kind == SensorKind.IRRADIANCE:
        direct = float(cf.point_irradiance(l.emission[ch], l.position, s.position, s.normal))
    elif s.kind == SensorKind.PATCH:
        direct = float(cf.point_flux_through_polygon(l.emission[ch], l.position, _patch_vertices(s))) / (s.size[0] * s.size[1])
    else:
        raise _no_closed_form(ctx, s, "irradiance and patch receivers only")
    return {"total": direct + reflected, "indirect": reflected, "direct": direct}[ctx.cfg.simulation.component]


def _cie171_5_8(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """CIE 171:2006 case 5.8: in a closed room of uniform reflectance ρ and
    total area S_T, the mean indirect illuminance over all surfaces is
    E_ind = ρΦ/((1 − ρ)S_T) (closed_forms.cie171_indirect_illuminance). The
    room is a cube with the source at its centre, so by symmetry each of the
    six faces receives the same indirect flux, and a patch covering one whole
    face reads E_ind itself. Φ = 4π·I from the stage's source; S_T from its
    triangles."""
    rho, _ = _uniform_surface(ctx.scene)
    l = _one_light(ctx.scene, LightKind.POINT)
    g = ctx.scene.geometry
    p = g.points[g.triangles]
    area = float(0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum())
    if s.kind != SensorKind.PATCH or abs(s.size[0] * s.size[1] * 6.0 / area - 1.0) > 1e-9:
        raise _no_closed_form(ctx, s, "only patches covering one whole face of the cube")
    if ctx.cfg.simulation.component != "indirect":
        raise _no_closed_form(ctx, s, "the case's closed form is the indirect component")
    flux = 4.0 * math.pi * l.emission[ch]
    return float(cf.cie171_indirect_illuminance(flux, rho, area))


def _cie171_5_8_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    rho, _ = _uniform_surface(ctx.scene)
    table = cf.CIE171_5_8_TABLE_LX.get(round(rho, 2))
    return f"ρ = {rho:g}; CIE table {table:g}" if table is not None and ch == 1 else f"ρ = {rho:g}"


def _rho_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    return f"ρ = {_uniform_surface(ctx.scene)[0]:g}"


# --------------------------------------------------------------------------- the registry

# Direct light: one emitter, closed forms, next-event estimation ("mis" for the
# polygon, whose near-field receivers are noisy under area sampling alone).
_BASE_CASES: tuple[Case, ...] = (
    Case("cie171_5_2", "cie171_5_2.toml", "light", _cie171_5_2, note=_cie171_5_2_note),
    Case("point", "point.toml", "light", _point),
    Case("point_cm_yup", "point_cm_yup.toml", "light", _point_cm_yup),
    Case("sphere", "sphere.toml", "light", _sphere),
    Case("rect", "rect.toml", "light", _rect),
    Case("cie171_5_3", "cie171_5_3.toml", "light", _rect, note=lambda ctx, s, ch: "Lambert (flush light)"),
    Case("cie171_5_2_ies", "cie171_5_2_ies.toml", "light", _shaped_point, note=_cie171_5_2_ies_note),
    Case("spot_cone", "spot_cone.toml", "light", _shaped_point),
    Case("asymmetric_luminaire", "asymmetric_luminaire.toml", "light", _shaped_point),
    Case("disk", "disk.toml", "light", _disk),
    Case("disk_perpendicular", "disk_perpendicular.toml", "light", _disk, note=_disk_note),
    Case("polygon", "polygon.toml", "mis", _polygon),
    Case("distant_occluder", "distant_occluder.toml", "light", _distant_occluder),
    Case("dome", "dome.toml", "light", _dome),
    Case("cie_overcast", "cie_overcast.toml", "mis", _overcast, note=_overcast_note),
    Case("radiance_floor", "radiance_floor.toml", "light", _radiance_floor),
)


def _reflectance(rho: str) -> tuple[tuple[str, str], ...]:
    return (("reflectance", rho),)


# Interreflection: path tracing with Russian roulette, several reflectances
# each (the configs' "reflectance" variant set). These are the slow cases, so
# they stop at stderr ≤ 0.2% (still five standard errors inside 1%), and
# --quick runs one reflectance each.
_ENCLOSURE_CASES: tuple[Case, ...] = (
    Case("furnace ρ=0.5", "furnace.toml", "path", _furnace, note=_rho_note, optional=True,
         variants=_reflectance("rho_0_5"), rel_target=REL_TARGET_QUICK),
    Case("furnace ρ=0.9", "furnace.toml", "path", _furnace, note=_rho_note, optional=True,
         variants=_reflectance("rho_0_9"), rel_target=REL_TARGET_QUICK, quick=False),
    Case("integrating_sphere", "integrating_sphere.toml", "path", _integrating_sphere, note=_rho_note,
         optional=True, rel_target=REL_TARGET_QUICK),
    Case("cie171_5_8 ρ=0.5", "cie171_5_8.toml", "path", _cie171_5_8, note=_cie171_5_8_note, optional=True,
         variants=_reflectance("rho_0_5"), patch_flux=False, rel_target=REL_TARGET_QUICK),
    Case("cie171_5_8 ρ=0.8", "cie171_5_8.toml", "path", _cie171_5_8, note=_cie171_5_8_note, optional=True,
         variants=_reflectance("rho_0_8"), patch_flux=False, rel_target=REL_TARGET_QUICK, quick=False),
)  # fmt: skip


def _radiometric_twin(c: Case) -> Case:
    return dataclasses.replace(c, name=f"{c.name} [W]", light_units="radiometric")


#: every case: the photometric ones, then each again in radiometric light units
CASES: tuple[Case, ...] = (
    _BASE_CASES + _ENCLOSURE_CASES + tuple(_radiometric_twin(c) for c in _BASE_CASES)
)


# --------------------------------------------------------------------------- running


def default_configs_dir() -> Path:
    """The bundled configs folder."""
    return bundled_configs_dir(command="verify")


def _load_case(case: Case, configs_dir: Path):
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(configs_dir / case.config)
    if case.light_units is not None:
        cfg = dataclasses.replace(cfg, light_units=case.light_units)
    if case.variants:
        cfg = dataclasses.replace(cfg, variants={**cfg.variants, **dict(case.variants)})
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    return cfg, scene, sensors


def expected_values(case: Case, configs_dir: Path | None = None) -> list[tuple[Sensor, int, float, str]]:
    """Expected reading of every receiver of a case, without tracing.

    Returns
    -------
    list of (sensor, channel, expected, note)
        Channel 1 (photometric) for photometric cases, 0 (radiometric) for
        radiometric ones.
    """
    configs_dir = configs_dir or default_configs_dir()
    cfg, scene, sensors = _load_case(case, configs_dir)
    ctx = CaseContext(cfg, scene, configs_dir)
    ch = 0 if cfg.light_units == "radiometric" else 1
    return [
        (s, ch, float(case.expected(ctx, s, ch)) * _scale(case, s), case.note(ctx, s, ch) if case.note else "")
        for s in sensors
    ]


def _scale(case: Case, s: Sensor) -> float:
    """Factor from the kernel's reading to the table's: a patch's area when it reports flux."""
    return s.size[0] * s.size[1] if s.kind == SensorKind.PATCH and case.patch_flux else 1.0


def run_case(case: Case, *, quick: bool = False, device: str = "cpu", configs_dir: Path | None = None) -> list[Row]:
    """Trace one case through the normal pipeline and judge every receiver."""
    from simulator.engine.driver import Engine  # imports warp

    configs_dir = configs_dir or default_configs_dir()
    cfg, scene, sensors = _load_case(case, configs_dir)
    ctx = CaseContext(cfg, scene, configs_dir)
    ch = 0 if cfg.light_units == "radiometric" else 1
    expected = [float(case.expected(ctx, s, ch)) * _scale(case, s) for s in sensors]  # before tracing: a bad case fails fast
    notes = [case.note(ctx, s, ch) if case.note else "" for s in sensors]
    sim = cfg.simulation
    engine = Engine(scene, sensors, device=device, threads=sim.threads)
    res = engine.run(
        case.method,
        samples=FIRST_BATCH,
        seed=sim.seed,
        rel_error=max(case.rel_target, REL_TARGET_QUICK) if quick else case.rel_target,
        abs_error=0.0,
        max_samples=MAX_SAMPLES_QUICK if quick else MAX_SAMPLES,
        max_depth=sim.max_depth,
        component=sim.component,
    )
    rows = []
    for i, s in enumerate(sensors):
        scale = _scale(case, s)
        m, se = float(res.mean[i, ch]) * scale, float(res.stderr[i, ch]) * scale
        note = notes[i]
        if res.target_met is not None and not res.target_met[i]:
            note = "; ".join(x for x in (note, "error target not met") if x)
        rows.append(
            Row(case.name, s.name, _unit(s, ch, case.patch_flux), expected[i], m, se, int(res.samples[i]), res.method, judge(expected[i], m, se), note)
        )
    return rows


def run_suite(
    *,
    quick: bool = False,
    device: str = "cpu",
    configs_dir: Path | None = None,
    cases: tuple[Case, ...] | None = None,
    on_row: Callable[[Row], None] | None = None,
    on_skip: Callable[[str], None] | None = None,
) -> SuiteResult:
    """Run every case (or ``cases``); absent optional configs are skipped with a note.

    A case that cannot run (its config is missing or invalid, or a receiver
    has no closed form) gives one failing row carrying the message.

    Parameters
    ----------
    quick : bool
        Looser adaptive target (stderr ≤ 0.2% instead of 0.1%).
    device : str
        cpu, cuda or auto.
    on_row, on_skip : callable, optional
        Called with each row as its case finishes, and with each skip note.
    """
    configs_dir = Path(configs_dir) if configs_dir else default_configs_dir()
    if not configs_dir.is_dir():
        raise UserError(f"{configs_dir}: reference configs folder not found (run from a source checkout)")
    t0 = time.perf_counter()
    rows: list[Row] = []
    skipped: list[str] = []
    ran: list[str] = []
    for case in CASES if cases is None else cases:
        if quick and not case.quick:
            continue
        if not (configs_dir / case.config).exists() and case.optional:
            msg = f"skipped {case.name}: {case.config} is not in {configs_dir.name}/ yet"
            skipped.append(msg)
            if on_skip:
                on_skip(msg)
            continue
        try:
            case_rows = run_case(case, quick=quick, device=device, configs_dir=configs_dir)
        except UserError as e:  # a broken case fails its row; the others still run
            case_rows = [Row(case.name, "(case)", "", math.nan, math.nan, math.nan, 0, case.method, False, str(e))]
        ran.append(case.name)
        rows.extend(case_rows)
        if on_row:
            for r in case_rows:
                on_row(r)
    return SuiteResult(rows, skipped, ran, time.perf_counter() - t0)


# --------------------------------------------------------------------------- output

_HEADER = (
    f"{'case':<24} {'receiver':<16} {'unit':<8} {'expected':>13} {'measured':>13} "
    f"{'stderr':>9} {'error':>9} {'err/σ':>7}  {'result':<6} note"
)


def format_header() -> str:
    return _HEADER


def _g(x: float, width: int, prec: int) -> str:
    return f"{x:>{width}.{prec}g}"


def format_row(r: Row) -> str:
    pct = "—" if math.isnan(r.error_pct) else f"{r.error_pct:+.3f}%"
    sig = r.error_sigma
    if r.exact:
        sig_s = "exact"  # equal to float32 precision: a count of standard errors says nothing
    elif math.isnan(sig):
        sig_s = "—"
    else:
        sig_s = f"{sig:+.2f}" if math.isfinite(sig) else ("+inf" if sig > 0 else "-inf")
    return (
        f"{r.case[:24]:<24} {r.receiver[:16]:<16} {r.unit:<8} {_g(r.expected, 13, 8)} {_g(r.measured, 13, 8)} "
        f"{_g(r.stderr, 9, 2)} {pct:>9} {sig_s:>7}  {'pass' if r.passed else 'FAIL':<6} {r.note}"
    ).rstrip()


def format_summary(result: SuiteResult) -> str:
    n_fail = sum(not r.passed for r in result.rows)
    worst_pct = max((abs(r.error_pct) for r in result.rows if not math.isnan(r.error_pct)), default=0.0)
    finite_sig = [abs(r.error_sigma) for r in result.rows if math.isfinite(r.error_sigma) and not r.exact]
    worst_sig = max(finite_sig, default=0.0)
    verdict = "all pass" if n_fail == 0 else f"{n_fail} FAIL"
    n_exact = sum(r.exact for r in result.rows)
    skipped = f", {len(result.skipped)} skipped" if result.skipped else ""
    return (
        f"{len(result.rows) - n_fail} of {len(result.rows)} readings pass ({verdict}); "
        f"{len(result.cases_run)} cases run{skipped}; worst error {worst_pct:.3f}%, "
        f"worst {worst_sig:.2f} standard errors ({n_exact} readings exact to float32 precision); "
        f"{result.wall_s:.1f} s. "
        f"Pass: within {100 * REL_TOL:g}% and within {K_SIGMA:g}·stderr + {FLOAT32_SLACK:g}·|expected|."
    )


_CSV_COLUMNS = (
    "case", "receiver", "unit", "expected", "measured", "stderr", "error_pct", "error_stderrs",
    "exact_float32", "pass", "samples", "method", "note",
)  # fmt: skip


def csv_text(rows: list[Row]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(_CSV_COLUMNS)
    for r in rows:
        w.writerow([
            r.case, r.receiver, r.unit, f"{r.expected:.12g}", f"{r.measured:.12g}", f"{r.stderr:.6g}",
            "" if math.isnan(r.error_pct) else f"{r.error_pct:.6g}", f"{r.error_sigma:.6g}",
            "true" if r.exact else "false", "true" if r.passed else "false", r.samples, r.method, r.note,
        ])  # fmt: skip
    return buf.getvalue()


def write_csv(path: Path, rows: list[Row]) -> None:
    """Write the table as CSV atomically (temporary sibling, then rename)."""
    from simulator.io.results import _atomic_write_all

    _atomic_write_all({Path(path): csv_text(rows)})
