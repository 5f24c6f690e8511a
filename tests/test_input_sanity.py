"""Inputs that would give a plausible wrong number are named, not traced silently (simulator.scene.sanity,
the stage reader's light check, the study's levels, scenarios and work planes).

The stage of most tests: a closed room (a Cube, 0..4 x 0..3 x 0..3 m, matte) lit by a sphere lamp at
(2, 1.5, 2.5), with a closed table slab (x 1..3, y 1..2, z 0.72..0.76) and an open rug quad at
z = 0.005 whose front faces up. What each warning claims follows from the geometry alone: no light
crosses a closed opaque surface, so a point inside a closed shell that holds no emitter reads exactly 0
(checked on the engine below), and a point outside the room's closed shell receives nothing of the lamp
inside it.
"""

from __future__ import annotations

import glob
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.errors import UserError
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.sanity import sensor_warnings
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]

MATTE = """
def Material "Grey"
{
    token outputs:surface.connect = </Grey/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
        token outputs:surface
    }
}
"""


def cube(name: str, lo, hi) -> str:
    """A closed box from ``lo`` to ``hi`` (metres), grey."""
    c = [(a + b) / 2 for a, b in zip(lo, hi)]
    s = [b - a for a, b in zip(lo, hi)]
    return f"""
    def Cube "{name}" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {{
        double size = 1
        double3 xformOp:translate = ({c[0]}, {c[1]}, {c[2]})
        float3 xformOp:scale = ({s[0]}, {s[1]}, {s[2]})
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
        rel material:binding = </Grey>
    }}
"""


RUG = """
    def Mesh "Rug"
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(0.5, 0.5, 0.005), (3.5, 0.5, 0.005), (3.5, 2.5, 0.005), (0.5, 2.5, 0.005)]
    }
"""


def lamp(intensity: float = 1000.0) -> str:
    return f"""
    def SphereLight "Lamp"
    {{
        float inputs:intensity = {intensity}
        float inputs:radius = 0.1
        double3 xformOp:translate = (2, 1.5, 2.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}
"""


SUN = """
    def DistantLight "Sun"
    {
        float inputs:intensity = 1000
        float inputs:angle = 0
    }
"""


def write_room(tmp_path: Path, lights: str = "", name: str = "room.usda", mpu: float = 1.0) -> Path:
    body = cube("Room", (0, 0, 0), (4, 3, 3)) + cube("Table", (1, 1, 0.72), (3, 2, 0.76)) + RUG + (lights or lamp())
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = {mpu}\n    upAxis = "Z"\n)\n{MATTE}\ndef Xform "World"\n{{{body}}}\n')
    return path


def sensor(name: str, p, n=(0, 0, 1), kind=SensorKind.IRRADIANCE) -> Sensor:
    n = np.asarray(n, float)
    return Sensor(name=name, kind=kind, position=np.asarray(p, float), normal=n / np.linalg.norm(n), source=name)


@pytest.fixture(scope="module")
def room(tmp_path_factory):
    return load_stage(write_room(tmp_path_factory.mktemp("room")))


DESK = sensor("desk", (2, 1.5, 0.8))  # on the table top, facing up: nothing to say


def test_a_well_placed_sensor_raises_nothing(room):
    assert sensor_warnings(room, [DESK, sensor("rug", (2.0, 0.7, 0.005)), sensor("wall", (3.99, 1.5, 1.5), (-1, 0, 0))]) == []


@pytest.mark.parametrize("p, unit", [((2000, 1500, 760), "millimetres"), ((200, 150, 76), "centimetres")])
def test_positions_in_the_wrong_unit_are_named_with_the_unit(room, p, unit):
    """(2000, 1500, 760) on a metres stage lies ~2.5 km outside a 5.8 m room; /1000 it is the desk."""
    (line,) = sensor_warnings(room, [DESK, sensor("typed", p)])
    assert "'typed'" in line and f"looks like {unit}" in line and "metres" in line
    assert "(2, 1.5, 0.76) m lies inside" in line


