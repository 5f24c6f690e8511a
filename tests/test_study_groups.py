"""Light groups: recombined dimming scenarios against separate runs, and the recombination algebra."""

from dataclasses import replace

import numpy as np

from simulator.config.loader import SimulationConfig
from simulator.scene.model import Geometry, Sensor, SensorKind
from simulator.study.trace.groups import GroupReadings, derive_seed, trace_groups


def _office():
    from simulator.scene.usd import load_stage

    return load_stage("stages/office.usda", light_units="photometric", radiometric_spectrum="E")


def _sensors():
    pts = [(1.0, 1.0, 0.8), (2.5, 2.0, 0.8), (4.5, 3.0, 0.8), (5.2, 1.2, 0.8)]
    out = [Sensor(f"wp{i}", SensorKind.IRRADIANCE, np.array(p), np.array([0.0, 0.0, 1.0])) for i, p in enumerate(pts)]
    out.append(Sensor("cell", SensorKind.RADIANCE, np.array([3.0, 2.0, 2.98]), np.array([0.0, 0.0, -1.0]), half_angle=np.radians(30)))
    return out


def _separate_run(scene, sensors, groups, levels, sim, seed):
    """An ordinary run of the scenario: every lit light at its level in one scene, one trace."""
    from simulator.engine.driver import Engine
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan

    owner = {l: g for g, ls in groups.items() for l in ls}
    lights = [replace(l, emission=(l.emission[0] * levels[owner[l.name]], l.emission[1] * levels[owner[l.name]]))
              for l in scene.lights if levels.get(owner.get(l.name), 0.0) > 0]  # fmt: skip
    g = scene.geometry
    sc = replace(scene, lights=lights, geometry=Geometry(g.points, g.triangles, g.albedo, np.zeros_like(g.emission), g.two_sided, g.prim, g.prim_names))
    eng = Engine(sc, sensors, threads=0)
    return run_plan(eng, make_plan(sc, sensors, sim.method, sim.component), replace(sim, seed=seed))


def test_recombined_dimming_agrees_with_separate_runs_within_4_sigma():
    """E(d) = Σ_g d_g E_g (linearity of light transport in emission): three dimming
    vectors recombined from one trace per group agree with a separate run of each
    scenario, |Δ| ≤ 4·sqrt(σ_recombined² + σ_run²) in both channels, path tracing with
    interreflection (the part a first-vertex light mask could not switch off)."""
    scene = _office()
    sensors = _sensors()
    groups = {"window_row": [l.name for l in scene.lights if "/WindowRow/" in l.name],
              "corridor_row": [l.name for l in scene.lights if "/CorridorRow/" in l.name]}  # fmt: skip
    sim = SimulationConfig(samples=4096, method="path", seed=0)
    gr = trace_groups(scene, sensors, groups, sim, derive_seed(3, "pass"))
    assert gr.mean.shape == (2, len(sensors), 2) and gr.cov.shape == (len(sensors), 2, 2, 2)
    assert np.allclose(gr.cov[:, :, 0, 1], gr.cov[:, :, 1, 0], rtol=1e-12, atol=0)  # symmetric
    for k, levels in enumerate([{"window_row": 1.0, "corridor_row": 1.0}, {"window_row": 0.3, "corridor_row": 0.8},
                                {"window_row": 1.0, "corridor_row": 0.0}]):  # fmt: skip
        m, se = gr.combine(levels)
        ref = _separate_run(scene, sensors, groups, levels, sim, derive_seed(99, k))
        sig = np.sqrt(se**2 + ref.stderr**2)
        assert np.all(sig > 0)
        assert np.all(np.abs(m - ref.mean) <= 4 * sig + 1e-9 * np.abs(ref.mean)), (levels, m, ref.mean, sig)


def test_combine_uses_the_covariance():
    """σ(d)² = dᵀ C d: with a correlated pair the cross term counts."""
    mean = np.array([[[1.0, 10.0]], [[2.0, 20.0]]])  # (G=2, S=1, 2)
    se = np.array([[[0.1, 1.0]], [[0.2, 2.0]]])
    cov = np.zeros((1, 2, 2, 2))
    for c in range(2):
        cov[0, c] = [[se[0, 0, c] ** 2, 0.5 * se[0, 0, c] * se[1, 0, c]], [0.5 * se[0, 0, c] * se[1, 0, c], se[1, 0, c] ** 2]]
    gr = GroupReadings(["a", "b"], mean, se, cov, np.zeros((2, 1), np.int64), np.zeros(2))
    m, s = gr.combine({"a": 2.0, "b": 0.5})
    assert np.allclose(m[0], [2 * 1 + 0.5 * 2, 2 * 10 + 0.5 * 20])
    var = 4 * 0.01 + 0.25 * 0.04 + 2 * 2 * 0.5 * 0.5 * 0.1 * 0.2
    assert np.isclose(s[0, 0], np.sqrt(var), rtol=1e-12)
    m0, s0 = gr.combine({})
    assert np.all(m0 == 0) and np.all(s0 == 0)


def test_seeds_differ_per_part():
    assert derive_seed(1, "a", 0) != derive_seed(1, "a", 1) != derive_seed(2, "a", 1)
    assert derive_seed(1, "a", 0) == derive_seed(1, "a", 0) and 0 <= derive_seed(5, "x") < 2**31


