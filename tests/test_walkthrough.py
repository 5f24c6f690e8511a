"""The README's walkthrough room (stages/walkthrough_room.usda, configs/walkthrough.toml) runs and reads right.

The room is written by hand in the README; these tests keep its files working:
a cheap run of the bundled config gives finite readings with a standard error
on every sensor, and the floor photometer in the patch of sun reads what the
sun and the sky through the pane give it.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np

import simulator
from simulator.config import apply_overrides, load_config
from simulator.reference.closed_forms import polygon_irradiance, thin_slab

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "configs" / "walkthrough.toml"

# the stage's values (stages/walkthrough_room.usda)
SUN_LX = 60000.0  # normalized DistantLight: illuminance normal to the beam
SUN_ELEVATION_DEG = 35.0  # rotateX 55: from due south (-Y)
SKY_CD_M2 = 3000.0  # uniform DomeLight
PANE_T0, PANE_IOR = 0.7, 1.52
WINDOW_X, WINDOW_Z = (1.5, 3.5), (0.9, 2.1)  # in the wall y = 0, facing +Y
PANEL_LM, PANEL_SIDE_M, PANEL_CENTRE = 3000.0, 0.6, (2.5, 2.5, 2.79)  # RectLight facing down
# the config's floor photometer: centre, half sides (x, y)
PATCH_C, PATCH_HALF = np.array([2.5, 1.8, 0.005]), 0.15


def _rows(cfg, tmp_path: Path) -> dict:
    out = simulator.run(apply_overrides(cfg, csv=tmp_path / "walk.csv"), log=lambda m: None)
    return {r.sensor.name: r for r in out.rows}


def _gauss(a: float, b: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (a + b), 0.5 * (b - a) * w


def direct_patch_illuminance_lx() -> tuple[float, float, float]:
    """(sun, sky, panel) direct illuminance averaged over the floor photometer, lx.

    Sun: E⊥·sin h·T(θ), the patch wholly in the sunlit spot (its edges lie
    ≥ 0.36 m from the spot's), h the elevation and θ = the beam's incidence on
    the vertical pane, cos θ = cos h (the sun due south, the pane facing it);
    T the datasheet pane's thin-slab transmittance (docs/REFERENCES.md §Thin slab).
    Sky: the uniform dome's light straight through the pane, averaged over the patch,
    (1/A_p)∫_patch ∫_window L·T(θ_w)·cos θ_p·cos θ_w / r² dA_w dA_p, by Gauss–Legendre
    quadrature (16 points per axis: a smooth integrand, error far below 1e-4 relative).
    Every direction from the floor through the window rises, so the ground (which hides
    the dome below the horizon) takes no part.
    Panel: a one-sided Lambertian square of luminance Φ/(π·A) (``probesim:flux_lm`` = 3000),
    read by Lambert's contour formula at the same quadrature points
    (docs/REFERENCES.md §Lambert's polygon formula).
    """
    h = math.radians(SUN_ELEVATION_DEG)
    _, t_sun = thin_slab(math.cos(h), PANE_IOR, PANE_T0)
    sun = SUN_LX * math.sin(h) * float(t_sun)
    px, pwx = _gauss(PATCH_C[0] - PATCH_HALF, PATCH_C[0] + PATCH_HALF, 16)
    py, pwy = _gauss(PATCH_C[1] - PATCH_HALF, PATCH_C[1] + PATCH_HALF, 16)
    wx, wwx = _gauss(*WINDOW_X, 16)
    wz, wwz = _gauss(*WINDOW_Z, 16)
    P = np.stack(np.meshgrid(px, py, indexing="ij"), -1).reshape(-1, 2)
    PW = np.outer(pwx, pwy).ravel()
    W = np.stack(np.meshgrid(wx, wz, indexing="ij"), -1).reshape(-1, 2)
    WW = np.outer(wwx, wwz).ravel()
    dx = W[None, :, 0] - P[:, None, 0]
    dy = 0.0 - P[:, None, 1]
    dz = W[None, :, 1] - PATCH_C[2]
    r2 = dx * dx + dy * dy + dz * dz
    r = np.sqrt(r2)
    cos_p, cos_w = dz / r, -dy / r
    _, t = thin_slab(cos_w, PANE_IOR, PANE_T0)
    inner = (SKY_CD_M2 * t * cos_p * cos_w / r2) @ WW
    area = (2 * PATCH_HALF) ** 2
    sky = float(inner @ PW) / area
    h2, (cx, cy, cz) = PANEL_SIDE_M / 2, PANEL_CENTRE
    square = np.array([[cx - h2, cy - h2, cz], [cx + h2, cy - h2, cz], [cx + h2, cy + h2, cz], [cx - h2, cy + h2, cz]])
    lum = PANEL_LM / (math.pi * PANEL_SIDE_M**2)
    pts = np.column_stack([P, np.full(len(P), PATCH_C[2])])
    up, down = np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0])
    e_panel = polygon_irradiance(lum, square, pts, up, one_sided_normal=down)
    panel = float(np.asarray(e_panel) @ PW) / area
    return sun, sky, panel


def test_the_walkthrough_room_runs_with_an_error_bar_on_every_reading(tmp_path):
    """The bundled walkthrough at 64 samples: every sensor (the desk grid, the floor patch, the wall
    sensor) reads a finite, positive illuminance with a standard error above 0, and the sunlit patch
    reads at least its direct sun, sky and panel (light reflected in the room only adds to it)."""
    cfg = apply_overrides(load_config(CONFIG), samples=64, seed=3)
    rows = _rows(cfg, tmp_path)
    assert len(rows) == 32 + 2 and sum(n.startswith("desk[") for n in rows) == 32
    for name, r in rows.items():
        e, s = r.values["illuminance_lx"], r.values["illuminance_stderr_lx"]
        assert math.isfinite(e) and e > 0.0 and math.isfinite(s) and s > 0.0, (name, e, s)
    sun, sky, panel = direct_patch_illuminance_lx()
    patch = rows["sun_patch"].values
    assert patch["illuminance_lx"] > sun + sky + panel - 4.0 * patch["illuminance_stderr_lx"]


def test_the_sunlit_floor_patch_reads_the_sun_and_sky_through_the_pane(tmp_path):
    """Direct light only (``component = "direct"``): the floor photometer reads
    E⊥·sin h·T(θ) of the sun, the sky's light through the pane and the ceiling
    panel's (see :func:`direct_patch_illuminance_lx`) within 4 standard errors,
    plus 2e-4 relative (the sun's 0.53° disc: its mean of cos·T differs from its
    centre's by ~2e-5; float32 arithmetic; the quadrature). 23.4 klx of sun,
    0.38 klx of sky (11σ at this budget), 0.11 klx of panel (3σ): a pane left out
    (T = 1) would read 47% high, a pane read as clear glass 34% high, the sky missed
    1.6% low, a sun from the wrong side 0."""
    cfg = apply_overrides(load_config(CONFIG), samples=1024, seed=5)
    cfg = dataclasses.replace(cfg, simulation=dataclasses.replace(cfg.simulation, component="direct"))
    r = _rows(cfg, tmp_path)["sun_patch"]
    e, s = r.values["illuminance_lx"], r.values["illuminance_stderr_lx"]
    sun, sky, panel = direct_patch_illuminance_lx()
    expected = sun + sky + panel
    assert s > 0.0
    assert abs(e - expected) <= 4.0 * s + 2e-4 * expected, (e, s, sun, sky, panel)
