"""EN 12464-1 grid spacing and the candidate grids built with it."""

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.study.inputs.en12464 import en12464_grid, explicit_grid, grid_spacing_m


@pytest.mark.parametrize("d_m, p_m", [(1.0, 0.2), (5.0, 0.6), (10.0, 1.0), (50.0, 3.0), (100.0, 5.0)])
def test_spacing_matches_the_standards_worked_values(d_m, p_m):
    """EN 12464-1:2011 §4.4: p = 0.2·5^log10(d); its table rounds to 0.2, 0.6, 1, 3 and 5 m
    for d = 1, 5, 10, 50 and 100 m (0.615 and 3.08 unrounded)."""
    assert abs(grid_spacing_m(d_m) - p_m) <= 0.1 * p_m
    assert math.isclose(grid_spacing_m(d_m), 0.2 * 5 ** math.log10(d_m), rel_tol=1e-12)


def test_spacing_is_capped_at_10_m():
    assert grid_spacing_m(1e4) == 10.0  # 0.2·5^4 = 125 m uncapped


def test_grid_on_the_office_floor_with_the_wall_band():
    """6 × 4 m floor less a 0.5 m band: 5 × 3 m, d = 5 m (ratio < 2), p = 0.616 m;
    n = nearest(5 / 0.616) = 8 along 5 m (pitch 0.625 m), nearest(3 / 0.625) = 5 along 3 m."""
    g = en12464_grid(5.0, 3.0)
    assert (g.n_u, g.n_v) == (8, 5)
    assert math.isclose(g.pitch_u_m, 0.625) and math.isclose(g.pitch_v_m, 0.6)
    assert 0.5 <= g.pitch_u_m / g.pitch_v_m <= 2.0


def test_long_narrow_area_uses_the_shorter_side():
    """20 × 4 m (ratio 5 ≥ 2): d = 4 m, p = 0.527 m, n = nearest(4 / 0.527) = 8 (pitch 0.5 m), 40 along 20 m."""
    g = en12464_grid(20.0, 4.0)
    assert g.relevant_d_m == 4.0
    assert (g.n_u, g.n_v) == (40, 8)
    g2 = en12464_grid(4.0, 20.0)  # same area turned: same counts, swapped
    assert (g2.n_u, g2.n_v) == (8, 40)


def test_cell_centres_and_explicit_spacing():
    g = explicit_grid(5.0, 3.0, 1.0)
    assert (g.n_u, g.n_v) == (5, 3)
    c = np.array(g.centres())
    assert np.allclose(c[0], (0.5, 0.5)) and np.allclose(c[-1], (4.5, 2.5))
    assert explicit_grid(5.0, 3.0, 0.7).pitch_u_m <= 0.7


def test_candidates_on_the_office_floor():
    """The work plane sits 0.8 m above the floor, inside the wall band, and points in the shelf's box are dropped."""
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.schema import CandidateSpec

    scene = load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")
    spec = CandidateSpec(name="wp", on=["/Office/Room/Floor"], height_m=0.8, spacing_m=0.25, drop_inside=["/Office/Furniture/*"])
    (cs,) = build_candidates(scene, [spec], "study.toml")
    p = np.array([c.position for c in cs.candidates])
    assert np.allclose(p[:, 2], 0.8)
    assert p[:, 0].min() >= 0.5 and p[:, 0].max() <= 5.5 and p[:, 1].min() >= 0.5 and p[:, 1].max() <= 3.5
    assert cs.dropped_inside > 0 and len(cs.candidates) + cs.dropped_inside == 20 * 12
    in_shelf = (p[:, 0] > 2.55) & (p[:, 0] < 2.95) & (p[:, 1] > 2.6)
    assert not in_shelf.any()
    assert all(np.allclose(c.sensor.normal, (0, 0, 1)) for c in cs.candidates)


def test_candidate_errors_name_the_key():
    from simulator.errors import UserError
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.schema import CandidateSpec

    scene = load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")
    with pytest.raises(UserError, match=r"study.toml: candidates\[0\].on\[0\]: no geometry prim matches '/Office/Nope'"):
        build_candidates(scene, [CandidateSpec(name="a", on=["/Office/Nope"])], "study.toml")
    with pytest.raises(UserError, match=r"candidates\[0\].on: prim /Office/Furniture/Shelf is not flat"):
        build_candidates(scene, [CandidateSpec(name="a", on=["/Office/Furniture/Shelf"])], "study.toml")
    with pytest.raises(UserError, match=r"wall_band_m: a 3 m band leaves nothing"):
        build_candidates(scene, [CandidateSpec(name="a", on=["/Office/Room/Floor"], wall_band_m=3.0)], "study.toml")


