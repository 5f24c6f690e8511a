"""UGR at the observers of EN 12464-1 areas (simulator.study.figures.ugr; docs/REFERENCES.md §Glare indices).

The luminaire terms against closed forms (a rectangle's solid angle by Lambert's polygon formula's
companion, simulator.reference.closed_forms.polygon_solid_angle; Guth's position index); the study's
UGR against its own recombined indirect illuminance, and UGR's scaling with the lamps' level: L² grows
with the level squared and L_b with the level, so UGR rises by 8·log10(k) when every lamp is k times
brighter, with the same standard error.
"""

from __future__ import annotations

import csv
import io
import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from simulator.glare.indices import position_index_guth
from simulator.reference.closed_forms import polygon_solid_angle
from simulator.scene.usd import load_stage
from simulator.study.figures.ugr import Observer, luminaire_terms

ROOT = Path(__file__).resolve().parents[1]


def _stage(tmp_path: Path, extra: str = "") -> Path:
    p = tmp_path / "lamp.usda"
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n' + textwrap.dedent('''\
        def RectLight "Lamp"
        {
            float inputs:intensity = 3000
            float inputs:width = 1.2
            float inputs:height = 0.4
            double3 xformOp:translate = (3, 0, 2.5)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        ''') + textwrap.dedent(extra))  # fmt: skip
    return p


def test_a_lamp_as_seen_closed_form(tmp_path):
    """A 1.2 m × 0.4 m RectLight of 3000 cd/m² facing down, 3 m ahead of and 1.3 m above an eye looking level
    along +X: ω is the rectangle's solid angle, L its luminance, P Guth's at its centre (τ = 0, straight
    above the line of sight: σ = atan(1.3/3))."""
    scene = load_stage(_stage(tmp_path), light_units="photometric", radiometric_spectrum="E")
    obs = Observer("a", 0, np.array([0.0, 0.0, 1.2]), np.array([1.0, 0.0, 0.0]))
    ((name, lum, omega, p),), skipped = luminaire_terms(scene, scene.lights, obs)
    quad = [(2.4, -0.2, 2.5), (3.6, -0.2, 2.5), (3.6, 0.2, 2.5), (2.4, 0.2, 2.5)]
    assert name == "/Lamp" and lum == pytest.approx(3000.0, rel=1e-9) and not skipped
    assert omega == pytest.approx(polygon_solid_angle(quad, obs.position), rel=1e-9)
    assert p == pytest.approx(float(position_index_guth(math.degrees(math.atan2(1.3, 3.0)), 0.0)), rel=1e-9)


def test_a_half_hidden_lamp_counts_the_half_in_sight(tmp_path):
    """A black quad 1 mm below the lamp hiding its near half (x < 3, a cell boundary of its 8 × 8 cells): ω is the far
    half's solid angle; from behind the lamp's emitting side (an eye above it) it is not seen at all."""
    blocker = '''\
        def Mesh "Blocker"
        {
            int[] faceVertexCounts = [4]
            int[] faceVertexIndices = [0, 1, 2, 3]
            point3f[] points = [(2.0, -1, 2.499), (3.0, -1, 2.499), (3.0, 1, 2.499), (2.0, 1, 2.499)]
        }
        '''
    scene = load_stage(_stage(tmp_path, blocker), light_units="photometric", radiometric_spectrum="E")
    lamp = [l for l in scene.lights if l.name == "/Lamp"]
    obs = Observer("a", 0, np.array([0.0, 0.0, 1.2]), np.array([1.0, 0.0, 0.0]))
    ((_, _, omega, _),), _ = luminaire_terms(scene, lamp, obs)
    far = [(3.0, -0.2, 2.5), (3.6, -0.2, 2.5), (3.6, 0.2, 2.5), (3.0, 0.2, 2.5)]
    assert omega == pytest.approx(polygon_solid_angle(far, obs.position), rel=1e-9)
    above = Observer("a", 1, np.array([0.0, 0.0, 4.0]), np.array([1.0, 0.0, 0.0]))
    assert luminaire_terms(scene, lamp, above)[0] == []


STUDY = """
stage = "{stage}"
seed = 5
[simulation]
samples = 256
method = "light"
[compute]
mode = "inprocess"
[[candidates]]
name = "wp"
on = ["/Office/Room/Floor"]
height_m = 0.8
spacing_m = 0.5
wall_band_m = 0.0
[[group]]
name = "lamps"
lights = ["/Office/Lights/*/*"]
[[scenario]]
name = "full"
levels = {{ lamps = [0.5, 1.0] }}
[[area]]
name = "desk"
candidates = "wp"
task = [3.5, 1.0, 5.5, 3.0]
required_lx = 500
u0 = 0.6
{ugr}
"""


def _study(tmp_path, ugr: str):
    from simulator.commands.cli import main

    p = tmp_path / "s.toml"
    p.write_text(STUDY.format(stage=(ROOT / "stages" / "office.usda").as_posix(), ugr=ugr))
    return main(["study", str(p), "--out", str(tmp_path / "o")]), tmp_path / "o"


def test_study_ugr_rows_scale_with_the_lamps_level(tmp_path, capsys):
    """The desk area's four default observers (the task's side midpoints, 1.2 m above the floor, looking
    across): every row's UGR is 8·log10(0.25·π/E_ind·Σ(level·L)²ω/P²) of its own E_ind and the lamps as seen;
    at level 1 it is 8·log10(2) above level 0.5 (exactly: E_ind is recombined linearly, L² is quadratic) with
    the same standard error; verdicts follow from UGR, its error and UGR_L 19."""
    rc, out = _study(tmp_path, "ugr_limit = 19")
    assert rc == 0, capsys.readouterr().err
    rows = list(csv.DictReader(io.StringIO((out / "ugr.csv").read_text())))
    assert len(rows) == 8
    by = {(r["observer"], r["scenario"]): r for r in rows}
    obs = sorted({r["observer"] for r in rows})
    assert [(float(by[(o, "full[lamps=1]")]["x"]), float(by[(o, "full[lamps=1]")]["y"]), float(by[(o, "full[lamps=1]")]["z"]))
            for o in obs] == [(4.5, 1.0, 1.2), (5.5, 2.0, 1.2), (4.5, 3.0, 1.2), (3.5, 2.0, 1.2)]  # fmt: skip
    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", radiometric_spectrum="E")
    lamps = [l for l in scene.lights if l.name.startswith("/Office/Lights/")]
    for o in obs:
        lo, hi = by[(o, "full[lamps=0.5]")], by[(o, "full[lamps=1]")]
        assert float(hi["ugr"]) - float(lo["ugr"]) == pytest.approx(8 * math.log10(2.0), abs=1.5e-4)
        assert float(hi["ugr_stderr"]) == pytest.approx(float(lo["ugr_stderr"]), rel=1e-4)
        r = hi
        ob = Observer("desk", 0, np.array([float(r[k]) for k in "xyz"]), np.array([float(r[k]) for k in ("dx", "dy", "dz")]))
        terms, _ = luminaire_terms(scene, lamps, ob)
        g = sum(lum**2 * om / p**2 for _, lum, om, p in terms)
        e = float(r["indirect_illuminance_lx"])
        assert float(r["ugr"]) == pytest.approx(8 * math.log10(0.25 * math.pi / e * g), abs=1e-4)
        u, se = float(r["ugr"]), float(r["ugr_stderr"])
        assert se == pytest.approx(8 / math.log(10) * float(r["indirect_illuminance_stderr_lx"]) / e, rel=1e-4)
        want = "pass" if 19 - u > 2 * se else ("fail" if u - 19 > 2 * se else "unsure")
        assert r["verdict"] == want and int(r["luminaires_seen"]) == len(terms)
    assert "UGR at the areas" in (out / "report.html").read_text()


def test_observers_need_a_ugr_limit(tmp_path, capsys):
    """observers without ugr_limit: one line naming the key."""
    rc, _ = _study(tmp_path, "observers = [[1, 1, 1.2, 1, 0, 0]]")
    err = capsys.readouterr().err.strip()
    assert rc == 2 and "area[0]" in err and "ugr_limit" in err and "\n" not in err
