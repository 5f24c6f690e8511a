"""A lamp-only scenario traced in one pass with the sun and the sky is no noisier than a plain run of its
lamps at equal samples: the pass splits its indirect paths for the scenarios that gain by it
(simulator.engine.scenario_split) and learns its guide per light group (simulator.engine.guide.scenario_tally).
"""

import numpy as np
import pytest

from simulator.engine.guide import scenario_tally
from simulator.engine.scenario_split import neyman_split, pass_split, pilot_groups, scenario_relative_variances


def test_pilot_groups_merge_lights_dimmed_alike():
    """Lights 0 and 2 have the same level in both scenarios: one pilot group; the unlit light another."""
    d = np.array([[1.7, 0.0, 1.7, 0.0], [0.0, 1.0, 0.0, 0.0]])
    g, lv = pilot_groups(d)
    assert g[0] == g[2] and len(set(g.tolist())) == 3
    assert np.allclose(lv[:, g], d)  # each light's levels read back through its group


def test_scenario_relative_variances_by_hand():
    """One sensor, two groups with means (2, 1), variances per sample 4 and 1, covariance −1 (m2 = C·(n − 1),
    n = 5). Scenario (1, 0): 4/2² = 1; scenario (1, 1): (4 + 1 − 2)/3² = 1/3."""
    c = np.array([[4.0, -1.0], [-1.0, 1.0]])
    m = np.array([[2.0, 1.0]])
    rv = scenario_relative_variances(m, (c * 4)[None], np.array([5]), np.array([[1.0, 0.0], [1.0, 1.0]]), m)
    assert rv == pytest.approx([1.0, 1.0 / 3.0], rel=1e-12)


def test_neyman_split_and_the_pass_split():
    """K = √(V_i·c_d/(V_d·c_i)): V_i/V_d = 25, equal rays → 5; no indirect variance → 1. The pass takes the
    largest K where any scenario splits, 1 where none does."""
    assert neyman_split(0.01, 0.25, 7.0, 7.0, 8, 1.0)[0] == 5
    assert neyman_split(0.01, 0.0, 7.0, 7.0, 8, 1.0) == (1, 1.0)
    assert pass_split([(1, 1.0), (3, 1.3)], 8) == 8 and pass_split([(1, 1.0), (1, 1.1)], 8) == 1


def test_scenario_tally_takes_each_patch_by_its_largest_share():
    """Two groups (sun, lamps) over three patches: the sun's tally (90, 0, 10), the lamps' (0, 3, 1). Scenario A
    lights the lamps only (shares 0, 0.75, 0.25), B the sun only (0.9, 0, 0.1): the guide weighs
    (0.9, 0.75, 0.25), so the lamps' ceiling patch keeps nearly its own share where the union (93, 3, 11)
    would give it 3/107."""
    t = np.array([[[90.0, 0.0, 10.0]], [[0.0, 3.0, 1.0]]])
    out = scenario_tally(t, np.array([[0.0, 1.7], [1.0, 0.0]]))
    assert np.allclose(out, [[0.9, 0.75, 0.25]])


@pytest.fixture(scope="module")
def office():
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.schema import CandidateSpec

    sc = load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")
    (cs,) = build_candidates(sc, [CandidateSpec(name="wp", on=["/Office/Room/Floor"], height_m=0.8, spacing_m=1.5)], "t")
    names = [l.name for l in sc.lights]
    groups = {"window_row": [n for n in names if "WindowRow" in n], "corridor_row": [n for n in names if "CorridorRow" in n],
              "sky": ["/Office/Sky"], "sun": ["/Office/Sun"]}  # fmt: skip
    return sc, [c.sensor for c in cs.candidates], groups


def _plain(sc, sensors, levels, groups, n, seed):
    """``probesim run`` of the stage with only the lit lights, each at its level (engine defaults: the indirect
    split chosen by its pilot): photometric (mean, stderr)."""
    from dataclasses import replace

    from simulator.config.loader import SimulationConfig
    from simulator.engine.driver import Engine
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan
    from simulator.study.trace.groups import group_scene

    lights = []
    for l in sc.lights:
        lv = next((levels.get(g, 0.0) for g, ls in groups.items() if l.name in ls), 0.0)
        if lv > 0:
            lights.append(replace(l, emission=(l.emission[0] * lv, l.emission[1] * lv)))
    sub = replace(group_scene(sc, []), lights=lights)
    res = run_plan(Engine(sub, sensors), make_plan(sub, sensors, "auto", "total"), SimulationConfig(samples=n, seed=seed))
    return res.mean[:, 1], res.stderr[:, 1]


def test_a_lamp_only_scenario_beside_the_sun_is_no_noisier_than_a_plain_run(office):
    """Office, 8 work-plane sensors, 1024 samples; window row, corridor row, sky and sun in one pass serving
    "lamps" (both rows at 1.7, the rest 0) and "overcast" (sky 1, corridor 0.5); the plain run of the lamps
    scaled by 1.7 splits its indirect paths by its own pilot (K = 5 here).

    Measured (benchmarks/lamp_scenario.py, 3 seed pairs): variance-per-sample ratio pass/plain, median over
    sensors, 7.3 before (one path a sample, guide learnt on the sun's patch), 0.71 now; with a third
    scenario lighting the sun, 7.3 before and 0.89 now; this seed pair 0.73. The bound 1.21 is the target
    (standard error ≤ 1.1× a plain run's): a per-sensor ratio of two variances from 1024 samples each spreads
    by about √(2/1023 + 2/1023) = 6% (more where indirect paths have heavy tails), the median of 8 by less,
    so the measured figures sit many of those spreads below the bound and the old figure (7.3; 5.8–9.0 per
    sensor on this seed pair) 6× above it. Agreement: every lamp reading within 4 combined standard errors of
    the plain run, and Σ z² over the 8 sensors under χ²₈'s 0.999 quantile, 26.1 (z = difference over
    the combined standard error: an understated standard error would inflate it). The pass's other scenario
    (overcast) agrees with its own plain run within 4σ and is no noisier than it either."""
    from simulator.config.loader import SimulationConfig
    from simulator.study.trace.groups import trace_groups

    sc, sensors, groups = office
    n = 1024
    lamps = {"window_row": 1.7, "corridor_row": 1.7}
    scen = [lamps, {"sky": 1.0, "corridor_row": 0.5}]
    gr = trace_groups(sc, sensors, groups, SimulationConfig(samples=n, seed=0), 13, scenarios=scen)
    m, se = gr.combine(lamps)
    pm, pse = _plain(sc, sensors, lamps, groups, n, 14)
    r = (se[:, 1] / pse) ** 2
    assert np.median(r) <= 1.21 and np.sqrt(np.mean(r**2)) <= 1.21, r
    z = (m[:, 1] - pm) / np.hypot(se[:, 1], pse)
    assert np.all(np.abs(z) <= 4.0), z
    assert float(np.sum(z**2)) <= 26.1, z
    # the other scenario of the pass: unbiased, and no noisier than its own plain run (measured 0.27×)
    m, se = gr.combine(scen[1])
    pm, pse = _plain(sc, sensors, scen[1], groups, n, 15)
    assert np.median((se[:, 1] / pse) ** 2) <= 1.21
    assert np.all(np.abs(m[:, 1] - pm) <= 4.0 * np.hypot(se[:, 1], pse))
