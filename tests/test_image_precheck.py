"""The image source's pre-check: a vertex settles "no image" before the call only where the call would.

``kernels.mirrors.image_may_exist`` is asked, at every path vertex, before each try of a light's
image in a flat mirror plane (``kernels.mirrors.image_source``): a sun outside a window has no image
in the pane for a point in the room, and making the call only to learn that cost the office with a
pane 7% of its CPU per sample (docs/DESIGN.md §The glazed office). The test draws points on both sides
of the glazed office's pane (stages/office.usda, ``window = glazed``: its sun, 0.53°, and a point
lamp added on either side) and directions of the sun's whole cone; wherever the pre-check says no,
the call must find nothing (value 0, no ray cast), and the pre-check must say no for most points in
the room (the sun lies behind the pane) and yes for points outdoors where the sun's image reaches.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import warp as wp

from simulator.engine.driver import Engine, load_kernels
from simulator.kernels.lights import SceneRec
from simulator.kernels.mirrors import image_may_exist, image_source
from simulator.scene.model import Light, LightKind, Sensor, SensorKind
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]


@wp.kernel
def k_tries(scene: SceneRec, li: int, k: int, pts: wp.array(dtype=wp.vec3), nrm: wp.array(dtype=wp.vec3), seed: int,
            may: wp.array(dtype=int), value: wp.array(dtype=float), traced: wp.array(dtype=int)):  # fmt: skip
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    u = wp.vec2(wp.randf(rng), wp.randf(rng))
    may[i] = wp.where(image_may_exist(scene, li, k, pts[i]), 1, 0)
    im = image_source(scene, li, k, pts[i], nrm[i], pts[i] + 1.0e-4 * nrm[i], u, 0)
    value[i] = im.value[0] + im.value[1]
    traced[i] = im.traced


def test_the_precheck_says_no_only_where_the_image_source_finds_nothing():
    """2·10⁵ points per light (the sun, a point lamp indoors, one outdoors), uniform in a box around the
    pane on both sides, normals uniform on the sphere: no point where the pre-check says no has an
    image or casts a ray; the sun's pre-check says no for every point in the room, and yes for some
    outdoors whose image is found (value > 0)."""
    load_kernels("cpu")
    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", variants={"window": "glazed"})
    lamp_in = Light("/LampIn", LightKind.POINT, np.array([3.0, 2.0, 1.5]), np.eye(3), (10.0, 6830.0))
    lamp_out = Light("/LampOut", LightKind.POINT, np.array([-3.0, 2.0, 1.5]), np.eye(3), (10.0, 6830.0))
    scene = replace(scene, lights=[*scene.lights, lamp_in, lamp_out])
    eng = Engine(scene, [Sensor("s", SensorKind.IRRADIANCE, np.array([3.0, 2.0, 0.8]), np.array([0.0, 0.0, 1.0]))])
    rec = eng.scene_rec
    assert int(rec.n_mirror_planes) == 1  # the pane's plane
    rng = np.random.default_rng(5)
    n = 200_000
    pts = np.c_[rng.uniform(-6.0, 6.0, n), rng.uniform(0.2, 3.8, n), rng.uniform(0.05, 2.9, n)].astype(np.float32)
    nrm = rng.normal(size=(n, 3))
    nrm = (nrm / np.linalg.norm(nrm, axis=1)[:, None]).astype(np.float32)
    names = [l.name for l in scene.lights]
    sun = next(i for i, l in enumerate(scene.lights) if l.kind == LightKind.DISTANT)
    for li in (sun, names.index("/LampIn"), names.index("/LampOut")):
        may, value, traced = (wp.zeros(n, dtype=t, device="cpu") for t in (int, float, int))
        wp.launch(k_tries, dim=n, inputs=[rec, li, 0, wp.array(pts, dtype=wp.vec3, device="cpu"),
                                          wp.array(nrm, dtype=wp.vec3, device="cpu"), 11 + li],
                  outputs=[may, value, traced], device="cpu")  # fmt: skip
        may, value, traced = may.numpy(), value.numpy(), traced.numpy()
        no = may == 0
        assert np.all(value[no] == 0.0) and np.all(traced[no] == 0), names[li]
        assert no.mean() > 0.3 and (value[~no] > 0.0).any(), (names[li], no.mean())
        if li == sun:
            assert np.all(no[pts[:, 0] > 0.0])  # the room: the sun lies behind the pane
