"""Spectra a stage names: a material's measured reflectance (``probesim:reflectance``) and a light's own
spectrum (``probesim:spectrum``), read by the stage reader and traced by whole runs.

The furnace (stages/furnace.usda, docs/REFERENCES.md §Furnace): a closed box
whose walls all emit L_e(λ) and reflect diffusely with albedo ρ(λ); inside it
the radiance is L_e(λ)/(1 − ρ(λ)) at every wavelength, so an irradiance
sensor reads, for a response with quadrature vector q
(simulator.spectra.responses),

    R_E = π ∫ q(λ) L_e(λ) / (1 − ρ(λ)) dλ,

with L_e D65 scaled to 1 W m⁻² sr⁻¹ over 380–780 nm (the stage's
``light_units = "radiometric"``, ``radiometric_spectrum = "D65"``). A flat
ρ = 0.5 gives 2π W/m². The measured "red" paint here is 0.1 up to 560 nm,
0.8 from 620 nm, linear between (the file's rows; the reader interpolates
linearly and holds the end values beyond 400–700 nm).
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
from simulator.spectra import responses as R, sources
from simulator.spectra.grid import WAVELENGTHS_NM

ROOT = Path(__file__).resolve().parents[1]
RED_ROWS = ((400, 0.1), (560, 0.1), (620, 0.8), (700, 0.8))
NAMES = ("photopic", "par", "melanopic_edi")


def _write_curve(path: Path, rows, column: str = "reflectance") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"# measured paint\nwavelength_nm,{column}\n" + "".join(f"{w},{v}\n" for w, v in rows))
    return path


def _furnace(tmp_path: Path, rows, name: str = "paint.csv", stem: str = "furnace_measured") -> Path:
    """stages/furnace.usda in ``tmp_path/stage/`` whose wall shader names ``spectra/<name>`` (relative to
    the stage's layer, next to it) beside its diffuseColor 0.5."""
    text = (ROOT / "stages" / "furnace.usda").read_text()
    grey = "color3f inputs:diffuseColor = (0.5, 0.5, 0.5)"
    assert text.count(grey) == 1
    p = tmp_path / "stage" / f"{stem}.usda"
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(text.replace(grey, grey + f"\n                        asset probesim:reflectance = @spectra/{name}@"))
    if rows is not None:
        _write_curve(p.parent / "spectra" / name, rows)
    return p


def _config(tmp_path: Path, stage: Path, samples: int, seed: int = 5, extra: str = "") -> Path:
    p = tmp_path / "cfg" / "furnace.toml"  # another folder: the curve resolves against the stage, not this
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(f'''stage = "{stage.as_posix()}"
light_units = "radiometric"
radiometric_spectrum = "D65"
variants = {{ reflectance = "rho_0_5" }}

[simulation]
method = "path"
samples = {samples}
seed = {seed}
{extra}
[[sensor]]
name = "up"
kind = "irradiance"
position = [0, 0, 1.25]
normal = [0, 0, 1]

[output]
csv = "out/furnace.csv"
responses = ["par", "melanopic_edi"]
''')
    return p


def _rho(rows) -> np.ndarray:
    """The file's rows on the grid: linear inside, end values held outside."""
    w, v = np.array(rows, float).T
    return np.interp(WAVELENGTHS_NM, w, v)


def _truth_E(name: str, rho: np.ndarray) -> float:
    """π ∫ q L_e/(1 − ρ) dλ on the grid (trapezoid rule), L_e = D65 at 1 W m⁻² sr⁻¹."""
    d65 = sources.cie_illuminant("D65")
    return math.pi * float(R.response(name).of(d65.values / d65.radiometric / (1.0 - rho)))


def _read(row: dict, name: str) -> tuple[float, float]:
    if name == "photopic":
        return float(row["illuminance_lx"]), float(row["illuminance_stderr_lx"])
    col, col_se = R.response(name).columns("irradiance")
    return float(row[col]), float(row[col_se])


def _rows(out) -> dict:
    with open(out.csv_path, newline="") as f:
        return {r["sensor"]: r for r in csv.DictReader(f)}


def test_a_flat_measured_curve_reads_like_the_grey_furnace(tmp_path):
    """A wall material naming a measured flat 0.5 curve (``probesim:reflectance``, a file beside the stage's
    layer): its albedo is exactly 0.5, the transport stays grey (one channel, responses post hoc), and the
    sensor reads π L_e/(1 − 0.5) = 2π W/m² within 4 standard errors (3000 samples); the diffuseColor beside
    the curve is named as ignored."""
    stage = _furnace(tmp_path, ((380, 0.5), (780, 0.5)))
    out = run(load_config(_config(tmp_path, stage, samples=3000)), log=lambda *a: None)
    assert np.all(out.scene.geometry.albedo == 0.5)
    assert out.record["plan"]["transport"] == "grey"
    row = _rows(out)["up"]
    e, se = float(row["irradiance_W_m2"]), float(row["irradiance_stderr_W_m2"])
    assert se > 0 and abs(e - 2 * math.pi) <= 4 * se, (e, se)
    assert any("inputs:diffuseColor beside probesim:reflectance" in w for w in out.record["warnings"])


@pytest.fixture(scope="module")
def red_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("measured_red")
    out = run(load_config(_config(tmp, _furnace(tmp, RED_ROWS), samples=4000)), log=lambda *a: None)
    return out, _rows(out)["up"]


def test_a_measured_red_curve_reads_the_spectral_closed_form(red_run):
    """The red paint: the plan traces hero wavelengths (a measured curve that is not flat), the hero tables
    carry the curve as a reflectance row every wall face uses, the albedo is its D65-luminance grey
    ∫ρ D65 ȳ/∫D65 ȳ, and illuminance, PPFD and melanopic EDI lie within 4 standard errors of
    π ∫ q L_e/(1 − ρ) dλ (4000 samples, seed 5)."""
    from simulator.spectra import tables

    out, row = red_run
    assert out.record["plan"]["transport"] == "spectral"
    assert out.record["spectra"]["measured_reflectances"] == ["paint.csv"]
    assert "measured reflectance paint.csv is not flat" in str(out.record["plan"])
    rho = _rho(RED_ROWS)
    w = tables.illuminant("D65") * tables.cmfs_1931()[1]
    grey = float(np.trapezoid(rho * w, WAVELENGTHS_NM) / np.trapezoid(w, WAVELENGTHS_NM))
    assert np.allclose(out.scene.geometry.albedo, grey, rtol=1e-12)
    g = out.scene.geometry
    assert len(g.reflectances) == 1 and np.allclose(g.reflectances[0][1], rho, atol=1e-12)
    for name in NAMES:
        mean, se = _read(row, name)
        truth = _truth_E(name, rho)
        assert se > 0 and abs(mean - truth) <= 4 * se + 1e-6 * truth, (name, mean, truth, se)


def test_the_hero_tables_hold_the_measured_row(red_run):
    """``hero_tables`` appends the measured curve after the uplifted colours and points every wall face at
    it (the furnace's walls are its only faces), so the device reads ρ(λ) of the file."""
    from simulator.spectra.hero import hero_tables

    out, _ = red_run
    t = hero_tables(out.scene, "radiometric", "D65")
    assert t.reflectance.shape[0] == 2  # the walls' grey uplift (unused), then the measured row
    assert np.all(t.face_reflectance == 1)
    assert np.allclose(t.reflectance[1], _rho(RED_ROWS), atol=1e-12)


def test_an_adaptive_run_of_the_red_furnace_meets_every_response_target(tmp_path):
    """With ``rel_error = 0.02`` the run stops only once every reported column (W, lux, PPFD, melanopic
    EDI) has z·stderr ≤ 0.02·|value| (z = 1.96): each does, the sensor says target_met, and the PPFD lies
    within 4 standard errors of its closed form. (Stopping on W and lux alone, this seed's melanopic EDI
    stops at z·stderr = 2.1 % of its value.)"""
    stage = _furnace(tmp_path, RED_ROWS)
    extra = "rel_error = 0.02\nmax_samples = 200000\ntime_limit_s = 300\n"
    out = run(load_config(_config(tmp_path, stage, samples=256, seed=9, extra=extra)), log=lambda *a: None)
    row = _rows(out)["up"]
    assert row["target_met"].lower() in ("true", "1", "yes")
    z = 1.959963984540054
    for col, col_se in (("irradiance_W_m2", "irradiance_stderr_W_m2"), ("illuminance_lx", "illuminance_stderr_lx"),
                        R.response("par").columns("irradiance"), R.response("melanopic_edi").columns("irradiance")):
        v, se = float(row[col]), float(row[col_se])
        assert se > 0 and z * se <= 0.02 * abs(v) * (1 + 1e-9), (col, v, se)
    v, se = _read(row, "par")
    assert abs(v - _truth_E("par", _rho(RED_ROWS))) <= 4 * se


def test_a_bad_curve_is_one_line_naming_the_file_and_row(tmp_path):
    """A row outside [0, 1), a missing file and a wrong header are each one UserError line naming the stage,
    the material's shader prim and the file (with the line number for a bad row)."""
    stage = _furnace(tmp_path, ((400, 0.2), (500, 1.3), (700, 0.5)))
    with pytest.raises(UserError) as e:
        load_stage(stage, light_units="radiometric", radiometric_spectrum="D65", variants={"reflectance": "rho_0_5"})
    msg = str(e.value)
    assert "\n" not in msg and "paint.csv:4:" in msg and "/World/Looks/Wall/Surface" in msg and "probesim:reflectance" in msg
    with pytest.raises(UserError, match=r"stage/spectra/missing\.csv: no such file") as e:
        load_stage(_furnace(tmp_path, None, "missing.csv", "other"), light_units="radiometric",
                   radiometric_spectrum="D65")
    assert "\n" not in str(e.value)
    _write_curve(tmp_path / "stage" / "spectra" / "paint.csv", RED_ROWS, column="albedo")
    with pytest.raises(UserError, match=r"paint\.csv:2: reflectance column 'albedo'"):
        load_stage(stage, light_units="radiometric", radiometric_spectrum="D65")


def test_a_curve_short_of_the_grid_is_held_and_warned(tmp_path):
    """A file covering 450–650 nm only: its end values are held to 380 and 780 nm, with one warning
    naming the file's range."""
    stage = _furnace(tmp_path, ((450, 0.3), (650, 0.6)))
    scene = load_stage(stage, light_units="radiometric", radiometric_spectrum="D65")
    rho = scene.geometry.reflectances[0][1]
    assert rho[0] == pytest.approx(0.3, abs=1e-12) and rho[-1] == pytest.approx(0.6, abs=1e-12)
    assert any("paint.csv covers 450–650 nm" in w for w in scene.warnings)


# ------------------------------------------------------------------ a light's own spectrum

_LAMPS = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
)

