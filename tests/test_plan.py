"""The planner behind ``method = "auto"``: each rule on a minimal stage that
proves it fires, and a twin that proves it does not."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.reference import closed_forms as cf
from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.plan.planner import make_plan
from simulator.pipeline import collect_sensors, load_scene, run_plan

ROOT = Path(__file__).resolve().parents[1]

HEADER = '#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n'


def _light(z=2.0, intensity=1000.0):
    """A 1 m × 1 m rect light facing down at height z."""
    return f"""
def RectLight "Lamp"
{{
    float inputs:intensity = {intensity}
    float inputs:width = 1
    float inputs:height = 1
    double3 xformOp:translate = (0, 0, {z})
    uniform token[] xformOpOrder = ["xformOp:translate"]
}}
"""


def _quad(name, z, half, albedo):
    """A horizontal square of side 2·half at height z, facing up."""
    h = half
    return f"""
def Mesh "{name}" (prepend apiSchemas = ["MaterialBindingAPI"])
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-{h}, -{h}, {z}), ({h}, -{h}, {z}), ({h}, {h}, {z}), (-{h}, {h}, {z})]
    rel material:binding = </M_{name}>
}}
def Material "M_{name}"
{{
    token outputs:surface.connect = </M_{name}/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = ({albedo}, {albedo}, {albedo})
        token outputs:surface
    }}
}}
"""


def _setup(tmp_path, body, sensors='[[sensor]]\nname = "s"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n', extra=""):
    (tmp_path / "stage.usda").write_text(HEADER + body)
    (tmp_path / "run.toml").write_text(f'stage = "stage.usda"\n{extra}[simulation]\nsamples = 4096\n{sensors}')
    cfg = load_config(tmp_path / "run.toml")
    scene = load_scene(cfg)
    return cfg, scene, collect_sensors(cfg, scene)


def test_closed_form_when_nothing_blocks_and_exact(tmp_path):
    """A sensor under an unoccluded rect light: the plan picks the closed form,
    and the reading equals Lambert's formula (float32 exact), with no samples."""
    cfg, scene, sensors = _setup(tmp_path, _light())
    plan = make_plan(scene, sensors)
    assert [sp.method for sp in plan.sensors] == ["analytic"]
    res = run_plan(Engine(scene, sensors), plan, cfg.simulation)
    l = scene.lights[0]
    verts = cf.rect_light_vertices(l.position, l.frame[:, 0], l.frame[:, 1], l.width, l.height)
    truth = cf.polygon_irradiance(l.emission[1], verts, np.zeros(3), np.array([0, 0, 1.0]), one_sided_normal=-l.frame[:, 2])
    assert res.mean[0, 1] == pytest.approx(truth, rel=2e-6)
    assert res.samples[0] == 0 and res.stderr[0, 1] == 0.0


def test_occluder_between_refuses_the_closed_form(tmp_path):
    """The twin: a black 0.4 m square at z = 1 between sensor and light. The
    unoccluded closed form would ignore it, so the plan reads the lamp's
    visible part instead (``exact``: a RectLight and one blocker), and the
    reading falls below the unoccluded value with no samples; light
    sampling of the same stage agrees within 4σ."""
    _, scene0, sensors0 = _setup(tmp_path, _light())
    free = Engine(scene0, sensors0).run("analytic", samples=1, seed=1).mean[0, 1]
    cfg, scene, sensors = _setup(tmp_path, _light() + _quad("Blocker", 1.0, 0.2, 0.0))
    plan = make_plan(scene, sensors)
    sp = plan.sensors[0]
    assert sp.method == "exact" and "Blocker may block" in sp.reason and sp.geometry == "black occluders"
    res = run_plan(Engine(scene, sensors), plan, cfg.simulation)
    assert res.mean[0, 1] < free and res.stderr[0, 1] == 0.0 and res.samples[0] == 0
    mc = Engine(scene, sensors).run("light", samples=1 << 14, seed=3)
    assert abs(mc.mean[0, 1] - res.mean[0, 1]) <= 4 * mc.stderr[0, 1] + 1e-6 * free


def test_exact_rule_needs_rect_lights(tmp_path):
    """No-fire twin of the ``exact`` rule: the same blocker under a SphereLight
    (no polygon to clip) is read by light sampling."""
    sphere = """
def SphereLight "Bulb"
{
    float inputs:intensity = 1000
    float inputs:radius = 0.2
    double3 xformOp:translate = (0, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
"""
    _, scene, sensors = _setup(tmp_path, sphere + _quad("Blocker", 1.0, 0.2, 0.0))
    sp = make_plan(scene, sensors).sensors[0]
    assert sp.method == "light" and "Blocker may block" in sp.reason


