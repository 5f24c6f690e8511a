"""The glazed office against the open one, each read with its default estimator.

Reads the office's 1,464 work-plane and wall sensors (configs/office_bench.toml)
with the stage's ``window`` variant ``open`` (an open opening, all matte) and
``glazed`` (a pane of ior 1.52 in the opening, a GGX floor of roughness 0.4),
each with the plan's estimator (``auto``: both ``guided``), at a fixed budget
and seed. For each it prints the RMS relative standard error of the
illuminance over the sensors, the CPU seconds of the run (the guide's pilot
included; process CPU time, so other load on the machine does not count),
and two load-free figures of the cost of a given error:

- CPU seconds to 1% RMS: CPU s × (RMS relative stderr / 1%)² (the error
  falls as 1/√samples), and the same with the guide's pilot counted once
  (pilot CPU s + trace CPU s × (RMS / 1%)²: the pilot is a fixed cost,
  :data:`simulator.engine.guide.PILOT_SAMPLES` per sensor, whatever the
  target);
- relative variance × rays: mean over the sensors of stderr²·n/mean², times
  the rays traced per sample (a separate counted run).

and the ratio glazed / open of each. ``--path`` also reads the glazed office
with plain paths.

    PYTHONPATH=. python benchmarks/glazed_office.py --samples 256 --seed 1
"""

from __future__ import annotations

import argparse
import dataclasses
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def measure(window: str, samples: int, seed: int, method: str = "auto") -> dict:
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, config_engine, load_scene, run_plan
    from simulator.plan.planner import make_plan
    from simulator.scene.model import SensorKind

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    cfg = dataclasses.replace(cfg, variants={**cfg.variants, "window": window})
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    plan = make_plan(scene, sensors, method)
    sim = dataclasses.replace(cfg.simulation, samples=samples, seed=seed, rel_error=None)
    config_engine(cfg, scene, sensors[:4]).run(plan.sensors[0].method, samples=32, seed=seed)  # compile, warm caches
    engine = config_engine(cfg, scene, sensors)
    t0 = time.process_time()
    if any(sp.method == "guided" for sp in plan.sensors):  # the pilot alone (the run then reuses its guide)
        engine.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        engine.ensure_guide(seed, np.arange(len(sensors)), sim.max_depth)
    pilot_s = time.process_time() - t0
    res = run_plan(engine, plan, sim)
    cpu_s = time.process_time() - t0
    mean, se = res.mean[:, 1], res.stderr[:, 1]
    rel = se / mean
    rms = float(np.sqrt(np.mean(rel**2)))
    relvar = float(np.mean(rel**2 * res.samples))
    counted = config_engine(cfg, scene, sensors)
    n_count = max(32, samples // 8)
    methods = sorted({sp.method for sp in plan.sensors})
    rays = 0.0
    for m in methods:
        ids = np.array([i for i, sp in enumerate(plan.sensors) if sp.method == m])
        counted.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        r = counted.run(m, samples=n_count, seed=seed + 7, sensor_ids=ids, count_rays=True)
        rays += counted.rays_traced
    rays_per_sample = rays / (n_count * len(sensors))
    return {"window": window, "methods": "+".join(methods), "rms": rms, "cpu_s": cpu_s,
            "cpu_to_1pct_s": cpu_s * (rms / 0.01) ** 2, "pilot_once_s": pilot_s + (cpu_s - pilot_s) * (rms / 0.01) ** 2,
            "relvar": relvar, "rays": rays_per_sample,
            "relvar_rays": relvar * rays_per_sample}  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=256)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--path", action="store_true", help="also read the glazed office with plain paths")
    a = ap.parse_args()
    rows = [measure("open", a.samples, a.seed), measure("glazed", a.samples, a.seed)]
    if a.path:
        rows.append(measure("glazed", a.samples, a.seed, "path"))
    print(f"{'window':<8} {'method':<8} {'RMS se':>8} {'CPU s':>8} {'CPU s to 1%':>12} {'pilot once':>11} {'relvar':>8} "
          f"{'rays':>7} {'relvar×rays':>12}")  # fmt: skip
    for r in rows:
        print(f"{r['window']:<8} {r['methods']:<8} {r['rms']:>8.2%} {r['cpu_s']:>8.2f} {r['cpu_to_1pct_s']:>12.1f} "
              f"{r['pilot_once_s']:>11.1f} {r['relvar']:>8.3f} {r['rays']:>7.2f} {r['relvar_rays']:>12.3f}")  # fmt: skip
    o, g = rows[0], rows[1]
    print(f"glazed / open ({a.samples} samples, seed {a.seed}): {g['cpu_to_1pct_s'] / o['cpu_to_1pct_s']:.2f}x CPU seconds "
          f"to 1% RMS ({g['pilot_once_s'] / o['pilot_once_s']:.2f}x with the pilot once), "
          f"{g['relvar_rays'] / o['relvar_rays']:.2f}x relative variance x rays")  # fmt: skip


if __name__ == "__main__":
    main()
