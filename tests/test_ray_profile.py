"""The profile's tools: ray counts split by kind, and the ray-query kernel alone.

Counts: in mode 1 the kernel counts every ray, in mode 2 shadow rays only,
on the same samples. With next-event estimation alone (``light``, direct
light) each sample of an irradiance sensor casts at most one shadow ray per light (none toward a light
behind the receiver) and nothing else; ``mis`` adds one cosine-weighted
closest-hit ray. The ray-query kernel must meet the
office's surfaces where the stage puts them: its ceiling at z = 3 m, facing
down into the room (stages/office.usda).
"""

from pathlib import Path

import numpy as np

from simulator.config import load_config
from simulator.engine.driver import Engine, load_kernels
from simulator.scene.model import SensorKind
from simulator.scene.usd import load_stage

ROOT = Path(__file__).resolve().parents[1]


def _rect_engine():
    cfg = load_config(ROOT / "configs" / "rect.toml")
    scene = load_stage(ROOT / "stages" / "rect.usda")
    load_kernels("cpu")
    irradiance = [s for s in cfg.sensors if s.kind == SensorKind.IRRADIANCE]  # a radiance meter casts its own ray
    assert len(irradiance) >= 3
    return Engine(scene, irradiance, threads=1), len(scene.lights)


def test_shadow_rays_are_counted_apart():
    eng, n_lights = _rect_engine()
    for method, closest in (("light", 0), ("mis", 1)):
        r = eng.run(method, samples=64, seed=1, count_rays=True)
        n = int(r.samples.sum())
        every = eng.rays_traced
        eng.run(method, samples=64, seed=1, count_rays=2)
        shadow = eng.rays_traced
        # at most one shadow ray per light per sample (none toward a light behind the receiver)
        assert 0 < shadow <= n * n_lights, method
        assert every - shadow == n * closest, method  # mis: one cosine ray per sample


def test_ray_query_kernel_meets_the_office_ceiling():
    from simulator.engine.ray_profile import cast, time_queries

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric")
    load_kernels("cpu")
    eng = Engine(scene, list(cfg.sensors), threads=1)
    o = np.array([[3.0, 2.0, 1.5], [3.0, 2.0, 1.5], [1.0, 1.3, 2.0]])
    d = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    t_max = np.array([1e30, 1.0, 1e30])
    h = cast(eng, o, d, t_max)
    assert h.face[0] >= 0 and abs(h.t_m[0] - 1.5) < 1e-5  # the ceiling, 1.5 m up
    assert abs(abs(h.ng[0, 2]) - 1.0) < 1e-6
    assert h.face[1] == -1  # stops 0.5 m short of it
    assert h.face[2] >= 0 and abs(h.t_m[2] - 1.0) < 1e-5
    first_hit_s, bvh_s = time_queries(eng, o, d, t_max, repeats=1)
    assert first_hit_s >= 0.0 and bvh_s >= 0.0