def test_the_bundled_study_is_valid():
    """configs/studies/office_study.toml validates; its candidates, scenarios and trace groups are the documented ones."""
    from pathlib import Path

    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.inputs.scenarios import expand_scenarios, resolve_groups, trace_groups_of
    from simulator.study.schema import load_study

    study, path = load_study(Path(__file__).resolve().parent.parent / "configs" / "studies" / "office_study.toml")
    scene = load_stage(path.parent / study.stage, light_units="photometric", radiometric_spectrum="E")
    sets = build_candidates(scene, study.candidates, str(path))
    assert [len(s.candidates) for s in sets] == [39, 15]
    groups, unassigned = resolve_groups(scene, study.group, str(path))
    assert unassigned == [] and [len(v) for v in groups.values()] == [3, 3, 1, 1]
    scen = expand_scenarios(study.scenario, list(groups), str(path))
    assert len(scen) == 15 and len(trace_groups_of(scen, scene, groups, str(path))) == 3


# ---------------------------------------------------------------- EN 12464-1 areas

AREA_STUDY = """
stage = "{stage}"
seed = 5
[simulation]
samples = 64
method = "light"
[compute]
mode = "inprocess"
[[candidates]]
name = "wp"
on = ["/Office/Room/Floor"]
height_m = 0.8
spacing_m = 0.5
wall_band_m = 0.0
[[candidates]]
name = "walls"
on = ["/Office/Room/Wall*"]
height_m = 0.01
spacing_m = 1.0
wall_band_m = 0.0
[[candidates]]
name = "ez"
kind = "cylindrical"
on = ["/Office/Room/Floor"]
height_m = 1.2
spacing_m = 1.0
[[candidates]]
name = "eh"
on = ["/Office/Room/Floor"]
height_m = 1.2
spacing_m = 1.0
[[group]]
name = "lamps"
lights = ["/Office/Lights/*/*", "/Office/Lights/CorridorRow"]
[[scenario]]
name = "full"
levels = {{ lamps = [0.5, 1.0] }}
[[area]]
name = "desk_1"
candidates = "wp"
task = [0.9, 0.65, 2.3, 1.35]
required_lx = 500
u0 = 0.6
maintenance_factor = 0.8
[[area]]
name = "walls"
kind = "walls"
candidates = "walls"
space = "office"
[[area]]
name = "modelling"
kind = "cylindrical"
candidates = "ez"
horizontal = "eh"
"""


def test_surround_requirement_follows_the_task():
    """EN 12464-1 (2011 Table 1, kept in 2021): ≥ 750 → 500, 500 → 300, 300 → 200, ≤ 200 → the task's own."""
    from simulator.study.figures.areas import surround_required_lx

    assert [surround_required_lx(x) for x in (1500, 750, 500, 300, 200, 100)] == [500, 500, 300, 200, 200, 100]


def _area_study(tmp_path, text=None):
    from simulator.commands.cli import main

    p = tmp_path / "area_study.toml"
    p.write_text(text or AREA_STUDY.format(stage=(Path(__file__).resolve().parent.parent / "stages" / "office.usda").as_posix()))
    return main(["study", str(p), "--out", str(tmp_path / "o")]), tmp_path / "o"