def test_direct_only_where_nothing_seen_reflects(tmp_path):
    """A black blocker between lamp and sensor casts a shadow but reflects
    nothing: direct light is the whole reading, so no bounces (`exact`, the
lamp being a RectLight). A
    black ceiling wholly behind a downward-facing lamp can neither block nor
    light anything: that stage keeps the closed form. The grey twin of the
    blocker is a reflecting surface the sensor sees; the planner does not try
    to prove that no light reaches its underside (none does here), so it
    conservatively follows paths (guided: the stage has a patch layout),
    which then find that out."""
    _, scene, sensors = _setup(tmp_path, _light() + _quad("Blocker", 1.0, 0.2, 0.0) + _quad("Ceiling", 3.0, 5.0, 0.0))
    assert make_plan(scene, sensors).sensors[0].method == "exact"
    _, scene, sensors = _setup(tmp_path, _light() + _quad("Ceiling", 3.0, 5.0, 0.0))
    assert make_plan(scene, sensors).sensors[0].method == "analytic"
    _, scene, sensors = _setup(tmp_path, _light() + _quad("Blocker", 1.0, 0.2, 0.5))
    sp = make_plan(scene, sensors).sensors[0]
    assert sp.method == "exact+guided" and sp.bounces and sp.geometry == "reflecting surfaces"
    assert "surface guide" in sp.reason


def test_surfaces_behind_the_sensor_do_not_force_paths_for_direct_component(tmp_path):
    """A grey floor under an up-facing sensor is behind its plane: with
    component = "direct" the closed form still applies; with "indirect" the
    plan must follow paths (guided paths: the stage has a patch layout)."""
    body = _light() + _quad("Floor", -0.5, 5.0, 0.5)
    _, scene, sensors = _setup(tmp_path, body)
    assert make_plan(scene, sensors, component="direct").sensors[0].method == "analytic"
    assert make_plan(scene, sensors, component="indirect").sensors[0].method == "guided"


def test_lights_behind_a_sensor_are_not_sampled(tmp_path):
    """A downward-facing sensor at z = 0 cannot see a lamp above it: the plan
    culls that lamp (reading exactly 0), and the twin facing up keeps it."""
    down = '[[sensor]]\nname = "down"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, -1]\n'
    up = '[[sensor]]\nname = "up"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'
    cfg, scene, sensors = _setup(tmp_path, _light() + _quad("Blocker", 1.0, 0.1, 0.0), sensors=down + up)
    plan = make_plan(scene, sensors)
    assert plan.sensors[0].culled == ["/Lamp"] and plan.sensors[1].culled == []
    assert plan.light_mask(["/Lamp"]).tolist() == [[0], [1]]
    res = run_plan(Engine(scene, sensors), plan, cfg.simulation)
    assert res.mean[0, 1] == 0.0 and res.mean[1, 1] > 0.0


def test_auto_never_picks_a_blind_or_biased_method():
    """Over every bundled config: `bsdf` (blind to delta lights) is never
    chosen, and a direct-only method (`light`, `mis`, `analytic`) only where no
    surface the sensor sees reflects (otherwise it would be biased low)."""
    for path in sorted((ROOT / "configs").glob("*.toml")):
        cfg = load_config(path)
        scene = load_scene(cfg)
        sensors = [s for s in collect_sensors(cfg, scene) if s.kind.name != "PROBE"]
        for sp in make_plan(scene, sensors, "auto", cfg.simulation.component).sensors:
            assert sp.method in ("analytic", "exact", "light", "mis", "path", "guided", "exact+path", "exact+guided"), (path.name, sp)
            if not sp.bounces and cfg.simulation.component != "direct":
                assert sp.geometry != "reflecting surfaces", (path.name, sp)


def test_one_spectral_channel_for_grey_scenes():
    cfg = load_config(ROOT / "configs" / "rect.toml")
    scene = load_scene(cfg)
    plan = make_plan(scene, collect_sensors(cfg, scene))
    assert plan.channels == 1 and "grey" in plan.channel_reason


def test_mis_for_a_large_source_light_for_a_small_one(tmp_path):
    """Direct light from a sphere light of radius 1.5 m, 2 m away (2π(1 − √(1 − 1.5²/2²)) = 2.1 sr of
    the sensor's sky), behind a black blocker: the plan adds cosine-weighted directions (`mis`). The
    twin under a 1 m² sphere light 2 m away (0.25 sr) keeps plain light sampling, whose single
    shadow ray per sample is the cheaper way there. (A uniform sky or a RectLight there is read
    ``exact``: their visible parts are computed.)"""
    big = ('def SphereLight "Big"\n{\n    float inputs:intensity = 1\n    float inputs:radius = 1.5\n'
           '    double3 xformOp:translate = (0, 0, 2)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    _, scene, sensors = _setup(tmp_path, big + _quad("Blocker", 1.0, 0.2, 0.0))
    sp = make_plan(scene, sensors).sensors[0]
    assert sp.method == "mis" and "2.1 sr" in sp.reason
    dome = 'def DomeLight "Sky"\n{\n    float inputs:intensity = 1\n}\n'
    _, scene, sensors = _setup(tmp_path, dome + _quad("Blocker", 1.0, 0.2, 0.0))
    assert make_plan(scene, sensors).sensors[0].method == "exact"
    bulb = 'def SphereLight "Bulb"\n{\n    float inputs:intensity = 1000\n    float inputs:radius = 0.564\n    double3 xformOp:translate = (0, 0, 2)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n'
    _, scene, sensors = _setup(tmp_path, bulb + _quad("Blocker", 1.0, 0.2, 0.0))
    assert make_plan(scene, sensors).sensors[0].method == "light"
