"""How computing direct light scales with sensors and triangles, up to a million triangles and 1,000 sensors.

``python benchmarks/exact_scaling.py [--sensors 100 1000] [--triangles 10000 100000 1000000] [--lights 16]``

A synthetic hall (built in numpy, no stage file): 20 m × 20 m × 3 m, black floor, a ceiling, four
walls, ``--lights`` RectLights (1.2 m × 0.3 m) in a grid 5 cm under the ceiling, and clutter of
triangles: small tessellated spheres (r = 0.1 m, 800 triangles each) scattered at 0.9–2.5 m
between the work plane and the lamps, as many as make up the triangle count. Sensors on a square
grid at 0.8 m facing up. For each (sensors, triangles) it prints the CPU seconds of

- building the occluder hierarchy (once per stage);
- planning (``make_plan``: the stage bounds, the culls and the cost model behind ``exact``);
- computing every sensor's direct light from every lamp (``exact_direct``, forced for all of them
  whatever the plan chose);

with the candidate occluders per (sensor, lamp) and the cost model's prediction beside the time
(``plan.exact_rule``: 6 µs per pair + 12 µs per candidate), and a least-squares fit of those two
constants to the measured times.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SIDE, HEIGHT = 20.0, 3.0


def _sphere(n_lat: int = 20, n_lon: int = 20) -> np.ndarray:
    """A unit sphere tessellated into 2·n_lat·n_lon triangles (poles included as thin ones)."""
    th = np.linspace(0, np.pi, n_lat + 1)
    ph = np.linspace(0, 2 * np.pi, n_lon + 1)
    p = np.stack(np.meshgrid(th, ph, indexing="ij"), axis=-1)
    v = np.stack([np.sin(p[..., 0]) * np.cos(p[..., 1]), np.sin(p[..., 0]) * np.sin(p[..., 1]), np.cos(p[..., 0])], axis=-1)
    a, b, c, d = v[:-1, :-1], v[1:, :-1], v[1:, 1:], v[:-1, 1:]
    return np.concatenate([np.stack([a, b, c], axis=-2).reshape(-1, 3, 3), np.stack([a, c, d], axis=-2).reshape(-1, 3, 3)])


def hall(n_tris: int, n_lights: int, seed: int = 1):
    from simulator.scene.model import Geometry, Light, LightKind, Scene

    def quad(a, b, c, d):
        return np.array([[a, b, c], [a, c, d]], float)

    S, H = SIDE, HEIGHT
    room = np.concatenate([quad((0, 0, 0), (S, 0, 0), (S, S, 0), (0, S, 0)), quad((0, 0, H), (0, S, H), (S, S, H), (S, 0, H)),
                           quad((0, 0, 0), (0, S, 0), (0, S, H), (0, 0, H)), quad((S, 0, 0), (S, 0, H), (S, S, H), (S, S, 0)),
                           quad((0, 0, 0), (0, 0, H), (S, 0, H), (S, 0, 0)), quad((0, S, 0), (S, S, 0), (S, S, H), (0, S, H))])  # fmt: skip
    unit = _sphere()
    k = max(0, (n_tris - len(room)) // len(unit))
    rng = np.random.default_rng(seed)
    centres = np.c_[rng.uniform(0.5, S - 0.5, (k, 2)), rng.uniform(0.9, 2.5, k)]
    clutter = (0.1 * unit[None] + centres[:, None, None, :]).reshape(-1, 3, 3)
    tris = np.concatenate([room, clutter])
    T = len(tris)
    albedo = np.r_[np.zeros(2), np.full(T - 2, 0.0)]  # black: the sensors' light is direct only
    g = Geometry(points=tris.reshape(-1, 3), triangles=np.arange(3 * T, dtype=np.int32).reshape(T, 3), albedo=albedo,
                 emission=np.zeros((T, 2)), two_sided=np.zeros(T, bool), prim=np.zeros(T, np.int32), prim_names=["/Hall"])  # fmt: skip
    m = int(round(np.sqrt(n_lights)))
    lights = []
    for i in range(m):
        for j in range(m):
            c = np.array([(i + 0.5) * S / m, (j + 0.5) * S / m, H - 0.05])
            lights.append(Light(f"/Lamp_{i}_{j}", LightKind.RECT, c, np.eye(3), (10.0, 4000.0), width=1.2, height=0.3))
    return Scene(g, lights, [])


def grid_sensors(n: int):
    from simulator.scene.model import Sensor, SensorKind

    m = int(round(np.sqrt(n)))
    xs = (np.arange(m) + 0.5) * SIDE / m
    return [Sensor(f"s[{i},{j}]", SensorKind.IRRADIANCE, np.array([x, y, 0.8]), np.array([0.0, 0.0, 1.0]))
            for i, x in enumerate(xs) for j, y in enumerate(xs)]  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sensors", type=int, nargs="+", default=[100, 1000])
    ap.add_argument("--triangles", type=int, nargs="+", default=[10_000, 100_000, 1_000_000])
    ap.add_argument("--lights", type=int, default=16)
    a = ap.parse_args()
    from simulator.engine import exact_memo
    from simulator.engine.exact import exact_direct, occluder_index
    from simulator.engine.occluders import pyramid_planes
    from simulator.engine.exact import record_polygons
    from simulator.plan import exact_rule
    from simulator.plan.planner import make_plan

    print(f"load {os.getloadavg()[0]:.2f} at start; {a.lights} RectLights; CPU seconds")
    print(f"{'sensors':>7s} {'triangles':>10s} {'index s':>8s} {'plan s':>7s} {'exact s':>8s} {'cand/pair':>9s} {'model s':>8s} "
          f"{'s/sensor':>9s}")  # fmt: skip
    fit_x, fit_y = [], []
    for T in a.triangles:
        scene = hall(T, a.lights)
        t0 = time.process_time()
        idx = occluder_index(scene)
        t_idx = time.process_time() - t0
        for S in a.sensors:
            sensors = grid_sensors(S)
            P = np.array([s.position for s in sensors])
            N = np.array([s.normal for s in sensors])
            t0 = time.process_time()
            make_plan(scene, sensors)
            t_plan = time.process_time() - t0
            exact_memo.clear()
            t0 = time.process_time()
            exact_direct(scene, sensors, np.arange(len(sensors)))
            t_exact = time.process_time() - t0
            cands = 0
            for r in range(len(scene.lights)):
                V = record_polygons(scene, r).V[0]
                pl = pyramid_planes(P, N, np.broadcast_to(V, (len(P), 4, 3)), np.full(len(P), 4))
                cands += int(idx.cull(pl, count_only=True).sum())
            pairs = len(P) * len(scene.lights)
            model = pairs * exact_rule.EXACT_JOB_S + cands * exact_rule.EXACT_OCCLUDER_S
            fit_x.append((pairs, cands))
            fit_y.append(t_exact)
            print(f"{len(sensors):7d} {scene.geometry.n_triangles:10d} {t_idx:8.2f} {t_plan:7.2f} {t_exact:8.2f} "
                  f"{cands / pairs:9.1f} {model:8.2f} {t_exact / len(sensors):9.5f}", flush=True)  # fmt: skip
    A = np.array(fit_x, float)
    if len(A) >= 2:
        coef, *_ = np.linalg.lstsq(A, np.array(fit_y), rcond=None)
        print(f"fit: {1e6 * coef[0]:.1f} µs per (sensor, lamp) pair + {1e6 * coef[1]:.1f} µs per candidate occluder "
              f"(the model: {1e6 * exact_rule.EXACT_JOB_S:g} + {1e6 * exact_rule.EXACT_OCCLUDER_S:g})")
    print(f"load {os.getloadavg()[0]:.2f} at end")


if __name__ == "__main__":
    main()