def test_adaptive_recombination_meets_its_target_and_agrees_with_a_run():
    """An adaptive pass that stops on the scenarios' recombined readings: every scenario
    meets the 5% target (z·sqrt(dᵀCd) ≤ 0.05·dᵀÊ, z = 1.96, in both channels, the cap of
    2^16 samples not reached) and agrees with a separate adaptive run within 4σ."""
    scene = _office()
    sensors = _sensors()
    groups = {"window_row": [l.name for l in scene.lights if "/WindowRow/" in l.name],
              "corridor_row": [l.name for l in scene.lights if "/CorridorRow/" in l.name]}  # fmt: skip
    sim = SimulationConfig(samples=128, method="path", seed=0, rel_error=0.05, max_samples=1 << 16)
    scen = [{"window_row": 1.0, "corridor_row": 0.2}, {"window_row": 0.3, "corridor_row": 1.0}]
    gr = trace_groups(scene, sensors, groups, sim, derive_seed(4, "pass"), scenarios=scen)
    assert np.all(gr.samples < 1 << 16)
    for k, levels in enumerate(scen):
        m, se = gr.combine(levels)
        assert np.all(1.959963 * se <= 0.05 * np.abs(m) * (1 + 1e-9))
        ref = _separate_run(scene, sensors, groups, levels, sim, derive_seed(98, k))
        assert np.all(np.abs(m - ref.mean) <= 4 * np.sqrt(se**2 + ref.stderr**2) + 1e-9 * np.abs(ref.mean))


def test_a_group_with_a_closed_form_is_read_exactly_in_a_sampled_pass():
    """Where the union of the groups needs sampling but one group alone has a closed form,
    that group stays exact: no geometry, a RectLight group (Lambert's closed form) and a
    CylinderLight group (none), so the pass reads the sensors by direct-light sampling
    (plan ``light`` or ``mis``); the rect group's readings equal an analytic run of it
    alone to 1e-12 with standard error and covariance 0, and the cylinder group agrees with
    a run of it alone within 4σ."""
    from simulator.engine.driver import Engine
    from simulator.plan.planner import make_plan
    from simulator.scene.model import Light, LightKind, Scene

    # a RectLight emits along −Z of its frame: down onto the upward-facing sensors
    rect = Light("/Rect", LightKind.RECT, np.array([0.0, 0.0, 2.0]), np.eye(3), (100.0, 100.0 * 683.0), width=1.0, height=0.5)
    cyl = Light("/Tube", LightKind.CYLINDER, np.array([1.0, 0.0, 2.5]), np.eye(3), (50.0, 50.0 * 683.0), radius=0.05, length=1.2)
    scene = Scene(Geometry(), [rect, cyl], [])
    sensors = [Sensor(f"s{i}", SensorKind.IRRADIANCE, np.array([x, 0.3, 0.0]), np.array([0.0, 0.0, 1.0])) for i, x in enumerate((0.0, 0.8, 1.5))]
    assert {sp.method for sp in make_plan(scene, sensors).sensors} <= {"light", "mis"}
    sim = SimulationConfig(samples=2048, seed=0)
    gr = trace_groups(scene, sensors, {"rect": ["/Rect"], "tube": ["/Tube"]}, sim, 17)
    alone = Engine(replace(scene, lights=[rect]), sensors).run("analytic", samples=0, seed=0)
    assert np.all(alone.mean[:, 0] > 0)
    assert np.allclose(gr.mean[0], alone.mean, rtol=1e-12, atol=0)
    assert np.all(gr.stderr[0] == 0) and np.all(gr.cov[:, :, 0, :] == 0) and np.all(gr.cov[:, :, :, 0] == 0)
    tube = Engine(replace(scene, lights=[cyl]), sensors).run("light", samples=4096, seed=3)
    assert np.all(gr.stderr[1] > 0)
    assert np.all(np.abs(gr.mean[1] - tube.mean) <= 4 * np.sqrt(gr.stderr[1] ** 2 + tube.stderr**2) + 1e-9 * np.abs(tube.mean))


def test_the_single_run_stands_for_the_hardest_of_the_scenarios_with_most_groups_lit():
    """The cost figure's single run: among the scenarios lighting the most groups, the one
    whose own target asks the most samples, Σ_s n_s·max_c(σ/|E|)² from the pass. Two groups
    with readings 10 and 1 and variances 1 and 4: d = (1, 1) has (σ/E)² = 5/121 = 0.041,
    d = (0.1, 1) 4.01/4 = 1.0, so the dimmer one is chosen; d = (0, 1), 4/1 = 4, asks
    more still but lights one group only (a run of it would trace fewer lights), so it is
    not; without a target the first of the most-lit is."""
    from types import SimpleNamespace

    from simulator.study.runner import _reference_scenario
    from simulator.study.inputs.scenarios import Scenario

    mean = np.array([[[10.0, 10.0]], [[1.0, 1.0]]])
    cov = np.zeros((1, 2, 2, 2))
    cov[0, :, 0, 0], cov[0, :, 1, 1] = 1.0, 4.0
    res = {"c": {"names": ["a", "b"], "mean": mean, "stderr": np.sqrt(np.array([[[1.0, 1.0]], [[4.0, 4.0]]])), "cov": cov,
                 "samples": np.full((2, 1), 100), "trace_s": np.zeros(2)}}  # fmt: skip
    first = [Scenario("b_only", {"a": 0.0, "b": 1.0}, None, ()), Scenario("full", {"a": 1.0, "b": 1.0}, None, ()),
             Scenario("dim_a", {"a": 0.1, "b": 1.0}, None, ())]  # fmt: skip
    specs = [SimpleNamespace(id="c")]
    assert _reference_scenario(first, specs, res, adaptive=True).name == "dim_a"
    assert _reference_scenario(first, specs, res, adaptive=False).name == "full"
