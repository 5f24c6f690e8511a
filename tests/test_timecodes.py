"""A run over several USD time codes (``times``): a sensor prim moving along its time samples, one row
per sensor and time, one trace while the rest of the stage stays the same.

Reference: a point light of intensity I at height h over a sensor facing up at horizontal distance x
reads E = I·h/(h² + x²)^{3/2} (docs/REFERENCES.md §Point source), here
closed_forms.point_irradiance with the light the stage reader produced; light sampling of a point light
has no variance, so readings match to float32 (relative 1e-5).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.reference import closed_forms as cf

STAGE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
    startTimeCode = 0
    endTimeCode = 10
)

def Xform "World"
{
    def SphereLight "Lamp"
    {
        float inputs:intensity%s
        bool inputs:normalize = 1
        float inputs:radius = 0.05
        bool treatAsPoint = 1
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Xform "Rover"
    {
        token probesim:sensor:kind = "irradiance"
        string probesim:sensor:name = "rover"
        double3 xformOp:translate.timeSamples = {0: (0, 0, 0), 10: (2, 0, 0)}
        float3 xformOp:rotateXYZ = (180, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
    }
}
"""


def _run(tmp_path, intensity: str, times="[0, 5, 10]"):
    from simulator.config.loader import load_config
    from simulator.pipeline import run

    (tmp_path / "s.usda").write_text(STAGE % intensity)
    cfg = tmp_path / "c.toml"
    cfg.write_text(f'stage = "s.usda"\ntimes = {times}\n[simulation]\nmethod = "light"\nsamples = 64\n'
                   '[[sensor]]\nname = "fixed"\nkind = "irradiance"\nposition = [1, 1, 0]\nnormal = [0, 0, 1]\n'
                   f'[output]\ncsv = "{tmp_path / "out.csv"}"\n')
    out = run(load_config(cfg), log=lambda m: None)
    with open(out.csv_path, newline="") as f:
        return out, list(csv.DictReader(f))


def _expected(out, x_y, t):
    from simulator.scene.usd import load_stage

    scene = load_stage(Path(out.record["stage"]["path"]), light_units="photometric", time=t)
    (lamp,) = scene.lights
    return float(cf.point_irradiance(lamp.emission[1], lamp.position, np.array([*x_y, 0.0]), np.array([0, 0, 1.0])))


def test_a_moving_sensor_reads_along_its_path_in_one_trace(tmp_path):
    """The rover moves from x = 0 to 2 m between time codes 0 and 10 under a fixed 100 cd lamp 2 m up:
    one row per sensor and time (rover and the fixed sensor at 0, 5, 10), each the closed form at that
    place, the column time_code; the stage is the same at every time but for the rover, so one trace."""
    out, rows = _run(tmp_path, " = 400")
    assert [(r["sensor"], float(r["time_code"])) for r in rows] == [
        ("fixed", 0.0), ("rover", 0.0), ("fixed", 5.0), ("rover", 5.0), ("fixed", 10.0), ("rover", 10.0)]
    for r in rows:
        t = float(r["time_code"])
        where = (1.0, 1.0) if r["sensor"] == "fixed" else (0.2 * t, 0.0)
        assert float(r["illuminance_lx"]) == pytest.approx(_expected(out, where, t), rel=1e-5), r
    assert out.record["times"]["traces"] == [[0.0, 5.0, 10.0]]


def test_a_changing_stage_is_traced_per_time(tmp_path):
    """A lamp whose intensity has time samples (400 → 800 between 0 and 10): each time is its own trace,
    and each reading is still the closed form of that time's lamp."""
    out, rows = _run(tmp_path, ".timeSamples = {0: 400, 10: 800}")
    assert out.record["times"]["traces"] == [[0.0], [5.0], [10.0]]
    for r in rows:
        t = float(r["time_code"])
        where = (1.0, 1.0) if r["sensor"] == "fixed" else (0.2 * t, 0.0)
        assert float(r["illuminance_lx"]) == pytest.approx(_expected(out, where, t), rel=1e-5), r


def test_times_errors_name_the_key(tmp_path):
    """time and times together, or a time code twice: one line naming `times`."""
    from simulator.config.loader import load_config

    (tmp_path / "s.usda").write_text(STAGE % " = 400")
    for extra, message in (("time = 1\ntimes = [0, 1]", "give time (one reading) or times (several), not both"),
                           ("times = [0, 1, 0]", "a time code is given twice"), ("times = []", "times")):
        cfg = tmp_path / "c.toml"
        cfg.write_text(f'stage = "s.usda"\n{extra}\n')
        with pytest.raises(UserError) as e:
            load_config(cfg)
        assert message in str(e.value) and "\n" not in str(e.value), str(e.value)
