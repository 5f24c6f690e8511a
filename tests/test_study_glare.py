"""Glare views in a study: the stage's glare prims traced in every scenario (simulator.study.figures.glare_views).

E_v is linear in the lamps' level (twice the level, twice E_v within the two readings' errors: 4σ), and a
sky split into Tregenza patches at one level everywhere is the uniform dome it was split from: the view
reads the same E_v on the textured dome of patch levels as on the authored dome (4σ).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path


ROOT = Path(__file__).resolve().parents[1]

VIEW_STAGE = """#usda 1.0
(
    subLayers = [@{office}@]
    defaultPrim = "Office"
    metersPerUnit = 1
    upAxis = "Z"
)

over "Office"
{{
    def Xform "Eye"
    {{
        token probesim:sensor:kind = "glare"
        string probesim:sensor:name = "corridor_desk"
        int2 probesim:sensor:resolution = (32, 32)
        double3 xformOp:translate = (4.5, 2, 1.2)
        float3 xformOp:rotateXYZ = (90, 0, 90)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
    }}
}}
"""

STUDY = """
stage = "view.usda"
seed = 3
[simulation]
samples = 64
[compute]
mode = "inprocess"
[[candidates]]
name = "wp"
on = ["/Office/Room/Floor"]
height_m = 0.8
spacing_m = 2.0
[[group]]
name = "sky"
lights = ["/Office/Sky"]
sky = "tregenza"
[[group]]
name = "lamps"
lights = ["/Office/Lights/*/*"]
[[scenario]]
name = "sky"
levels = { sky = 1.0, lamps = 0.0 }
[[scenario]]
name = "lamps"
levels = { sky = 0.0, lamps = [0.5, 1.0] }
"""


def test_glare_prims_are_read_in_every_scenario(tmp_path, capsys):
    """glare.csv holds the view in each of the three scenarios with its pictures beside it and a report
    section; E_v at level 1 is twice E_v at level 0.5 within 4 of their combined standard errors; the sky
    scenario (every patch at the group's level 1) reads the authored uniform dome's E_v within 4σ."""
    from simulator.commands.cli import main
    from simulator.engine.driver import Engine
    from simulator.engine.glare import run_glare
    from simulator.scene.usd import load_stage
    from simulator.study.trace.groups import group_scene

    (tmp_path / "view.usda").write_text(VIEW_STAGE.format(office=(ROOT / "stages" / "office.usda").as_posix()))
    (tmp_path / "s.toml").write_text(STUDY)
    rc = main(["study", str(tmp_path / "s.toml"), "--out", str(tmp_path / "o")])
    assert rc == 0, capsys.readouterr().err
    out = tmp_path / "o"
    rows = {r["scenario"]: r for r in csv.DictReader(io.StringIO((out / "glare.csv").read_text()))}
    assert set(rows) == {"sky", "lamps[lamps=0.5]", "lamps[lamps=1]"}
    lo, hi = rows["lamps[lamps=0.5]"], rows["lamps[lamps=1]"]
    e_lo, e_hi = float(lo["ev_lx"]), float(hi["ev_lx"])
    bound = 4 * math.hypot(float(hi["ev_stderr_lx"]), 2 * float(lo["ev_stderr_lx"]))
    assert abs(e_hi - 2 * e_lo) <= bound, (e_hi, e_lo, bound)
    for sc in ("sky", "lamps_lamps_1_"):
        assert (out / f"glare_corridor_desk_{sc}.png").stat().st_size > 0
        assert (out / f"glare_corridor_desk_{sc}.hdr").read_bytes().startswith(b"#?RADIANCE\nSOFTWARE= probesim glare view")
    assert "Glare at the stage" in (out / "report.html").read_text()
    scene = load_stage(tmp_path / "view.usda", light_units="photometric", radiometric_spectrum="E")
    sky = replace_lights(group_scene(scene, []), [l for l in scene.lights if l.name == "/Office/Sky"])
    (r,) = run_glare(sky, [scene.sensors[0]], "path", lambda s, ss: Engine(s, ss), seed=11)
    e_sky, se_sky = float(rows["sky"]["ev_lx"]), float(rows["sky"]["ev_stderr_lx"])
    assert abs(r.estimate.ev_lx - e_sky) <= 4 * math.hypot(r.estimate.ev_stderr_lx, se_sky), (r.estimate.ev_lx, e_sky)


def replace_lights(scene, lights):
    from dataclasses import replace

    return replace(scene, lights=lights)