def test_a_sensor_outside_the_stage_and_its_closed_room_is_named(room):
    """1 m east of the room's wall: outside the stage's box and outside the closed shell holding the lamp."""
    lines = sensor_warnings(room, [DESK, sensor("outdoors", (5, 1.5, 0.8))])
    assert len(lines) == 2
    assert "'outdoors'" in lines[0] and "outside the stage's bounds" in lines[0]
    assert "'outdoors'" in lines[1] and "outside every closed room" in lines[1] and "/World/Lamp" in lines[1]
    assert "desk" not in " ".join(lines)


def test_a_sensor_inside_a_solid_is_named_with_the_prim(room):
    """Inside the slab (z 0.74), and on its top facing down (its rays start a hair inside the slab)."""
    (line,) = sensor_warnings(room, [DESK, sensor("in_slab", (2, 1.5, 0.74)), sensor("down", (2, 1.5, 0.76), (0, 0, -1))])
    assert "2 sensors ('in_slab', 'down')" in line and "/World/Table" in line and "0 is read" in line


def test_a_sensor_just_behind_a_face_is_named_with_the_prim(room):
    """1 mm under the slab, facing up into it."""
    (line,) = sensor_warnings(room, [DESK, sensor("under", (2, 1.5, 0.719))])
    assert "'under'" in line and "/World/Table" in line and "just behind" in line and "mm ahead" in line


def test_a_sensor_on_an_open_face_facing_its_back_is_named(room):
    """On the rug (front up), facing down."""
    (line,) = sensor_warnings(room, [DESK, sensor("rug_down", (2, 0.7, 0.005), (0, 0, -1))])
    assert "'rug_down'" in line and "/World/Rug" in line and "facing its back" in line


def test_a_closed_room_with_no_light_inside_is_dark(tmp_path):
    """Sun outside, room closed: every sensor in it reads 0, and is named so."""
    scene = load_stage(write_room(tmp_path, SUN))
    (line,) = sensor_warnings(scene, [DESK])
    assert "'desk'" in line and "/World/Room" in line and "holds no light" in line


def test_grid_sensors_are_counted_not_listed(room):
    grid = [sensor(f"g[{i}]", (2000 + i, 1500, 760)) for i in range(40)]
    for s in grid:
        s.grid = "g"
    (line,) = sensor_warnings(room, [DESK] + grid)
    assert line.startswith("40 sensors ('g[0]', 'g[1]', 'g[2]', ...)")


def test_the_named_readings_are_what_the_warnings_say(room):
    """The claim on the engine: the sensor in the slab reads exactly 0 (no light crosses a closed opaque
    shell with no emitter inside it), the desk above it more than 0 (the lamp is 1.7 m above it)."""
    from simulator.engine.driver import Engine

    res = Engine(room, [DESK, sensor("in_slab", (2, 1.5, 0.74))]).run("path", samples=64, seed=1)
    assert res.mean[0, 1] > 0.0
    assert np.all(res.mean[1] == 0.0)


