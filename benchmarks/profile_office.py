"""Where a sample's time goes on the office: ray queries against everything else.

Reads configs/office_bench.toml (1,464 sensors in the furnished office) with
one estimator (default ``guided``, one path a sample: ``--paths auto`` lets
the engine split samples) on one CPU worker, so CPU seconds
(``time.process_time``) are the kernel's own, and prints:

- samples/s and CPU µs per sample;
- rays per sample, closest-hit and shadow (the kernel counts both kinds,
  then shadow rays alone, on the same samples);
- µs per ray of a pure ray-query kernel (:mod:`simulator.kernels.ray_replay`)
  casting rays of the same distribution into the same BVH: cosine
  directions from the sensors and, bounce after bounce, from the surfaces
  they reach; shadow segments from those vertices toward the lights (every
  light at a sensor, one at a surface, as next-event estimation draws
  them): by the estimator's query (BVH, then the float64 re-solve of the
  hit) and by the BVH query alone;
- hence the share of kernel time that is ray queries, and the rest;
- the variance split: direct and indirect light read on their own (same
  seed), each one's variance per sample over the total reading's square,
  averaged over the sensors.

    PYTHONPATH=. python benchmarks/profile_office.py [--samples 32] [--method guided] [--rays 400000] [--paths auto]
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
#: the office's sun and its luminaires' spacing are the stage's; rays of the replay are drawn with this seed
REPLAY_SEED = 12345


def cosine_dirs(rng: np.random.Generator, n: np.ndarray) -> np.ndarray:
    """Cosine-weighted unit directions about the unit normals ``n`` (k, 3)."""
    k = len(n)
    r = np.sqrt(rng.random(k))
    phi = 2 * np.pi * rng.random(k)
    z = np.sqrt(np.maximum(0.0, 1 - r * r))
    a = np.where(np.abs(n[:, :1]) > 0.9, [[0.0, 1.0, 0.0]], [[1.0, 0.0, 0.0]])
    x = np.cross(a, n)
    x /= np.linalg.norm(x, axis=1, keepdims=True)
    y = np.cross(n, x)
    return (r * np.cos(phi))[:, None] * x + (r * np.sin(phi))[:, None] * y + z[:, None] * n


def light_targets(scene, rng: np.random.Generator, p: np.ndarray, n: np.ndarray, every: bool):
    """Shadow segments from vertices ``p`` (normals ``n``) toward the lights: every light from each
    vertex (``every``) or one light drawn uniformly; rect lights to a point uniform on them, the
    sun along its direction, a dome through a point uniform on its portal, both unbounded.
    Segments leaving below the vertex's surface (which next-event estimation does not cast) are dropped."""
    lights = scene.lights
    ids = np.repeat(np.arange(len(lights))[None], len(p), 0).ravel() if every else rng.integers(0, len(lights), len(p))
    q_p = np.repeat(p, len(lights), 0) if every else p
    q_n = np.repeat(n, len(lights), 0) if every else n
    d = np.zeros_like(q_p)
    t = np.full(len(q_p), 1e30)
    for li, l in enumerate(lights):
        m = ids == li
        k = int(m.sum())
        if not k:
            continue
        kind = l.kind.name
        if kind == "DISTANT":
            d[m] = l.frame[:, 2]
            continue
        if kind == "DOME" and l.portals:
            pt = l.portals[0]
            w, h = pt.width, pt.height
            c = pt.position + pt.frame[:, 0] * (w * (rng.random(k) - 0.5))[:, None] + pt.frame[:, 1] * (
                h * (rng.random(k) - 0.5))[:, None]
            v = c - q_p[m]
            d[m] = v / np.linalg.norm(v, axis=1, keepdims=True)
            continue
        if kind == "DOME":
            d[m] = cosine_dirs(rng, q_n[m])
            continue
        c = l.position + l.frame[:, 0] * (l.width * (rng.random(k) - 0.5))[:, None] + l.frame[:, 1] * (
            l.height * (rng.random(k) - 0.5))[:, None]
        v = c - q_p[m]
        dist = np.linalg.norm(v, axis=1)
        d[m] = v / dist[:, None]
        t[m] = dist * (1 - 1e-4)
    keep = np.einsum("ij,ij->i", d, q_n) > 0
    return q_p[keep], d[keep], t[keep]