def test_areas_csv_parts_maintained_figures_and_verdicts(tmp_path, capsys):
    """The desk's task area, its 0.5 m surround and 3 m background on a 0.5 m grid (cell centres 0.25 … 5.75 m
    by 0.25 … 3.75 m): 6, 14 and 76 points by hand; maintained Ē = 0.8 × the readings' mean; each verdict
    follows from the figure, its error and the requirement; E_z/E_h the two sets' means over the room."""
    import csv
    import io

    rc, out = _area_study(tmp_path)
    assert rc == 0, capsys.readouterr().err
    rows = list(csv.DictReader(io.StringIO((out / "areas.csv").read_text())))
    read = list(csv.DictReader(io.StringIO((out / "readings.csv").read_text())))
    assert {(r["area"], r["part"]) for r in rows} == {("desk_1", "task"), ("desk_1", "surround"), ("desk_1", "background"),
                                                       ("walls", "walls"), ("modelling", "cylindrical")}  # fmt: skip
    for r in rows:
        sc = r["scenario"]
        mine = [x for x in read if x["scenario"] == sc]
        if r["area"] == "desk_1":
            wp = [x for x in mine if x["candidates"] == "wp"]
            xy = np.array([[float(x["x"]), float(x["y"])] for x in wp])
            e = np.array([float(x["illuminance_lx"]) for x in wp])
            dx = np.maximum(np.maximum(0.9 - xy[:, 0], xy[:, 0] - 2.3), 0)
            dy = np.maximum(np.maximum(0.65 - xy[:, 1], xy[:, 1] - 1.35), 0)
            d = np.maximum(dx, dy)
            sel = {"task": d == 0, "surround": (d > 0) & (d <= 0.5), "background": (d > 0.5) & (d <= 3.5)}[r["part"]]
            assert int(r["sensors"]) == {"task": 6, "surround": 14, "background": 76}[r["part"]] == sel.sum()
            assert float(r["mean"]) == pytest.approx(0.8 * e[sel].mean(), rel=1e-7)
            assert float(r["u0"]) == pytest.approx(e[sel].min() / e[sel].mean(), rel=1e-7)
            assert (float(r["required_mean"]), float(r["required_u0"])) == {"task": (500, 0.6), "surround": (300, 0.4),
                                                                             "background": (100, 0.1)}[r["part"]]  # fmt: skip
        if r["area"] == "walls":
            assert (float(r["required_mean"]), float(r["required_u0"])) == (75, 0.1)  # space = "office"
        if r["area"] == "modelling":
            ez = np.mean([float(x["cylindrical_illuminance_lx"]) for x in mine if x["candidates"] == "ez"])
            eh = np.mean([float(x["illuminance_lx"]) for x in mine if x["candidates"] == "eh"])
            ratio, se = float(r["modelling_ratio"]), float(r["modelling_ratio_stderr"])
            assert ratio == pytest.approx(ez / eh, rel=1e-7) and se > 0
            margin = min(ratio - 0.3, 0.6 - ratio)
            assert r["modelling_verdict"] == ("pass" if margin > 2 * se else "fail" if margin < -2 * se else "unsure")
            assert float(r["required_mean"]) == 50 and float(r["required_u0"]) == 0.1
        for key, req in (("mean", float(r["required_mean"])), ("u0", float(r["required_u0"]))):
            v, s = float(r[key]), float(r[f"{key}_stderr"])
            if not np.isfinite(v):
                continue
            assert r[f"{key}_verdict"] == ("pass" if v - req > 2 * s else "fail" if v - req < -2 * s else "unsure")
    # the report shows them: every maintained Ē with its standard error, each verdict in its colour's class
    import html

    from simulator.io.numbers import with_error

    page = html.unescape((out / "report.html").read_text())
    sec = page[page.index('id="areas"'):page.index("</section>", page.index('id="areas"'))]
    for r in rows:
        if np.isfinite(float(r["mean"])):
            assert f'<td class="n">{with_error(float(r["mean"]), float(r["mean_stderr"]))}</td>' in sec, r
            assert f'<td class="{r["mean_verdict"]}">{r["mean_verdict"]}</td>' in sec
    # the cylindrical set's axis is the floor's normal
    ez = [x for x in read if x["candidates"] == "ez"]
    assert {x["kind"] for x in ez} == {"cylindrical"} and all(float(x["z"]) == pytest.approx(1.2) for x in ez)
    # the lamps at half level halve the readings: light is linear in emission
    full = {r["part"]: float(r["mean"]) for r in rows if r["area"] == "desk_1" and r["scenario"] == "full[lamps=1]"}
    half = {r["part"]: float(r["mean"]) for r in rows if r["area"] == "desk_1" and r["scenario"] == "full[lamps=0.5]"}
    assert all(half[k] == pytest.approx(0.5 * full[k], rel=1e-9) for k in full)


@pytest.mark.parametrize("old, new, message", [
    ("task = [0.9, 0.65, 2.3, 1.35]", "task = [0.9, 0.65, 0.95, 0.7]", "area[0]: no 'wp' candidate lies inside its task"),
    ('candidates = "ez"', 'candidates = "eh"', "area[2].candidates: a cylindrical area needs a cylindrical set"),
    ("required_lx = 500\n", "", "area[0]: a task area needs task = [x0, y0, x1, y1], required_lx and u0"),
    ('horizontal = "eh"', 'horizontal = "ehh"', "area[2].horizontal: no [[candidates]] named 'ehh'"),
    ('kind = "cylindrical"\non', 'kind = "semicylindrical"\non', "candidates[2]: a semicylindrical set needs 'facing'"),
])  # fmt: skip
def test_area_mistakes_are_one_line(tmp_path, capsys, old, new, message):
    text = AREA_STUDY.format(stage=(Path(__file__).resolve().parent.parent / "stages" / "office.usda").as_posix())
    assert old in text
    rc, out = _area_study(tmp_path, text.replace(old, new, 1))
    err = capsys.readouterr().err.strip()
    assert rc == 2 and err.count("\n") == 0 and message in err, err
    assert not (out / "areas.csv").exists()
