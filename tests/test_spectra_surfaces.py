"""Coloured metals and coloured glass in spectral runs: the BSDF and the pane per hero wavelength.

Closed forms (written out here; ρ(λ) the Mallett–Yuksel uplift of the
diffuseColor, simulator.spectra.reflectance.uplift, tested on its own):

- a metallic-1 mirror (roughness 0) has F0 = F90 = ρ(λ), so it reflects
  ρ(λ) at every angle; a point light of intensity I (photometric, spectrum
  S(λ)) seen in it by a down-facing sensor reads, from the image source at
  distance d and incidence cosine cosθ,

      E_v = (I cosθ / d²) · ∫ S ρ V dλ / ∫ S V dλ;

- a pane given by a measured normal-incidence transmittance T0(λ) (a CSV) is
  the absorbing slab of that T0 per wavelength: at normal incidence it passes
  exactly T0(λ), at θ the slab of τ0(λ) (the quadratic t0 r² τ² + (1 − r)² τ −
  t0 = 0, r = ((n − 1)/(n + 1))²), with τ(θ) = τ0^(1/cos θ_t); under a
  zero-angle sun of normal illuminance E it reads E cosθ ∫ S T(θ, λ) V / ∫ S V;
  a radiance meter looking up through it at a uniform sky of luminance L,
  over a black floor, reads L ∫ S T0 V / ∫ S V.

Integrals on the 1 nm grid (trapezoid, the responses' quadrature). Readings
carry the hero wavelengths' noise: held within 4 standard errors at fixed
seeds.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.errors import UserError
from simulator.pipeline import run
from simulator.scene.usd import load_stage
from simulator.spectra import responses as R
from simulator.spectra.grid import WAVELENGTHS_NM
from simulator.spectra.reflectance import uplift
from tests.test_surfaces import material, quad, slab, stage

GOLD = (1.0, 0.766, 0.336)  # linear sRGB
T_CCT = 3000.0  # K, the lights' spectrum ([spectra] lights)


def planck(t_k: float) -> np.ndarray:
    """Planck's law on the grid, relative: λ⁻⁵ / (exp(c₂/(λT)) − 1), c₂ = 1.4388e-2 m·K."""
    lam = WAVELENGTHS_NM * 1e-9
    return lam ** -5 / np.expm1(1.4388e-2 / (lam * t_k))


def v_weighted(f: np.ndarray) -> float:
    """∫ S f V dλ / ∫ S V dλ with S the 3000 K Planckian (the photopic response's quadrature)."""
    s = planck(T_CCT)
    return float(R.response("photopic").of(s * f) / R.response("photopic").of(s))


def config(tmp_path: Path, stage_path: Path, sensors: str, method: str, samples: int, seed: int = 3) -> Path:
    p = tmp_path / "run.toml"
    p.write_text(f'stage = "{stage_path.as_posix()}"\nlight_units = "photometric"\n[simulation]\n'
                 f'method = "{method}"\nsamples = {samples}\nseed = {seed}\n[spectra]\nlights = {T_CCT:g}\n'
                 f'{sensors}\n[output]\ncsv = "out/run.csv"\n')
    return p


def readings(out) -> dict:
    with open(out.csv_path, newline="") as f:
        return {r["sensor"]: r for r in csv.DictReader(f)}


def lx(row: dict) -> tuple[float, float]:
    return float(row["illuminance_lx"]), float(row["illuminance_stderr_lx"])


