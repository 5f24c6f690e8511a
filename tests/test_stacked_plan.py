"""The per-sensor work stacked over sensors gives the one-sensor answers, exactly.

The plan's tests (lights behind a sensor, the first triangle in front of its
plane, the ``exact`` rule's occluder count), the exact estimator's union of
shadows per receiver, the run record's spliced JSON and the map's PNG
encoder each have a one-at-a-time definition; these tests hold the stacked
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
from simulator.engine import exact as X
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


def test_shadows_united_per_receiver_in_one_call_equal_a_call_each():
    import shapely

    rng = np.random.default_rng(2)
    sizes = rng.integers(1, 6, 200)
    shadows = np.array([shapely.Polygon(rng.uniform(-1, 1, (3, 2))) for _ in range(int(sizes.sum()))], dtype=object)
    starts = np.r_[0, np.cumsum(sizes)[:-1]]
    one = X._union_per_receiver(shadows, starts)
    each = [g[0] if len(g) == 1 else shapely.union_all(g) for g in np.split(shadows, starts[1:])]
    assert all(shapely.equals_exact(a, b, tolerance=0.0) and a.wkb == b.wkb for a, b in zip(one, each))


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


def test_rings_clipped_to_the_horizon_together_equal_one_at_a_time():
    """Star-shaped (non-convex) rings around receivers of random facing, some with vertices on the
    horizon plane or at the receiver: the stacked clip and contour sum give the loop's bits."""
    rng = np.random.default_rng(9)
    rings = []
    for i in range(600):
        k = int(rng.integers(3, 30))
        ang, rad = np.sort(rng.uniform(0, 2 * np.pi, k)), rng.uniform(0.3, 1.5, k)
        e1 = rng.normal(size=3)
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(e1, rng.normal(size=3))
        e2 /= np.linalg.norm(e2)
        pts = rng.normal(size=3) * 0.5 + (rad * np.cos(ang))[:, None] * e1 + (rad * np.sin(ang))[:, None] * e2
        if i % 10 == 0:
            pts[0] = 0.0
        if i % 7 == 0:
            pts = np.round(pts * 2) / 2
        rings.append(pts)
    P = np.zeros((20, 3))
    N = rng.normal(size=(20, 3))
    N[:5] = np.eye(3)[rng.integers(0, 3, 5)]
    N /= np.linalg.norm(N, axis=1)[:, None]
    rec = rng.integers(0, 20, len(rings))
    counts = np.array([len(r) for r in rings])
    loop = [X._lambert_one(X._clip_convex_or_not(r - P[k], (r - P[k]) @ N[k]), N[k]) for r, k in zip(rings, rec)]
    many = X._lambert_clipped(np.concatenate(rings), np.r_[0, np.cumsum(counts)[:-1]], counts, rec,
                              np.arange(len(rings)), P, N)  # fmt: skip
    assert np.array_equal(np.array(loop), many)
