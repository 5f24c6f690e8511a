"""What computing the direct light buys: the offices read with and without it, per sample and in all.

``python benchmarks/hybrid_gain.py [--samples 64] [--every 1] [--stages office office_emissive office_furnished]``

For each office (``office``: configs/office_bench.toml on stages/office.usda, sky, sun and six
RectLights; ``office_emissive``: its sensors on stages/office_emissive.usda, a window and diffusers
as emissive geometry; ``office_furnished``: configs/office_furnished.toml) it reads every
``--every``-th sensor with ``guided`` (everything sampled) and ``exact+guided`` with the direct
light always computed (``Engine.hybrid = True``), after a warm-up run that builds the guide and the
pilots, and prints over the sensors the mean relative variance per sample (stderr²·n/mean²), rays
per sample, CPU µs per sample (one process, all its threads; the samples alone, the computed part
kept from a first timed run), their product relvar × µs (the CPU time to a given error once the
computed part is paid, lower is better), the CPU seconds of the computed part (the first run's CPU
less the second's), and the split K each chose.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

STAGES = {"office": ("configs/office_bench.toml", None), "office_emissive": ("configs/office_bench.toml", "stages/office_emissive.usda"),
          "office_furnished": ("configs/office_furnished.toml", None)}  # fmt: skip


def measure(stage: str, method: str, samples: int, every: int) -> dict:
    from simulator.config.loader import load_config
    from simulator.engine import exact_memo
    from simulator.pipeline import collect_sensors, config_engine, load_scene
    from simulator.plan.planner import make_plan

    cfg_path, other = STAGES[stage]
    cfg = load_config(ROOT / cfg_path)
    if other:
        cfg = dataclasses.replace(cfg, stage=ROOT / other)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)[::every]
    plan = make_plan(scene, sensors)
    eng = config_engine(cfg, scene, sensors, threads=0)
    eng.hybrid = True
    eng.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
    eng.run(method, samples=8, seed=100)
    exact_memo.clear()
    c0 = time.process_time()
    eng.run(method, samples=samples, seed=1)
    cpu_all = time.process_time() - c0  # with the computed part
    c0 = time.process_time()
    r = eng.run(method, samples=samples, seed=1, count_rays=True)  # the same samples, the computed part kept
    cpu = time.process_time() - c0
    n = r.samples.astype(float)
    m = r.mean[:, 1]
    ok = m > 0
    rv = float(np.mean(r.stderr[ok, 1] ** 2 * n[ok] / m[ok] ** 2))
    us = 1e6 * cpu / n.sum()
    return {"stage": stage, "method": method, "relvar": rv, "rays": eng.rays_traced / n.sum(), "us": us, "product": rv * us,
            "exact_s": max(cpu_all - cpu, 0.0) if method.startswith("exact") else 0.0, "k": (eng.split_pilot or {}).get("k", 1)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--samples", type=int, default=64)
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--stages", nargs="+", default=list(STAGES), choices=list(STAGES))
    a = ap.parse_args()
    print(f"load {os.getloadavg()[0]:.2f} at start; {a.samples} samples per sensor, every {a.every} sensor(s)")
    print(f"{'stage':17s} {'method':13s} {'relvar':>7s} {'rays':>6s} {'µs/smp':>7s} {'relvar×µs':>9s} {'exact CPU s':>11s} {'K':>2s}")
    for st in a.stages:
        rows = [measure(st, m, a.samples, a.every) for m in ("guided", "exact+guided")]
        for r in rows:
            print(f"{r['stage']:17s} {r['method']:13s} {r['relvar']:7.3f} {r['rays']:6.2f} {r['us']:7.2f} {r['product']:9.3f} "
                  f"{r['exact_s']:11.2f} {r['k']:2d}", flush=True)  # fmt: skip
        print(f"{'':17s} gain in relvar × µs: {rows[0]['product'] / rows[1]['product']:.2f}x")
    print(f"load {os.getloadavg()[0]:.2f} at end")


if __name__ == "__main__":
    main()
