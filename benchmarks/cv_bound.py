"""The most a control variate of the reflected field at a sensor's first hit could remove.

    PYTHONPATH=. python benchmarks/cv_bound.py [--sensors 12] [--directions 256] [--seed 3]

A work-plane or wall sensor's indirect light, one cosine-drawn path per sample, reads X = π·L(y) at
its first hit y (a Lambertian face: L(y) = ρ(y)·E(y)/π, so E[X | y] = ρ(y)·E(y); a ray that escapes
through the window meets the sky directly, which is direct light: 0). A control variate equal to the
true L at the first hit, however it was solved (a radiosity on the guide's patches, a pilot's cache),
leaves X − L(y) and removes at most Var_y(ρE) of Var(X), and its own integral over the hemisphere is
more rays. For ``--sensors`` irradiance sensors of configs/office_bench.toml drawn at random, this
draws ``--directions`` cosine directions each, reads E(y) at every first hit by a traced irradiance
sensor there (512 samples, its noise subtracted from the spread), and prints Var(X) (8,192
one-path samples), Var_y(E[X | y]) and their ratio, the share a perfect first-hit control variate
could remove.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    from simulator.config.loader import load_config
    from simulator.engine.ray_profile import cast
    from simulator.pipeline import collect_sensors, config_engine, load_scene
    from simulator.scene.model import Sensor, SensorKind

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sensors", type=int, default=12)
    ap.add_argument("--directions", type=int, default=256)
    ap.add_argument("--seed", type=int, default=3)
    a = ap.parse_args()
    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    scene = load_scene(cfg)
    every = [s for s in collect_sensors(cfg, scene) if s.kind == SensorKind.IRRADIANCE]
    rng = np.random.default_rng(a.seed)
    pick = [every[i] for i in rng.choice(len(every), a.sensors, replace=False)]
    m = a.directions
    engine = config_engine(cfg, scene, pick)
    engine.split_indirect = 1  # one path a sample: X as the first hit draws it
    ind = engine.run("path", samples=8192, seed=5, component="indirect")
    var_x = ind.stderr[:, 1] ** 2 * ind.samples
    points, normals, rho, slot = [], [], [], []
    for i, s in enumerate(pick):
        n = s.normal / np.linalg.norm(s.normal)
        t = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
        t /= np.linalg.norm(t)
        b = np.cross(n, t)
        u1, u2 = rng.random(m), rng.random(m)
        d = np.sqrt(u1)[:, None] * (np.cos(2 * np.pi * u2)[:, None] * t + np.sin(2 * np.pi * u2)[:, None] * b)
        d += np.sqrt(1.0 - u1)[:, None] * n
        o = np.repeat(s.position[None] + 1e-4 * n, m, 0)
        hits = cast(engine, o, d, np.full(m, 1e30))
        for k in np.flatnonzero(hits.face >= 0):
            ny = hits.ng[k] if np.dot(hits.ng[k], d[k]) < 0 else -hits.ng[k]  # the side the ray arrives on
            points.append(o[k] + hits.t_m[k] * d[k] + 1e-4 * ny)
            normals.append(ny)
            rho.append(scene.geometry.albedo[hits.face[k]])
            slot.append(i * m + k)
    at_y = [Sensor(f"y{j}", SensorKind.IRRADIANCE, np.asarray(p), np.asarray(n)) for j, (p, n) in enumerate(zip(points, normals))]
    ey = config_engine(cfg, scene, at_y).run("guided", samples=512, seed=7)
    cond, noise = np.zeros(len(pick) * m), np.zeros(len(pick) * m)
    cond[slot] = np.asarray(rho) * ey.mean[:, 1]
    noise[slot] = (np.asarray(rho) * ey.stderr[:, 1]) ** 2
    print(f"{len(pick)} sensors × {m} first directions ({len(slot)} meet a face); illuminance, lx²")
    shares = []
    for i, s in enumerate(pick):
        c = cond[i * m:(i + 1) * m]
        between = c.var(ddof=1) - noise[i * m:(i + 1) * m].mean()  # less the E(y) readings' own noise
        shares.append(between / var_x[i])
        print(f"{s.name:<14} indirect {ind.mean[i, 1]:9.1f} lx  Var(X) {var_x[i]:12.4g}  Var_y(E[X|y]) {between:12.4g}  "
              f"share {shares[-1]:.3f}")  # fmt: skip
    print(f"share a perfect first-hit control variate could remove: median {np.median(shares):.3f}, "
          f"mean {np.mean(shares):.3f}, largest {np.max(shares):.3f}")  # fmt: skip


if __name__ == "__main__":
    main()
