"""Animated stages read at a chosen USD time code (config ``time``, ``--time``).

A point light (SphereLight, radius 0, normalize: I = intensity/4 cd)
moves from z = 2 m at time 0 to z = 4 m at time 10 (linear interpolation
between time samples, as USD reads them); a sensor at the origin facing up
reads E = I/z² exactly (a delta light: one shadow ray, zero variance). A
floor mesh's points move too. With no time given the stage is read at each
attribute's earliest sample and the summary line names the animated prims;
the run record says which time was read.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from simulator.commands.cli import main
from simulator.config.loader import apply_overrides, load_config
from simulator.errors import UserError
from simulator.pipeline import load_scene
from simulator.scene.usd import load_stage

I_CD = 100.0  # intensity 400, normalized point: 400 / 4

STAGE = '''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    startTimeCode = 0
    endTimeCode = 10
)
def SphereLight "Lamp"
{
    float inputs:intensity = 400
    bool inputs:normalize = 1
    float inputs:radius = 0
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 2), 10: (0, 0, 4) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Mesh "Floor"
{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points.timeSamples = { 0: [(5, 5, -1), (6, 5, -1), (5, 6, -1)], 10: [(5, 5, -3), (6, 5, -3), (5, 6, -3)] }
}
def Mesh "Still"
{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(8, 8, 0), (9, 8, 0), (8, 9, 0)]
}
'''

CONFIG = '''stage = "s.usda"
{time}
[simulation]
samples = 16
method = "light"
[[sensor]]
name = "up"
kind = "irradiance"
position = [0, 0, 0]
normal = [0, 0, 1]
'''


@pytest.fixture
def stage(tmp_path: Path) -> Path:
    p = tmp_path / "s.usda"
    p.write_text(STAGE)
    return p


def _animated_warning(scene) -> list[str]:
    return [w for w in scene.warnings if "animated prim" in w]


@pytest.mark.parametrize("time, z", [(0.0, 2.0), (10.0, 4.0), (5.0, 3.0), (-3.0, 2.0)])
def test_stage_read_at_the_time_given(stage, time, z):
    s = load_stage(stage, time=time)
    assert s.lights[0].position.tolist() == [0.0, 0.0, z]
    floor = s.geometry.points[s.geometry.triangles[s.geometry.prim == s.geometry.prim_names.index("/Floor")]]
    assert floor[..., 2].ravel().tolist() == [-1.0 - (z - 2.0)] * 3
    assert s.time_code == time and not _animated_warning(s)


def test_no_time_given_names_the_animated_prims_once(stage):
    s = load_stage(stage)
    assert s.lights[0].position.tolist() == [0.0, 0.0, 2.0]  # the earliest sample
    (line,) = _animated_warning(s)
    assert line.startswith("s.usda: 2 animated prim(s)") and "/Lamp" in line and "/Floor" in line and "/Still" not in line
    assert "--time" in line and s.animated == ("/Lamp", "/Floor")


def test_a_stage_with_nothing_animated_says_nothing(tmp_path):
    p = tmp_path / "still.usda"
    p.write_text(STAGE.replace("xformOp:translate.timeSamples = { 0: (0, 0, 2), 10: (0, 0, 4) }",
                               "xformOp:translate = (0, 0, 2)").split('def Mesh "Floor"')[0])
    assert not _animated_warning(load_stage(p))


def test_run_at_config_time_and_flag_reads_E_and_records_the_time(stage, tmp_path):
    cfg_path = tmp_path / "c.toml"
    cfg_path.write_text(CONFIG.format(time="time = 5.0"))
    assert main(["run", str(cfg_path), "-q"]) == 0
    e, rec = _read(tmp_path)
    assert e == pytest.approx(I_CD / 3.0**2, rel=1e-6)  # E = I / z², z = 3 m at time 5
    assert rec["stage"]["time"] == {"code": 5.0}
    assert main(["run", str(cfg_path), "-q", "--time", "10"]) == 0
    e, rec = _read(tmp_path)
    assert e == pytest.approx(I_CD / 4.0**2, rel=1e-6)
    assert rec["stage"]["time"] == {"code": 10.0} and rec["overrides"]["time"] == 10.0
    cfg_path.write_text(CONFIG.format(time=""))
    assert main(["run", str(cfg_path), "-q"]) == 0
    e, rec = _read(tmp_path)
    assert e == pytest.approx(I_CD / 2.0**2, rel=1e-6)
    assert rec["stage"]["time"] == {"code": None, "read": "earliest time sample of each attribute", "animated_prims": 2}
    assert any("animated prim" in w for w in rec["warnings"])


def _read(tmp_path: Path) -> tuple[float, dict]:
    with open(tmp_path / "c.csv", newline="") as f:
        (row,) = list(csv.DictReader(f))
    return float(row["illuminance_lx"]), json.loads((tmp_path / "c.run.json").read_text())


@pytest.mark.parametrize("body, words", [('time = "ten"', "c.toml: time: expected a number, got string"),
                                         ("time = nan", "c.toml: time: must be a finite number, got nan")])
def test_bad_time_in_config_is_one_line(stage, tmp_path, body, words):
    cfg_path = tmp_path / "c.toml"
    cfg_path.write_text(CONFIG.format(time=body))
    with pytest.raises(UserError) as info:
        load_config(cfg_path)
    assert str(info.value).endswith(words), str(info.value)


def test_bad_time_flag_is_one_line_exit_2(stage, tmp_path, capsys):
    cfg_path = tmp_path / "c.toml"
    cfg_path.write_text(CONFIG.format(time=""))
    assert main(["run", str(cfg_path), "--time", "inf"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == "probesim: error: --time: must be a finite number, got inf", err
    assert not (tmp_path / "c.csv").exists()
    assert load_scene(apply_overrides(load_config(cfg_path), time=10.0)).time_code == 10.0


def test_a_transform_pxr_cannot_build_is_one_line_naming_the_prim(tmp_path):
    """An xformOpOrder naming an op of an unknown type makes pxr raise: one UserError naming the prim."""
    p = tmp_path / "bad.usda"
    p.write_text(STAGE.replace('uniform token[] xformOpOrder = ["xformOp:translate"]',
                               'uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:bogus"]'))
    with pytest.raises(UserError) as info:
        load_stage(p, time=0.0)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{p}: /Lamp: transform cannot be computed") and "bogus" in msg, msg
