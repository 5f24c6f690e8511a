"""Coloured emissive geometry in spectral transport: each face keeps its ``emissiveColor``'s spectrum.

A UsdPreviewSurface ``emissiveColor`` c (linear sRGB) on a stage in
photometric units states the face's luminance L_v = Y(c) (BT.709 grey, cd/m²);
its spectrum is the emissive record's white shape (D65 here) times the
Mallett–Yuksel uplift of c, ``S_c = colour_emission(c, D65)``
(simulator.spectra.sources), scaled so that K_m ∫ S_c ȳ dλ = L_v. A response
r (quadrature vector q_r, simulator.spectra.responses) of light straight from
the face is then the photopic reading times

    k_r(c) = (q_r · S_c) / (q_photopic · S_c),

the ratio of the response integrals of S_c; the grey reduction (every face
D65) would give k_r(D65) instead. The panel's illuminance below it is the
closed form E_v = L_v · ∫ cos θ dω over the polygon (Lambert's contour formula,
simulator.reference.closed_forms.polygon_irradiance), and a radiance meter
whose cone lies inside a face reads L_v exactly in lux terms (cd/m²).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.errors import UserError
from simulator.pipeline import run
from simulator.reference.closed_forms import polygon_irradiance
from simulator.scene.usd import load_stage
from simulator.spectra import responses as R, sources

NAMES = ("par", "melanopic_edi")
RED = (1.0, 0.05, 0.02)
GREEN = (0.03, 1.0, 0.05)


def _panel(name: str, x0: float, x1: float, rgb, scale: float, y: float = 0.5) -> str:
    """A quad in z = 2 m over x ∈ [x0, x1], y ∈ [−y, y], wound so its emitting front face looks down (−Z), with its
    own material of emissiveColor ``scale · rgb`` and diffuseColor 0 (it reflects nothing)."""
    c = ", ".join(f"{scale * v:g}" for v in rgb)
    return (f'    def Mesh "{name}" (\n        prepend apiSchemas = ["MaterialBindingAPI"]\n    )\n    {{\n'
            f'        int[] faceVertexCounts = [4]\n        int[] faceVertexIndices = [0, 1, 2, 3]\n'
            f'        point3f[] points = [({x0}, {-y}, 2), ({x0}, {y}, 2), ({x1}, {y}, 2), ({x1}, {-y}, 2)]\n'
            f'        uniform bool doubleSided = 0\n        rel material:binding = </World/M{name}>\n    }}\n'
            f'    def Material "M{name}"\n    {{\n'
            f'        token outputs:surface.connect = </World/M{name}/S.outputs:surface>\n'
            f'        def Shader "S"\n        {{\n            uniform token info:id = "UsdPreviewSurface"\n'
            f'            color3f inputs:diffuseColor = (0, 0, 0)\n            color3f inputs:emissiveColor = ({c})\n'
            f'            token outputs:surface\n        }}\n    }}\n')


def _stage(tmp: Path, panels) -> Path:
    p = tmp / "panels.usda"
    body = "".join(_panel(*a) for a in panels)
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n    defaultPrim = "World"\n)\n'
                 f'def Xform "World"\n{{\n{body}}}\n')
    return p


def _config(tmp: Path, stage: Path, sensors: str, samples: int, responses=NAMES) -> Path:
    p = tmp / "run.toml"
    names = ", ".join(f'"{n}"' for n in responses)
    p.write_text(f'stage = "{stage.as_posix()}"\n\n[simulation]\nmethod = "path"\nsamples = {samples}\nseed = 3\n'
                 f'{sensors}\n[output]\ncsv = "out/panels.csv"\nresponses = [{names}]\n')
    return p


def _irradiance_sensor(name: str, x: float) -> str:
    return f'[[sensor]]\nname = "{name}"\nkind = "irradiance"\nposition = [{x}, 0, 0]\nnormal = [0, 0, 1]\n'


def _meter(name: str, x: float) -> str:
    return (f'[[sensor]]\nname = "{name}"\nkind = "radiance"\nposition = [{x}, 0, 0]\ndirection = [0, 0, 1]\n'
            'half_angle_deg = 5.0\n')


def _rows(out) -> dict:
    with open(out.csv_path, newline="") as f:
        return {r["sensor"]: r for r in csv.DictReader(f)}


def _ratio(rgb, name: str) -> float:
    """k_r(c) = (q_r · S_c)/(q_photopic · S_c), S_c = colour_emission(c, D65) (rgb None: D65 itself)."""
    d65 = sources.cie_illuminant("D65")
    s = d65 if rgb is None else sources.colour_emission(rgb, d65)
    return float(R.response(name).of(s.values)) / float(R.response("photopic").of(s.values))


def _value(row: dict, name: str, quantity: str) -> tuple[float, float]:
    col, col_se = R.response(name).columns(quantity)
    return float(row[col]), float(row[col_se])


def _luminance(rgb) -> float:
    """BT.709 grey Y of a linear sRGB colour (the reader's stated cd/m² of emissiveColor ``rgb``)."""
    return float(np.dot([0.2126, 0.7152, 0.0722], rgb))


@pytest.fixture(scope="module")
def red_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("red_panel")
    stage = _stage(tmp, [("Red", -0.5, 0.5, RED, 400.0)])
    out = run(load_config(_config(tmp, stage, _irradiance_sensor("below", 0.0) + _meter("meter", 0.0), 40000)),
              log=lambda *a: None)
    return out, _rows(out)


def test_a_red_panel_reads_its_own_spectrum_below_it(red_run):
    """A 1 m × 1 m panel of emissiveColor 400·(1, 0.05, 0.02) 2 m above an upward irradiance sensor: the plan
    traces hero wavelengths; illuminance is the closed form L_v ∫cos θ dω (L_v = 400·Y(c) cd/m²), and PPFD and
    melanopic EDI are that illuminance times k_r(c) of S_c = colour_emission(c, D65), each within 4 standard
    errors; the grey reduction's k_r(D65) lies more than 20 standard errors away (this red: about 1.4× the
    PPFD per lux of D65 and a fifth of its melanopic EDI)."""
    out, rows = red_run
    assert out.record["plan"]["transport"] != "grey"
    row = rows["below"]
    lv = 400.0 * _luminance(RED)
    assert out.scene.geometry.emission[:, 1] == pytest.approx(lv, rel=1e-9)
    verts = [(-0.5, -0.5, 2), (-0.5, 0.5, 2), (0.5, 0.5, 2), (0.5, -0.5, 2)]
    ev = float(polygon_irradiance(lv, verts, (0, 0, 0), (0, 0, 1)))
    e, se = float(row["illuminance_lx"]), float(row["illuminance_stderr_lx"])
    assert se > 0 and abs(e - ev) <= 4 * se, (e, ev, se)
    for name in NAMES:
        v, s = _value(row, name, "irradiance")
        truth, grey = ev * _ratio(RED, name), ev * _ratio(None, name)
        assert s > 0 and abs(v - truth) <= 4 * s, (name, v, truth, s)
        assert abs(v - grey) > 20 * s, (name, v, grey, s)


def test_a_radiance_meter_sees_the_red_panel_s_colour(red_run):
    """The radiance meter (5° cone inside the panel, the first surface's emission) reads L_v = 400·Y(c) cd/m²
    and its PAR and melanopic radiances are L_v · k_r(c), within 4 standard errors."""
    out, rows = red_run
    row = rows["meter"]
    lv = 400.0 * _luminance(RED)
    l, se = _value(row, "photopic", "radiance")
    assert abs(l - lv) <= 4 * se + 1e-6 * lv, (l, lv, se)
    for name in NAMES:
        v, s = _value(row, name, "radiance")
        truth = lv * _ratio(RED, name)
        assert abs(v - truth) <= 4 * s + 1e-6 * truth, (name, v, truth, s)


def test_the_hero_tables_give_the_red_faces_their_own_row(red_run):
    """The hero tables hold one row beyond the emissive record's, ``colour_emission(c, D65)`` scaled so that
    its photopic response per radiometric unit is the faces' K = L_v/L_e (the stated lm value kept), and every
    emitting triangle indexes it."""
    from simulator.spectra.hero import hero_tables
    from simulator.spectra.responses import response

    scene = red_run[0].scene
    t = hero_tables(scene, "photometric", "D65")
    g = scene.geometry
    assert t.emission.shape[0] == 2
    assert np.all(t.face_emission[g.emission[:, 0] > 0] == 1)
    d65 = sources.cie_illuminant("D65")
    shape = sources.colour_emission(RED, d65).values
    k = g.emission[0, 1] / g.emission[0, 0]
    row = t.emission[1]
    assert float(response("photopic").of(row)) == pytest.approx(k, rel=1e-9)
    assert np.allclose(row / row.max(), shape / shape.max(), rtol=1e-9)


def test_two_emissive_colours_in_one_stage_each_keep_theirs(tmp_path):
    """A red and a green panel side by side (x ∈ [−1, 0] and [0, 1]), a radiance meter under each looking up
    at its centre (5° cone inside it): each reads its own L_v = 300·Y(c) and PAR and melanopic radiances
    L_v · k_r(c) of its own colour within 4 standard errors, and the two ratios differ."""
    stage = _stage(tmp_path, [("Red", -1.0, 0.0, RED, 300.0), ("Green", 0.0, 1.0, GREEN, 300.0)])
    out = run(load_config(_config(tmp_path, stage, _meter("red", -0.5) + _meter("green", 0.5), 20000)),
              log=lambda *a: None)
    rows = _rows(out)
    for sensor, rgb in (("red", RED), ("green", GREEN)):
        lv = 300.0 * _luminance(rgb)
        l, se = _value(rows[sensor], "photopic", "radiance")
        assert abs(l - lv) <= 4 * se + 1e-6 * lv, (sensor, l, lv, se)
        for name in NAMES:
            v, s = _value(rows[sensor], name, "radiance")
            truth = lv * _ratio(rgb, name)
            assert abs(v - truth) <= 4 * s + 1e-6 * truth, (sensor, name, v, truth, s)
    assert _ratio(RED, "melanopic_edi") < 0.5 * _ratio(GREEN, "melanopic_edi")


def test_a_grey_emissive_stage_is_traced_as_before(tmp_path):
    """A grey panel (emissiveColor 400·(1, 1, 1)): no colour kept (``Geometry.emission_rgb`` None), one
    channel (transport grey), no colour warning, and the CSV's illuminance is the closed form L_v ∫cos θ dω
    (400 cd/m²) within 4 standard errors."""
    stage = _stage(tmp_path, [("White", -0.5, 0.5, (1.0, 1.0, 1.0), 400.0)])
    out = run(load_config(_config(tmp_path, stage, _irradiance_sensor("below", 0.0), 4000)), log=lambda *a: None)
    assert out.scene.geometry.emission_rgb is None
    assert out.record["plan"]["transport"] == "grey"
    assert not any("luminance grey" in w for w in out.record["warnings"])
    row = _rows(out)["below"]
    verts = [(-0.5, -0.5, 2), (-0.5, 0.5, 2), (0.5, 0.5, 2), (0.5, -0.5, 2)]
    ev = float(polygon_irradiance(400.0, verts, (0, 0, 0), (0, 0, 1)))
    e, se = float(row["illuminance_lx"]), float(row["illuminance_stderr_lx"])
    assert se > 0 and abs(e - ev) <= 4 * se, (e, ev, se)


def test_a_probe_under_a_red_ceiling_maps_its_colour(tmp_path):
    """A probe 2 m below a 6 m × 6 m red panel (emissiveColor 400·c). The map's frame is the stage's
    (an untransformed DomeLight's: longitude 0 toward +Z, latitude toward +Y; simulator.io.latlong), so on
    a 16 × 8 map the 4 × 4 pixels of longitude and latitude within ±45° (columns 6–9, rows 2–5) look up
    at the panel, every direction meeting it at |x| ≤ 2 m, |y| ≤ 2√2 m; each of them reads the panel's
    linear sRGB ``M K_m ∫ L (x̄, ȳ, z̄) dλ`` (cd/m²), L(λ) = S_c(λ) scaled to K_m ∫ S_c ȳ dλ = L_v =
    400·Y(c): the 16 pixels' mean R, G, B each within 4 standard errors (the pixels' spread gives the
    mean's stderr: each has the same expectation). The grey reduction would read R = G = B = L_v; the
    colour's is (4.00, 0.202, 0.080) L_v: R over 3 L_v, G and B under L_v/4."""
    import math

    import OpenEXR

    from simulator.spectra.grid import trapezoid_weights
    from simulator.spectra.hero import colour_weights

    stage = _stage(tmp_path, [("Red", -3.0, 3.0, RED, 400.0, 3.0)])
    probe = '[[sensor]]\nname = "ball"\nkind = "probe"\nposition = [0, 0, 0]\nresolution = [16, 8]\n'
    run(load_config(_config(tmp_path, stage, probe, 128 * 200)), log=lambda *a: None)
    lv = 400.0 * _luminance(RED)
    shape = sources.colour_emission(RED, sources.cie_illuminant("D65")).values
    radiance = shape * lv / float(R.response("photopic").of(shape))  # W m⁻² sr⁻¹ nm⁻¹
    rgb_truth = colour_weights() / 400.0 @ (trapezoid_weights() * radiance)  # cd/m²
    exr = OpenEXR.File(str(tmp_path / "out" / "panels.ball.exr"), separate_channels=True)
    ch = {k: c.pixels.astype(float) for k, c in exr.channels().items()}
    assert "traced spectrum" in exr.header()["probesim:rgb"]
    for k, c in enumerate("RGB"):
        pix = ch[c][2:6, 6:10].reshape(-1)
        assert abs(pix.mean() - rgb_truth[k]) <= 4 * pix.std(ddof=1) / math.sqrt(pix.size), (c, pix, rgb_truth[k])
    assert rgb_truth[0] > 3 * lv and rgb_truth[1] < 0.25 * lv and rgb_truth[2] < 0.25 * lv


def test_an_emissive_colour_with_a_negative_channel_is_one_line_naming_the_prim(tmp_path):
    """emissiveColor (10, −1, 0) has a positive grey (2.126 − 0.7152 > 0) but no spectrum (a negative
    emission): the stage is refused with one line naming the prim and the input."""
    stage = _stage(tmp_path, [("Bad", -0.5, 0.5, (10.0, -1.0, 0.0), 1.0)])
    with pytest.raises(UserError) as e:
        load_stage(stage, light_units="photometric")
    msg = str(e.value)
    assert "\n" not in msg and "/World/Bad" in msg and "emissiveColor" in msg and "non-negative" in msg, msg
