"""Are the hybrid's standard errors honest? The office's planned readings against its stored reference.

``python benchmarks/hybrid_errors.py [--budgets 64 256 1024] [--methods auto guided]``

Reads ``configs/office_bench.toml`` (1,464 sensors) three ways at each budget on its own seed: the
plan (``auto``: ``exact+guided``, the lamps' and the sky's direct light computed and the rest traced
by guided paths, where the engine's pilot finds that it pays, else all traced), the plan with the
direct light computed at every budget (``computed``), and everything traced (``guided``); and compares every reading with the stored reference
(``configs/references/office_bench.csv``, two pooled 16,384-sample runs): z = (x − ref)/√(σ² +
σ_ref²). Honest errors give an RMS z near 1 and about 5% of the sensors outside their 95%
intervals (|z| > 1.96). Prints per budget and method the RMS z, the share outside, the mean z (a
bias shows there) and the RMS relative error, with the machine's load.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--budgets", type=int, nargs="+", default=[64, 256, 1024])
    ap.add_argument("--methods", nargs="+", default=["auto", "computed", "guided"],
                    help="auto: the plan; computed: the plan, its direct light computed at every budget; else every sensor so")
    a = ap.parse_args()
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, config_engine, load_scene, run_plan
    from simulator.plan.planner import make_plan

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    ref = {r["sensor"]: r for r in csv.DictReader((ROOT / "configs" / "references" / "office_bench.csv").open())}
    r = np.array([float(ref[s.name]["illuminance_lx"]) for s in sensors])
    sr = np.array([float(ref[s.name]["illuminance_stderr_lx"]) for s in sensors])
    print(f"{len(sensors)} sensors; load {os.getloadavg()[0]:.2f} at start")
    print(f"{'method':14s} {'samples':>7s} {'RMS z':>6s} {'outside 95%':>11s} {'mean z':>7s} {'RMS err':>8s} {'seconds':>8s}")
    for m in a.methods:
        plan = make_plan(scene, sensors, "auto" if m == "computed" else m)
        engine = config_engine(cfg, scene, sensors)
        if m == "computed":
            engine.hybrid = True
        for k, n in enumerate(a.budgets):
            sim = dataclasses.replace(cfg.simulation, samples=n, seed=500 + k, rel_error=None)
            t0 = time.perf_counter()
            res = run_plan(engine, plan, sim)
            dt = time.perf_counter() - t0
            x, s = res.mean[:, 1], res.stderr[:, 1]
            z = (x - r) / np.sqrt(s**2 + sr**2)
            name = m
            hyb = engine.hybrid_pilot
            note = "" if hyb is None else f"  (direct light {'computed' if hyb['computed'] else 'sampled: pilot'})"
            print(f"{name:14s} {n:7d} {np.sqrt(np.mean(z**2)):6.3f} {np.mean(np.abs(z) > 1.96):11.1%} {np.mean(z):+7.3f} "
                  f"{np.sqrt(np.mean(((x - r) / r) ** 2)):8.2%} {dt:8.1f}{note}", flush=True)  # fmt: skip
    print(f"load {os.getloadavg()[0]:.2f} at end")


if __name__ == "__main__":
    main()