def Xform "World"
{
    def SphereLight "Incandescent"
    {
        float inputs:intensity = 400
        bool inputs:normalize = 1
        bool treatAsPoint = 1
        string probesim:spectrum = "A"
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Daylight"
    {
        float inputs:intensity = 800
        bool inputs:normalize = 1
        bool treatAsPoint = 1
        double3 xformOp:translate = (0, 0, -2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""


def test_a_lamp_names_its_own_spectrum_beside_the_run_wide_one(tmp_path):
    """Two point lamps on either side of the origin, one naming ``probesim:spectrum = "A"``, the other
    following the run's ``[spectra] lights = "D65"``; a sensor facing each sees only its lamp.
    Intensities stay the authored quantity: 100 cd and 200 cd at 2 m give 25 lx and 50 lx
    (E = I/d², normalize divides by 4), and the W column is lux/K(S) with K(A) and K(D65) from the tables.
    The PPFD per lux of each, estimated by direct-light sampling (the lamps differ in spectrum), lies
    within 4 standard errors of Σq_par S/Σq_V S (CIE 015 illuminant A and D65, McCree PAR weights on the grid):
    0.01990 µmol m⁻² s⁻¹/lx for A against 0.01802 for D65, 10 % apart, so each lamp's own spectrum is used
    (Thimijan & Heins 1983 list 0.0200 for incandescent light and 0.0185 for sunlight)."""
    stage = tmp_path / "lamps.usda"
    stage.write_text(_LAMPS)
    cfg = tmp_path / "lamps.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\nlight_units = "photometric"\n\n[simulation]\nsamples = 4000\n'
                   'seed = 3\n\n[[sensor]]\nname = "toA"\nkind = "irradiance"\nposition = [0, 0, 0]\n'
                   'normal = [0, 0, 1]\n\n[[sensor]]\nname = "toD65"\nkind = "irradiance"\nposition = [0, 0, 0]\n'
                   'normal = [0, 0, -1]\n\n[spectra]\nlights = "D65"\n\n[output]\ncsv = "out/l.csv"\n'
                   'responses = ["par"]\n')
    out = run(load_config(cfg), log=lambda *a: None)
    lights = {l.name: l for l in out.scene.lights}
    assert lights["/World/Incandescent"].spectrum == "A" and lights["/World/Incandescent"].spectrum_authored
    assert out.record["plan"]["transport"] == "per-emitter"
    rows = {r.sensor.name: r.values for r in out.rows}
    for sensor, lux, spd in (("toA", 25.0, sources.cie_illuminant("A")), ("toD65", 50.0, sources.cie_illuminant("D65"))):
        v = rows[sensor]
        assert v["illuminance_lx"] == pytest.approx(lux, rel=1e-6)
        assert v["irradiance_W_m2"] == pytest.approx(lux / spd.efficacy_lm_W, rel=1e-6)
        per_lux = R.response("par").of(spd.values) / R.response("photopic").of(spd.values)
        ppfd, se = v["ppfd_umol_m2_s"], v["ppfd_stderr_umol_m2_s"]
        assert se > 0 and abs(ppfd - lux * per_lux) <= 4 * se, (sensor, ppfd, lux * per_lux, se)
    a, d = (R.response("par").of(s.values) / R.response("photopic").of(s.values)
            for s in (sources.cie_illuminant("A"), sources.cie_illuminant("D65")))
    assert a == pytest.approx(0.01990, abs=5e-5) and d == pytest.approx(0.01802, abs=5e-5)


def test_color_temperature_and_the_own_spectrum_attribute_are_read(tmp_path):
    """``colorTemperature`` counts only with ``enableColorTemperature``: a 3000 K lamp's emission pair has
    K = K(blackbody 3000 K) (lux/W), a disabled one the run's D65; ``probesim:spectrum`` wins over an enabled
    colorTemperature (warned); an SPD file it names is relative to the stage's layer; a bad name is one
    line naming the prim."""
    spd = tmp_path / "stage" / "led.csv"
    spd.parent.mkdir()
    spd.write_text("wavelength_nm,relative_spd\n400,0\n450,1\n500,0.2\n600,0.6\n700,0\n")
    body = ""
    for name, attrs in (("Warm", "bool inputs:enableColorTemperature = 1\n float inputs:colorTemperature = 3000"),
                        ("Off", "bool inputs:enableColorTemperature = 0\n float inputs:colorTemperature = 3000"),
                        ("Both", 'bool inputs:enableColorTemperature = 1\n float inputs:colorTemperature = 3000\n'
                                 ' string probesim:spectrum = "LED-B3"'),
                        ("Led", 'asset probesim:spectrum = @led.csv@')):
        body += (f'def SphereLight "{name}" {{\n float inputs:intensity = 100\n bool treatAsPoint = 1\n {attrs}\n'
                 ' double3 xformOp:translate = (0, 0, 2)\n uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    stage = tmp_path / "stage" / "t.usda"
    stage.write_text('#usda 1.0\n(\n metersPerUnit = 1\n upAxis = "Z"\n)\n' + body)
    scene = load_stage(stage, light_units="photometric")
    k = {l.name.strip("/"): l.emission[1] / l.emission[0] for l in scene.lights}
    assert k["Warm"] == pytest.approx(sources.blackbody(3000.0).efficacy_lm_W, rel=1e-4)
    assert k["Off"] == pytest.approx(sources.cie_illuminant("D65").efficacy_lm_W, rel=1e-6)
    assert k["Both"] == pytest.approx(sources.cie_illuminant("LED-B3").efficacy_lm_W, rel=1e-9)
    assert k["Led"] == pytest.approx(sources.spd_csv(spd).efficacy_lm_W, rel=1e-9)
    assert any("/Both: colorTemperature ignored" in w for w in scene.warnings)
    stage.write_text(stage.read_text().replace('"LED-B3"', '"LED-B33"'))
    with pytest.raises(UserError, match=r"/Both: probesim:spectrum: unknown illuminant 'LED-B33'") as e:
        load_stage(stage, light_units="photometric")
    assert "\n" not in str(e.value)


def test_lamps_that_all_name_one_spectrum_keep_one_channel(tmp_path):
    """Both lamps name ``probesim:spectrum = "A"`` and no ``[spectra]`` table is given: the emitters share
    one spectrum, so the run stays grey and its PPFD is exact post hoc, lux × 0.019898 µmol m⁻² s⁻¹/lx
    (illuminant A's PAR per lux on the grid), with the W column lux/K(A); the record names A."""
    stage = tmp_path / "lamps.usda"
    stage.write_text(_LAMPS.replace("bool treatAsPoint = 1\n        double3 xformOp:translate = (0, 0, -2)",
                                    'bool treatAsPoint = 1\n        string probesim:spectrum = "A"\n'
                                    '        double3 xformOp:translate = (0, 0, -2)'))
    cfg = tmp_path / "lamps.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\nlight_units = "photometric"\n\n[simulation]\nsamples = 64\n\n'
                   '[[sensor]]\nname = "toA"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n\n'
                   '[output]\ncsv = "out/l.csv"\nresponses = ["par"]\n')
    out = run(load_config(cfg), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "grey" and out.record["spectra"]["spectrum"] == "A"
    a = sources.cie_illuminant("A")
    v = out.rows[0].values
    assert v["illuminance_lx"] == pytest.approx(25.0, rel=1e-6)
    assert v["irradiance_W_m2"] == pytest.approx(25.0 / a.efficacy_lm_W, rel=1e-6)
    per_lux = R.response("par").of(a.values) / R.response("photopic").of(a.values)
    assert per_lux == pytest.approx(0.019898, rel=1e-4)
    assert v["ppfd_umol_m2_s"] == pytest.approx(25.0 * per_lux, rel=1e-6)


def test_a_mesh_light_names_the_emissive_record_spectrum(tmp_path):
    """A mesh light with ``probesim:spectrum = "A"``: its triangles' pair has K(A), and the emissive record's
    hero row is illuminant A's shape (per radiometric unit: ∫row dλ = 1), not the run's D65, even with
    ``[spectra] lights = D65`` declared."""
    from simulator.spectra.hero import hero_tables
    from simulator.spectra.grid import integrate

    stage = tmp_path / "mesh.usda"
    stage.write_text('#usda 1.0\n(\n metersPerUnit = 1\n upAxis = "Z"\n)\n'
                     'def Mesh "Panel" (\n prepend apiSchemas = ["MeshLightAPI"]\n)\n{\n'
                     ' point3f[] points = [(0, 0, 2), (1, 0, 2), (1, 1, 2), (0, 1, 2)]\n'
                     ' int[] faceVertexCounts = [4]\n int[] faceVertexIndices = [0, 3, 2, 1]\n'
                     ' float inputs:intensity = 100\n string probesim:spectrum = "A"\n}\n')
    scene = load_stage(stage, light_units="photometric")
    g = scene.geometry
    assert g.emissive_spectrum == "A" and g.emissive_spectrum_authored
    a = sources.cie_illuminant("A")
    em = g.emission[g.emission[:, 0] > 0]
    assert np.allclose(em[:, 1] / em[:, 0], a.efficacy_lm_W, rtol=1e-9)
    t = hero_tables(scene, "photometric", "D65", declared=sources.cie_illuminant("D65"))
    row = t.emission[-1]
    assert integrate(row) == pytest.approx(1.0, rel=1e-9)
    assert np.allclose(row, a.values / a.radiometric, rtol=1e-9)


def test_a_curve_on_a_material_that_is_not_read_is_named(tmp_path):
    """A Material with only an MDL surface is not read (displayColor or 0.18 is the albedo), so a
    ``probesim:reflectance`` on it is named in the summary warning as ignored, not silently dropped."""
    _write_curve(tmp_path / "red.csv", RED_ROWS)
    stage = tmp_path / "mdl.usda"
    stage.write_text('#usda 1.0\n(\n metersPerUnit = 1\n upAxis = "Z"\n)\n'
                     'def Mesh "Floor" (\n prepend apiSchemas = ["MaterialBindingAPI"]\n)\n{\n'
                     ' point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]\n'
                     ' int[] faceVertexCounts = [4]\n int[] faceVertexIndices = [0, 1, 2, 3]\n'
                     ' rel material:binding = </M>\n}\n'
                     'def Material "M"\n{\n asset probesim:reflectance = @red.csv@\n'
                     ' token outputs:mdl:surface.connect = </M/S.outputs:out>\n'
                     ' def Shader "S"\n {\n  uniform token info:implementationSource = "sourceAsset"\n'
                     '  uniform asset info:mdl:sourceAsset = @x.mdl@\n  token outputs:out\n }\n}\n'
                     'def SphereLight "L"\n{\n float inputs:intensity = 1\n}\n')
    scene = load_stage(stage, light_units="photometric")
    assert scene.geometry.reflectance_id is None
    assert any("1 x probesim:reflectance on a material with no UsdPreviewSurface" in w for w in scene.warnings)