def replay_rays(engine, scene, sensors, n_rays: int, bounces: int = 3):
    """Closest-hit and shadow rays of a path's distribution (see the module docstring), about
    ``n_rays`` closest-hit ones: ``((o, d, t) closest, (o, d, t) shadow)``."""
    from simulator.engine.ray_profile import cast

    rng = np.random.default_rng(REPLAY_SEED)
    eps = float(engine.scene_rec.eps)
    sp = np.array([s.position for s in sensors], np.float64)
    sn = np.array([s.normal for s in sensors], np.float64)
    per = max(1, n_rays // (len(sensors) * (bounces + 1)))
    p = np.repeat(sp, per, 0)
    n = np.repeat(sn, per, 0)
    closest, shadow = [], []
    for depth in range(bounces + 1):
        off = eps * np.maximum(1.0, np.abs(p).max(axis=1))
        o = p + off[:, None] * n
        shadow.append(light_targets(scene, rng, o, n, every=depth == 0))
        d = cosine_dirs(rng, n)
        t = np.full(len(o), 1e30)
        closest.append((o, d, t))
        h = cast(engine, o, d, t)
        hit = h.face >= 0
        p = o[hit] + h.t_m[hit, None] * d[hit]
        ng = h.ng[hit].astype(np.float64)
        n = np.where((np.einsum("ij,ij->i", ng, d[hit]) < 0)[:, None], ng, -ng)
        if not len(p):
            break

    def cat(parts):
        return tuple(np.concatenate([x[i] for x in parts]) for i in range(3))

    return cat(closest), cat(shadow)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--samples", type=int, default=32, help="samples per sensor of each timed run")
    ap.add_argument("--method", default="guided")
    ap.add_argument("--rays", type=int, default=400000, help="closest-hit rays of the replay (about)")
    ap.add_argument("--no-split", action="store_true", help="skip the direct/indirect variance split")
    ap.add_argument("--paths", default="1", help="indirect paths per irradiance sample: 1 (one path a sample, "
                    "the default) or auto (the engine's split rule)")  # fmt: skip
    a = ap.parse_args()

    from simulator.config import load_config
    from simulator.engine.driver import Engine, load_kernels
    from simulator.engine.ray_profile import time_queries
    from simulator.scene.usd import load_stage

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric")
    sensors = list(cfg.sensors)
    load_kernels("cpu")
    eng = Engine(scene, sensors, threads=1)
    eng.split_indirect = a.paths if a.paths == "auto" else int(a.paths)
    eng.run(a.method, samples=8, seed=1000)  # kernel load and the method's pilots, out of the timing
    n_s = len(sensors)
    c0 = time.process_time()
    r = eng.run(a.method, samples=a.samples, seed=1, count_rays=True)
    cpu = time.process_time() - c0
    n_samples = float(r.samples.sum())
    rays_all = eng.rays_traced / n_samples
    eng.run(a.method, samples=a.samples, seed=1, count_rays=2)
    rays_shadow = eng.rays_traced / n_samples
    rays_closest = rays_all - rays_shadow
    us_sample = 1e6 * cpu / n_samples

    closest, shadow = replay_rays(eng, scene, sensors, a.rays)
    tc, tc_bvh = time_queries(eng, *closest)
    ts, ts_bvh = time_queries(eng, *shadow)
    us_c, us_c_bvh = 1e6 * tc / len(closest[0]), 1e6 * tc_bvh / len(closest[0])
    us_s, us_s_bvh = 1e6 * ts / len(shadow[0]), 1e6 * ts_bvh / len(shadow[0])
    us_rays = rays_closest * us_c + rays_shadow * us_s
    us_bvh = rays_closest * us_c_bvh + rays_shadow * us_s_bvh

    print(f"office_bench: {n_s} sensors, method {a.method}, {a.samples} samples each, one CPU worker "
          f"(load {os.getloadavg()[0]:.2f})")  # fmt: skip
    print(f"  samples/s (CPU)           {n_samples / cpu:12.0f}   ({us_sample:.2f} µs CPU per sample)")
    print(f"  rays per sample           {rays_all:12.2f}   closest-hit {rays_closest:.2f}, shadow {rays_shadow:.2f}")
    print(f"  replay: closest-hit ray   {us_c:12.3f} µs   (BVH query alone {us_c_bvh:.3f} µs; {len(closest[0])} rays)")
    print(f"  replay: shadow ray        {us_s:12.3f} µs   (BVH query alone {us_s_bvh:.3f} µs; {len(shadow[0])} rays)")
    print(f"  ray queries per sample    {us_rays:12.2f} µs = {100 * us_rays / us_sample:.0f}% of the kernel's time "
          f"(BVH alone {100 * us_bvh / us_sample:.0f}%)")  # fmt: skip
    print(f"  everything else           {us_sample - us_rays:12.2f} µs = {100 * (1 - us_rays / us_sample):.0f}%")
    if a.no_split:
        return
    m = r.mean[:, 1]
    ok = m > 0
    parts = {}
    for comp in ("direct", "indirect"):
        rc = eng.run(a.method, samples=a.samples, seed=1, component=comp)
        var = rc.stderr[:, 1] ** 2 * rc.samples
        parts[comp] = var[ok] / m[ok] ** 2
    tot = r.stderr[ok, 1] ** 2 * r.samples[ok] / m[ok] ** 2
    share = parts["indirect"] / (parts["direct"] + parts["indirect"])
    print(f"  relative variance / sample {tot.mean():11.4f}   direct {parts['direct'].mean():.4f}, indirect "
          f"{parts['indirect'].mean():.4f} (indirect's share: {100 * share.mean():.0f}% mean over sensors, "
          f"median {100 * np.median(share):.0f}%)")  # fmt: skip


if __name__ == "__main__":
    main()