def test_the_checks_cost_milliseconds(room):
    """A 1,000-sensor grid on the room: CPU time well under a second (the figure reported is ~10 ms)."""
    import time

    grid = [sensor(f"g[{i}]", (0.1 + 3.8 * (i % 40) / 40, 0.1 + 2.8 * (i // 40) / 25, 0.8)) for i in range(1000)]
    t = time.process_time()
    sensor_warnings(room, grid)
    assert time.process_time() - t < 1.0


def test_run_prints_the_warning_and_records_it(tmp_path, capsys):
    """``probesim run`` with a sensor typed in millimetres: a warning line on stderr and in the run record."""
    import json

    write_room(tmp_path)
    cfg = tmp_path / "run.toml"
    cfg.write_text('stage = "room.usda"\n[simulation]\nsamples = 16\nmethod = "light"\n'
                   '[[sensor]]\nname = "desk"\nkind = "irradiance"\nposition = [2, 1.5, 0.8]\nnormal = [0, 0, 1]\n'
                   '[[sensor]]\nname = "typed"\nkind = "irradiance"\nposition = [2000, 1500, 800]\nnormal = [0, 0, 1]\n'
                   '[output]\ncsv = "out/run.csv"\n')
    assert main(["run", str(cfg)]) == 0
    err = capsys.readouterr().err
    assert "warning: sensor 'typed'" in err and "looks like millimetres" in err
    record = json.loads(next((tmp_path / "out").glob("*.json")).read_text())
    assert any("looks like millimetres" in w for w in record["warnings"])


# --------------------------------------------------------------------------- #
# every light at 0
# --------------------------------------------------------------------------- #


def test_a_stage_whose_every_light_emits_0_is_refused(tmp_path):
    path = write_room(tmp_path, lamp(0.0) + SUN.replace("1000", "0"))
    with pytest.raises(UserError, match=r"room\.usda: every light emits 0 \(/World/Lamp, /World/Sun"):
        load_stage(path, require_light=True)
    assert len(load_stage(path).lights) == 2  # read alone (a study may light them by level): not refused
    load_stage(write_room(tmp_path, lamp(0.0) + SUN, name="sun.usda"), require_light=True)  # one light on: read


# --------------------------------------------------------------------------- #
# studies: levels, unlit scenarios, work planes
# --------------------------------------------------------------------------- #


def study_file(tmp_path: Path, scenario: str, candidates: str = 'points = [[2, 1.5, 0.8]]\nnormal = [0, 0, 1]') -> Path:
    write_room(tmp_path, lamp() + SUN)
    p = tmp_path / "study.toml"
    p.write_text(f'stage = "room.usda"\n[[candidates]]\nname = "c"\n{candidates}\n'
                 f'[[group]]\nname = "lamps"\nlights = ["/World/Lamp"]\n[[group]]\nname = "sun"\nlights = ["/World/Sun"]\n'
                 f'[[scenario]]\nname = "s"\n{scenario}\n')
    return p


@pytest.mark.parametrize("levels", ["{ lamps = 100 }", "{ lamps = [0.5, 1.7] }"])
def test_a_level_above_1_is_refused_without_allow_boost(tmp_path, levels):
    from simulator.study.schema import load_study

    with pytest.raises(UserError, match=r"study\.toml: scenario\[0\]: levels\.lamps: (100|1\.7) is above 1 .*allow_boost = true"):
        load_study(study_file(tmp_path, f"levels = {levels}"))


def test_a_boost_asked_for_is_read(tmp_path):
    from simulator.study.schema import load_study

    study, _ = load_study(study_file(tmp_path, "levels = { lamps = 1.7 }\nallow_boost = true"))
    assert study.scenario[0].levels["lamps"] == pytest.approx(1.7, rel=0, abs=1e-12)


def _scenarios(tmp_path, scenario: str):
    from simulator.study.inputs.scenarios import dark_scenarios, expand_scenarios, resolve_groups, trace_groups_of
    from simulator.study.schema import load_study

    study, p = load_study(study_file(tmp_path, scenario))
    scene = load_stage(p.parent / "room.usda")
    groups, _ = resolve_groups(scene, study.group, "study.toml")
    scs = expand_scenarios(study.scenario, list(groups), "study.toml", scene=scene, groups=groups)
    trace_groups_of(scs, scene, groups, "study.toml")
    return dark_scenarios(scs, scene, groups)


def test_a_scenario_with_every_level_0_is_named(tmp_path):
    (line,) = _scenarios(tmp_path, "levels = { lamps = 0, sun = 0.0 }")
    assert "scenario 's'" in line and "every level is 0" in line and "every reading is 0" in line


def test_a_scenario_lit_only_by_a_sun_below_the_horizon_is_named(tmp_path):
    (line,) = _scenarios(tmp_path, "levels = { sun = 1 }\nsun = { azimuth_deg = 180, elevation_deg = -5 }")
    assert "scenario 's'" in line and "below the horizon" in line


def test_of_a_product_only_the_unlit_scenario_is_named(tmp_path):
    (line,) = _scenarios(tmp_path, "levels = { lamps = [0, 0.5] }")
    assert "scenario 's[lamps=0]'" in line


def _candidate_lines(tmp_path, height_m: float):
    from simulator.study.inputs.candidates import build_candidates, candidate_warnings
    from simulator.study.schema import load_study

    study, p = load_study(study_file(tmp_path, "levels = { lamps = 1 }",
                                     f'on = ["/World/Rug"]\nheight_m = {height_m}\nspacing_m = 0.5\nwall_band_m = 0.1'))
    scene = load_stage(p.parent / "room.usda")
    return candidate_warnings(scene, study.candidates, build_candidates(scene, study.candidates, "study.toml"), "study.toml")


def test_a_work_plane_far_above_the_stage_is_refused(tmp_path):
    """height_m = 800 puts the rug's grid 800 m up, 797 m above a 3 m room."""
    with pytest.raises(UserError, match=r"study\.toml: candidates\[0\]\.height_m: 800 m from /World/Rug .* outside the stage"):
        _candidate_lines(tmp_path, 800)


def test_a_work_plane_above_the_ceiling_is_named(tmp_path):
    (line,) = _candidate_lines(tmp_path, 3.5)
    assert "candidates[0].height_m: 3.5 m" in line and "above the ceiling" in line
    assert _candidate_lines(tmp_path, 0.8) == []


# --------------------------------------------------------------------------- #
# the bundled configs and studies raise none of these
# --------------------------------------------------------------------------- #

BUNDLED = sorted(glob.glob(str(ROOT / "configs" / "*.toml")) + glob.glob(str(ROOT / "configs" / "stability" / "*.toml")))


@pytest.mark.parametrize("path", BUNDLED, ids=lambda p: Path(p).relative_to(ROOT / "configs").as_posix())
def test_bundled_configs_raise_no_placement_warning(path):
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(path)
    scene = load_scene(cfg)
    assert sensor_warnings(scene, collect_sensors(cfg, scene)) == []


@pytest.mark.parametrize("path", sorted(glob.glob(str(ROOT / "configs" / "studies" / "*.toml"))), ids=lambda p: Path(p).name)
def test_bundled_studies_raise_no_placement_warning(path):
    from simulator.study.inputs.candidates import build_candidates, candidate_warnings
    from simulator.study.schema import load_study

    study, p = load_study(path)
    scene = load_stage((p.parent / study.stage).resolve(), light_units=study.light_units)
    assert candidate_warnings(scene, study.candidates, build_candidates(scene, study.candidates, path), path) == []


def test_one_sample_per_sensor_is_named_and_reads_an_infinite_error():
    """One sample per sensor carries no standard error: the traced readings' stderr is inf (never 0 or
    a guess) and the run says so in one warning naming the key; a run whose every reading has a closed
    form (configs/point.toml) needs no samples and says nothing."""
    import dataclasses

    from simulator.config import load_config
    from simulator.pipeline import run

    lines = []
    cfg = load_config(ROOT / "configs" / "furnace.toml")
    cfg = dataclasses.replace(cfg, simulation=dataclasses.replace(cfg.simulation, samples=1, rel_error=None))
    out = run(cfg, log=lines.append, write=False)
    assert any(l.startswith("warning: simulation.samples = 1:") for l in lines), lines
    errors = [r.values["irradiance_stderr_W_m2"] for r in out.rows if "irradiance_stderr_W_m2" in r.values]
    assert len(errors) == 7 and all(np.isinf(e) for e in errors)  # the furnace's seven irradiance and patch rows
    lines = []
    cfg = load_config(ROOT / "configs" / "point.toml")
    run(dataclasses.replace(cfg, simulation=dataclasses.replace(cfg.simulation, samples=1, rel_error=None)), log=lines.append,
        write=False)  # fmt: skip
    assert not any("simulation.samples = 1" in l for l in lines)