POINT = ('def SphereLight "Lamp"\n{\n    float inputs:intensity = 100\n    float inputs:radius = 0.1\n'
         '    bool treatAsPoint = 1\n    float3 xformOp:translate = (0, 0, 2)\n'
         '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
DOWN = '[[sensor]]\nname = "down"\nkind = "irradiance"\nposition = [0.5, 0, 1]\nnormal = [0, 0, -1]\n'


def gold_mirror(tmp_path: Path, rgb=GOLD) -> Path:
    body = material("Mirror", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=1.0)
    body = body.replace("color3f inputs:diffuseColor = (1.0, 1.0, 1.0)",
                        f"color3f inputs:diffuseColor = ({rgb[0]}, {rgb[1]}, {rgb[2]})")
    return stage(tmp_path, body + quad("Floor", 0.0, "Mirror", half=50) + POINT)


def test_a_gold_mirror_reflects_the_lamps_image_in_its_colour(tmp_path):
    """A gold mirror (metallic 1, roughness 0) 2 m below a 3000 K point lamp of I cd; a down-facing
    sensor 1 m up, 0.5 m aside, sees only the image 2 m below the mirror: E_v = I cosθ/d² · ∫SρV/∫SV,
    within 4 standard errors (the wavelengths' noise), and below the grey reading (ρ's luminance)."""
    path = gold_mirror(tmp_path)
    out = run(load_config(config(tmp_path, path, DOWN, "path", 4000)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "spectral"
    intensity = out.scene.lights[0].emission[1]
    d = np.array([0.5, 0.0, 1.0]) - np.array([0.0, 0.0, -2.0])
    geometric = intensity * (d[2] / np.linalg.norm(d)) / float(d @ d)
    truth = geometric * v_weighted(uplift(np.array(GOLD)))
    e, se = lx(readings(out)["down"])
    assert se > 0 and abs(e - truth) <= 4 * se, (e, se, truth)
    assert abs(e - truth) <= 0.01 * truth


def test_a_white_mirror_in_a_spectral_run_reflects_the_whole_image(tmp_path):
    """The same mirror white (ρ = 1 at every wavelength) in a run made spectral by a small red matte
    patch 30 m up (the light it sends back is below 1e-6 of the image's): I cosθ/d² within 4 standard
    errors (the wavelengths' noise alone)."""
    body = material("Mirror", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=1.0)
    body += material("Red").replace("(0.5, 0.5, 0.5)", "(0.8, 0.1, 0.1)")
    body += quad("Floor", 0.0, "Mirror", half=50) + quad("Patch", 30.0, "Red", half=0.1) + POINT
    path = stage(tmp_path, body)
    out = run(load_config(config(tmp_path, path, DOWN, "path", 4000)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "spectral"
    intensity = out.scene.lights[0].emission[1]
    d = np.array([0.5, 0.0, 1.0]) - np.array([0.0, 0.0, -2.0])
    truth = intensity * (d[2] / np.linalg.norm(d)) / float(d @ d)
    e, se = lx(readings(out)["down"])
    assert se > 0 and abs(e - truth) <= 4 * se, (e, se, truth)


# --------------------------------------------------------------------------- #
# coloured glass through a transmittance CSV
# --------------------------------------------------------------------------- #

BRONZE = ((380, 0.30), (480, 0.45), (580, 0.70), (680, 0.80), (780, 0.82))  # T0(λ) of a tinted pane


def write_curve(path: Path, rows=BRONZE, column: str = "transmittance") -> Path:
    path.write_text(f"# a tinted pane\nwavelength_nm,{column}\n" + "".join(f"{w},{v}\n" for w, v in rows))
    return path


def t0_curve(rows=BRONZE) -> np.ndarray:
    w, v = np.array(rows, float).T
    return np.interp(WAVELENGTHS_NM, w, v)


def tau0(t0: np.ndarray, n: float) -> np.ndarray:
    """τ0 per wavelength from T0 (the positive root of t0 r² τ² + (1 − r)² τ − t0 = 0)."""
    r = ((n - 1) / (n + 1)) ** 2
    a, b = t0 * r * r, (1 - r) ** 2
    return (-b + np.sqrt(b * b + 4 * a * t0)) / (2 * a)


def sun(zenith: float) -> str:
    return (f'def DistantLight "Sun"\n{{\n    float inputs:intensity = 1000\n    float inputs:angle = 0\n'
            f'    float3 xformOp:rotateXYZ = ({zenith}, 0, 0)\n    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n}}\n')


def tinted(tmp_path: Path, extra: str = "") -> str:
    write_curve(tmp_path / "bronze.csv")
    return material("G", f"float inputs:ior = 1.52\n        asset probesim:transmittance = @bronze.csv@{extra}")


UP = '[[sensor]]\nname = "up"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'


def test_the_reader_keeps_the_curve_and_its_grey(tmp_path):
    """``asset probesim:transmittance``: the row is an absorbing pane whose T0 is the curve's D65-luminance
    grey ∫T D65 ȳ/∫D65 ȳ, the curve kept for spectral runs; the plan names it."""
    from simulator.spectra.reflectance import reflectance_grey

    g = load_stage(stage(tmp_path, tinted(tmp_path) + quad("Pane", 1.0, "G") + sun(0))).geometry
    row = g.surfaces[0]
    assert row.pane and row.transmittance_spectrum[0] == "bronze.csv"
    np.testing.assert_allclose(row.transmittance_spectrum[1], t0_curve(), atol=1e-12)
    assert row.transmittance == pytest.approx(reflectance_grey(t0_curve()), rel=1e-12)
    assert any("from bronze.csv" in part for part in row.lobes())


@pytest.mark.parametrize("zenith", [0.0, 60.0])
def test_a_tinted_pane_passes_its_spectral_transmittance_of_the_sun(tmp_path, zenith):
    """Under the tinted pane (ior 1.52) and a zero-angle 3000 K sun: E cosθ ∫S T(θ, λ) V/∫S V, the slab of
    τ0(λ) at θ (T0(λ) at normal incidence), within 4 standard errors; the grey reading (the curve's D65
    grey) differs by more than that."""
    path = stage(tmp_path, tinted(tmp_path) + quad("Pane", 1.0, "G", half=50) + sun(zenith))
    out = run(load_config(config(tmp_path, path, UP, "light", 4000)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "spectral"
    c = math.cos(math.radians(zenith))
    taus = tau0(t0_curve(), 1.52)
    t = np.array([slab(c, 1.52, float(tau))[1] for tau in taus])
    truth = 1000.0 * c * v_weighted(t)
    e, se = lx(readings(out)["up"])
    assert se > 0 and abs(e - truth) <= 4 * se, (e, se, truth)
    grey = 1000.0 * c * slab(c, 1.52, float(tau0(np.array([out.scene.geometry.surfaces[0].transmittance]), 1.52)[0]))[1]
    assert abs(grey - truth) > 4 * se


def test_a_meter_sees_the_sky_through_the_tinted_pane(tmp_path):
    """A radiance meter under the tinted pane looking straight up at a uniform 3000 K sky of L cd/m², a
    black floor below (what the pane reflects is lost): L ∫S T0 V/∫S V within 4 standard errors (the
    pass, reflect or absorb draws per path and the wavelengths)."""
    body = tinted(tmp_path) + material("Black", rho=0.0) + quad("Pane", 1.0, "G", half=1e3)
    body += quad("Floor", -1.0, "Black", half=1e3) + 'def DomeLight "Sky"\n{\n    float inputs:intensity = 100\n}\n'
    meter = ('[[sensor]]\nname = "sky"\nkind = "radiance"\nposition = [0, 0, 0]\ndirection = [0, 0, 1]\n'
             'half_angle_deg = 0\n')
    out = run(load_config(config(tmp_path, stage(tmp_path, body), meter, "bsdf", 20000)), log=lambda *a: None)
    row = readings(out)["sky"]
    v, se = float(row["luminance_cd_m2"]), float(row["luminance_stderr_cd_m2"])
    truth = 100.0 * v_weighted(t0_curve())
    assert se > 0 and abs(v - truth) <= 4 * se, (v, se, truth)


@pytest.mark.parametrize("rows, needle", [
    (((380, 0.3), (780, 1.2)), "outside [0, 1]"),
    (((380, 0.3), (780, 0.95)), "above the 0.9183"),
])
def test_a_bad_curve_is_one_line_naming_the_file(tmp_path, rows, needle):
    """A value outside [0, 1] (named on the shader that authors it), or a peak above what a clear slab of
    the ior transmits (on the prim the pane is read for, as the other pane inputs): one line naming the
    prim, the attribute and the file."""
    write_curve(tmp_path / "bronze.csv", rows)
    body = material("G", "float inputs:ior = 1.52\n        asset probesim:transmittance = @bronze.csv@")
    with pytest.raises(UserError) as e:
        load_stage(stage(tmp_path, body + quad("Pane", 1.0, "G")))
    msg = str(e.value)
    assert ("/G/S" in msg or "/Pane" in msg) and "probesim:transmittance" in msg and "bronze.csv" in msg and needle in msg, msg
    assert "\n" not in msg


def test_a_missing_curve_is_one_line(tmp_path):
    body = material("G", "float inputs:ior = 1.52\n        asset probesim:transmittance = @nowhere.csv@")
    with pytest.raises(UserError, match=r"probesim:transmittance: .*nowhere\.csv"):
        load_stage(stage(tmp_path, body + quad("Pane", 1.0, "G")))


def test_grey_glass_and_a_grey_mirror_trace_grey(tmp_path):
    """A flat transmittance curve and a grey mirror leave the run grey (one channel, exact post hoc)."""
    write_curve(tmp_path / "flat.csv", ((380, 0.7), (780, 0.7)))
    body = material("G", "float inputs:ior = 1.52\n        asset probesim:transmittance = @flat.csv@")
    body += quad("Pane", 1.0, "G") + sun(0)
    out = run(load_config(config(tmp_path, stage(tmp_path, body), UP, "light", 64)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "grey"
    e, _ = lx(readings(out)["up"])
    assert abs(e - 700.0) <= 2e-6 * 700.0


@pytest.mark.parametrize("method", ["path", "guided"])
def test_a_rough_gold_floor_reflects_the_sky_in_its_colour(tmp_path, method):
    """A rough gold metal floor (metallic 1, roughness 0.3: F0 = F90 = ρ(λ), so f = ρ(λ)·f₁ with f₁ the
    white metal's BSDF) under a uniform 3000 K sky of luminance L; a radiance meter looking down at
    it 60° from the normal reads L·A₁(cos 60°)·∫SρV/∫SV, A₁ the white metal's directional albedo (the
    quadrature of simulator.reference.microfacet), within 4 standard errors: light samples and BSDF
    directions at the glossy vertex, each weighed per wavelength (plain and guided paths)."""
    from simulator.reference.microfacet import directional_albedo, preview_lobes

    body = material("F", "float inputs:roughness = 0.3\n        float inputs:metallic = 1", rho=1.0)
    body = body.replace("color3f inputs:diffuseColor = (1.0, 1.0, 1.0)",
                        f"color3f inputs:diffuseColor = ({GOLD[0]}, {GOLD[1]}, {GOLD[2]})")
    body += quad("Floor", 0.0, "F", half=1e4) + 'def DomeLight "Sky"\n{\n    float inputs:intensity = 100\n}\n'
    t = math.radians(60.0)
    meter = ('[[sensor]]\nname = "m"\nkind = "radiance"\nposition = [0, 0, 1]\n'
             f'direction = [0, {math.sin(t)!r}, {-math.cos(t)!r}]\n')
    out = run(load_config(config(tmp_path, stage(tmp_path, body), meter, method, 20000)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "spectral"
    row = readings(out)["m"]
    v, se = float(row["luminance_cd_m2"]), float(row["luminance_stderr_cd_m2"])
    truth = 100.0 * directional_albedo(preview_lobes(1.0, 0.3, 1.0, 1.5, None, 0.0, 0.2), math.cos(t))
    truth *= v_weighted(uplift(np.array(GOLD)))
    assert se > 0 and abs(v - truth) <= 4 * se, (v, se, truth)


def test_a_lamp_below_the_tinted_pane_is_seen_untinted(tmp_path):
    """The meter of the sky test with a rect light (50 cd/m², facing down at it) between it and the
    pane: UsdLux lights do not block, so it reads the lamp whole plus the sky through the pane,
    50 + L ∫S T0 V/∫S V, within 4 standard errors (the lamp is met before the pane on each ray)."""
    body = tinted(tmp_path) + material("Black", rho=0.0) + quad("Pane", 1.0, "G", half=1e3)
    body += quad("Floor", -1.0, "Black", half=1e3) + 'def DomeLight "Sky"\n{\n    float inputs:intensity = 100\n}\n'
    body += ('def RectLight "Lamp"\n{\n    float inputs:intensity = 50\n    float inputs:width = 1\n'
             '    float inputs:height = 1\n    float3 xformOp:translate = (0, 0, 0.5)\n'
             '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    meter = ('[[sensor]]\nname = "sky"\nkind = "radiance"\nposition = [0, 0, 0]\ndirection = [0, 0, 1]\n')
    out = run(load_config(config(tmp_path, stage(tmp_path, body), meter, "bsdf", 20000)), log=lambda *a: None)
    row = readings(out)["sky"]
    v, se = float(row["luminance_cd_m2"]), float(row["luminance_stderr_cd_m2"])
    truth = 50.0 + 100.0 * v_weighted(t0_curve())
    assert se > 0 and abs(v - truth) <= 4 * se, (v, se, truth)


def test_guided_and_plain_paths_agree_through_a_tinted_pane(tmp_path):
    """A lamp between the tinted pane (z = 1 m) and a matte ceiling (z = 3 m, albedo 0.7); an up-facing
    sensor under the pane sees the lamp and the lit ceiling through it. Plain paths (each ray through
    the pane per lane) and guided paths (guided segments through the pane take its lanes too) are two
    unbiased estimates of the same reading: they agree within 4 combined standard errors."""
    body = tinted(tmp_path) + material("Ceil", rho=0.7) + quad("Pane", 1.0, "G", half=5)
    body += quad("Ceiling", 3.0, "Ceil", half=5)
    body += ('def SphereLight "Lamp"\n{\n    float inputs:intensity = 1000\n    float inputs:radius = 0.05\n'
             '    float3 xformOp:translate = (0, 0, 2)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    path = stage(tmp_path, body)
    got = {}
    for method in ("path", "guided"):
        out = run(load_config(config(tmp_path, path, UP, method, 20000)), log=lambda *a: None)
        got[method] = lx(readings(out)["up"])
        if method == "guided":
            assert out.record["guide"]["reason"].endswith("used"), out.record["guide"]
    (a, sa), (b, sb) = got["path"], got["guided"]
    assert sa > 0 and sb > 0 and abs(a - b) <= 4 * math.hypot(sa, sb), got
