"""EN 12464-1 grid spacing and the candidate grids built with it."""

import math

import numpy as np
import pytest

from simulator.study.en12464 import en12464_grid, explicit_grid, grid_spacing_m


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
    from simulator.study.candidates import build_candidates
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
    from simulator.study.candidates import build_candidates
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
    from simulator.study.candidates import build_candidates
    from simulator.study.scenarios import expand_scenarios, resolve_groups, trace_groups_of
    from simulator.study.schema import load_study

    study, path = load_study(Path(__file__).resolve().parent.parent / "configs" / "studies" / "office_study.toml")
    scene = load_stage(path.parent / study.stage, light_units="photometric", radiometric_spectrum="E")
    sets = build_candidates(scene, study.candidates, str(path))
    assert [len(s.candidates) for s in sets] == [39, 15]
    groups, unassigned = resolve_groups(scene, study.group, str(path))
    assert unassigned == [] and [len(v) for v in groups.values()] == [3, 3, 1, 1]
    scen = expand_scenarios(study.scenario, list(groups), str(path))
    assert len(scen) == 15 and len(trace_groups_of(scen, scene, groups, str(path))) == 3
