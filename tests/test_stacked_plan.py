"""The per-sensor work stacked over sensors gives the one-sensor answers, exactly.

The plan's tests (lights behind a sensor, the first triangle in front of its
plane, the ``exact`` rule's refusals), the run record's spliced JSON and the
map's PNG encoder each have a one-at-a-time definition; these tests hold the stacked
forms to it, bit for bit (no tolerance: the same products in the same order
give the same doubles), on the bundled stages and random sensors, including
sensors whose plane passes through a light's corner or a triangle's vertex.
"""

from __future__ import annotations

import io
import json

import numpy as np
import pytest

import simulator
from simulator.io.map_png import png_bytes
from simulator.io.results import record_text
from simulator.pipeline import collect_sensors, load_scene
from simulator.plan.bounds import FrontIndex
from simulator.plan.exact_rule import exact_plan_refusal, exact_plan_refusals
from simulator.plan.planner import lights_behind, lights_behind_many, scene_bounds
from simulator.scene.model import LightKind, Sensor, SensorKind

CONFIGS = ["occluded_floor_grid", "cie171_5_3", "rect", "disk", "sphere", "dome", "quickstart", "polygon", "spot_cone"]


def _sensors(scene, rng, n=150):
    """Random irradiance sensors in the scene's box, half with axis-aligned normals, and some lying in a
    RectLight's plane through its corner (the ``<= 0`` ties of the culling test)."""
    lo, hi = scene.bounds
    out = []
    for k in range(n):
        v = rng.normal(size=3)
        if k % 2:
            v = np.round(v)
        v = v if v.any() else np.array([0.0, 0.0, 1.0])
        out.append(Sensor(f"r{k}", SensorKind.IRRADIANCE, lo + (hi - lo) * rng.random(3), v / np.linalg.norm(v)))
    for l in scene.lights:
        if l.kind == LightKind.RECT:
            corner = l.position + 0.5 * l.width * l.frame[:, 0] + 0.5 * l.height * l.frame[:, 1]
            for n in (l.frame[:, 0], -l.frame[:, 2], l.frame[:, 1]):
                out.append(Sensor(f"c{len(out)}", SensorKind.IRRADIANCE, corner.copy(), n.copy()))
    return out


@pytest.mark.parametrize("name", CONFIGS)
def test_stacked_plan_tests_equal_the_one_sensor_tests(name):
    from simulator.bundled import configs_dir

    cfg = simulator.load_config(configs_dir() / f"{name}.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE] + _sensors(
        scene, np.random.default_rng(11))
    culled = lights_behind_many(scene, sensors)
    assert culled == [lights_behind(scene, s) for s in sensors]
    assert exact_plan_refusals(scene, sensors, culled) == [exact_plan_refusal(scene, s, c) for s, c in zip(sensors, culled)]
    bounds = scene_bounds(scene)
    if bounds.index is not None:
        many = bounds.index.first_in_front_many(np.array([s.position for s in sensors]), np.array([s.normal for s in sensors]))
        for s, row in zip(sensors, many.tolist()):
            assert dict(zip(bounds.index.names, row)) == bounds.index.first_in_front(s.position, s.normal)


def test_first_in_front_many_on_vertices_and_a_coarse_grid():
    """Planes through triangle vertices and axis-aligned planes on a grid of quarter metres (exact
    heights of 0 on many vertices): the stacked scan equals the hierarchy's answers."""
    rng = np.random.default_rng(4)
    pts = np.round(rng.uniform(-2, 2, (300, 3, 3)) * 4) / 4
    subsets = {"all": np.ones(300, bool), "some": rng.random(300) < 0.3}
    index = FrontIndex(pts, subsets, 1e-9 * 2.0)
    planes = [(pts[i, j], np.eye(3)[k] * sgn) for i in range(0, 300, 7) for j in range(3) for k in range(3) for sgn in (1, -1)]
    many = index.first_in_front_many(np.array([p for p, _ in planes]), np.array([n for _, n in planes]))
    for (o, n), row in zip(planes, many.tolist()):
        assert dict(zip(index.names, row)) == index.first_in_front(o, n)


def test_spliced_record_is_json_dumps_byte_for_byte():
    plan = {"sensors": [{"name": f"s[{i},0]", "lights": ["Lamp"], "reason": "a \"quoted\"\nline"} for i in range(3)],
            "methods": {"exact": 3}, "empty": [], "nested": {"e": {}}}
    record = {"config": {"stage": "x.usda"}, "plan": plan, "zeta": 1.5, "alpha": None}
    want = json.dumps(record, indent=2, sort_keys=True) + "\n"
    assert record_text(record, {"plan": json.dumps(plan, indent=2, sort_keys=True)}) == want
    assert record_text(record) == want


def test_png_encoder_round_trips():
    from PIL import Image

    rgb = np.random.default_rng(3).integers(0, 256, (37, 53, 3), dtype=np.uint8)
    img = Image.open(io.BytesIO(png_bytes(rgb)))
    assert img.mode == "RGB" and img.size == (53, 37)
    assert np.array_equal(np.asarray(img), rgb)
