"""Emissive geometry in pieces against the same emitters as RectLights, on the office.

Reads the office's 1,464 work-plane and wall sensors (configs/office_bench.toml)
on two stages: stages/office_emissive.usda (a 5 m x 3 m window emitter behind
its wall and six emissive diffusers) and stages/office_rect_twin.usda (the
same emitters as RectLights). For each it draws a fixed budget with a method
and reports, over the sensors, the mean relative variance per sample
(stderr²·n/mean²), the rays per sample and the CPU seconds, and their
products: relvar × rays is the load-free cost of a given error. The
emissive stage is also read with its emitters as one piece (the sampler
before pieces: a triangle ∝ its power) for the gain of the pieces.

    PYTHONPATH=. python benchmarks/emissive_office.py --samples 64 --seeds 2 --method path
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def measure(stage: str, method: str, samples: int, seeds: int, pieces_cap: int | None = None) -> dict:
    from simulator.config import load_config
    from simulator.engine.driver import Engine, load_kernels
    from simulator.scene import emitters
    from simulator.scene.usd import load_stage

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    scene = load_stage(ROOT / "stages" / stage, light_units="photometric")
    load_kernels("cpu")
    kept = emitters.MAX_PIECES
    if pieces_cap is not None:
        emitters.MAX_PIECES = pieces_cap
    try:
        rv, rays, cpu, mean = [], [], [], []
        for seed in range(seeds):
            eng = Engine(scene, list(cfg.sensors))
            eng.run(method, samples=8, seed=1000 + seed)  # the pilots and the kernel load, out of the timing
            c0 = time.process_time()
            r = eng.run(method, samples=samples, seed=seed, count_rays=True)
            cpu.append(time.process_time() - c0)
            n = r.samples.astype(np.float64)
            m = r.mean[:, 1]
            ok = m > 0
            rv.append(float(np.mean(r.stderr[ok, 1] ** 2 * n[ok] / m[ok] ** 2)))
            rays.append(eng.rays_traced / float(n.sum()))
            mean.append(m)
        pieces = eng._dev.pieces.n if getattr(eng._dev, "pieces", None) is not None else 0
    finally:
        emitters.MAX_PIECES = kept
    rv, rays, cpu = float(np.mean(rv)), float(np.mean(rays)), float(np.mean(cpu))
    return {"stage": stage, "pieces": pieces, "relvar": rv, "rays": rays, "cpu_s": cpu,
            "cpu_us_per_sample": 1e6 * cpu / (samples * len(cfg.sensors)), "relvar_x_rays": rv * rays,
            "mean_lx": float(np.mean(mean))}  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--samples", type=int, default=64)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--method", default="path")
    a = ap.parse_args()
    rows = [
        ("RectLight twin", measure("office_rect_twin.usda", a.method, a.samples, a.seeds)),
        ("emissive, one piece", measure("office_emissive.usda", a.method, a.samples, a.seeds, pieces_cap=1)),
        ("emissive, pieces", measure("office_emissive.usda", a.method, a.samples, a.seeds)),
    ]
    base = rows[0][1]
    print(f"{'stage':22s} {'pieces':>6s} {'relvar':>8s} {'rays':>6s} {'relvar×rays':>12s} {'µs/sample':>10s} "
          f"{'relvar×CPU':>11s} {'vs twin (rays)':>14s} {'vs twin (CPU)':>13s} {'mean lx':>9s}")  # fmt: skip
    for name, r in rows:
        vr = r["relvar_x_rays"] / base["relvar_x_rays"]
        vc = r["relvar"] * r["cpu_us_per_sample"] / (base["relvar"] * base["cpu_us_per_sample"])
        print(f"{name:22s} {r['pieces']:6d} {r['relvar']:8.3f} {r['rays']:6.1f} {r['relvar_x_rays']:12.2f} "
              f"{r['cpu_us_per_sample']:10.2f} {r['relvar'] * r['cpu_us_per_sample']:11.2f} {vr:13.2f}x {vc:12.2f}x "
              f"{r['mean_lx']:9.1f}")  # fmt: skip


if __name__ == "__main__":
    main()
