"""The office workloads on a CUDA device and on the CPU: samples/s, rays/s and time to 1%, side by side.

``python benchmarks/device.py [--workloads office_bench office_emissive] [--devices cpu cuda]
[--samples 256] [--rel-error 0.01] [--every 1] [--json out.jsonl]``

Each workload is read as ``probesim run`` reads it (the plan, ``auto``: for the offices the
lamps' and emitters' direct light computed, the rest traced by guided paths), on each device in
turn, in one process, after a warm-up run that loads the kernels and builds the guide (not timed):

- a fixed budget of ``--samples`` per sensor: samples/s (every sensor's samples over the wall time
  of the traced part) and rays/s (the rays the kernels count on a second, shorter run of the same
  plan, per sample, times samples/s);
- an adaptive run to ``--rel-error`` (every sensor's 95% half-width within that fraction of its
  reading): its wall time, whether every sensor met it, and the samples it drew.

The result format is fixed: one JSON object per (workload, device) line, on stdout after the
table and in ``--json`` where given, with the keys

``workload, device, device_name, sensors, methods, samples_per_sensor, samples_per_s, rays_per_s,
rays_per_sample, fixed_s, target_rel_error, time_to_target_s, target_met, adaptive_samples,
load_1m``,

then a table with one row per workload and device and, where both ran, the ratio CPU time over
CUDA time for the fixed budget (samples/s) and to the target. A device that is not there (no CUDA
on the machine) is skipped with a line saying so, and the ratios read ``-``.

Workloads: ``office_bench`` (``configs/office_bench.toml``: 1,464 sensors in the furnished office
lit by sky, sun and six RectLights), ``office_emissive`` (its sensors on
``stages/office_emissive.usda``: a window and six diffusers as emissive geometry) and
``office_furnished`` (``configs/office_furnished.toml``: the furnished office of desks and
chairs on legs, a window onto a large emitter, and emissive luminaires). ``--every N`` reads every
Nth sensor only (a quicker look).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import sys
import time
from pathlib import Path


ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

WORKLOADS = {
    "office_bench": ("configs/office_bench.toml", None),
    "office_emissive": ("configs/office_bench.toml", "stages/office_emissive.usda"),
    "office_furnished": ("configs/office_furnished.toml", None),
}
KEYS = ("workload", "device", "device_name", "sensors", "methods", "samples_per_sensor", "samples_per_s", "rays_per_s",
        "rays_per_sample", "fixed_s", "target_rel_error", "time_to_target_s", "target_met", "adaptive_samples", "load_1m")


def cuda_present() -> bool:
    from simulator.engine.device import cuda_available

    try:
        return cuda_available()
    except Exception:  # noqa: BLE001 - no driver, no device: the same for this script
        return False


def device_name(device: str) -> str:
    if device == "cpu":
        from simulator.commands.bench import processor_name

        return f"{processor_name()} ({os.cpu_count()} cores)"
    from simulator.engine.device import warp

    return str(warp().get_device(device).name)


def load_workload(name: str, every: int):
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene

    cfg_path, stage = WORKLOADS[name]
    cfg = load_config(ROOT / cfg_path)
    if stage is not None:
        cfg = dataclasses.replace(cfg, stage=ROOT / stage)
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind.name != "PROBE"][::every]
    return cfg, scene, sensors


def measure(name: str, device: str, samples: int, rel_error: float, every: int) -> dict:
    """One workload on one device (module docstring)."""
    from simulator.engine import exact_memo
    from simulator.pipeline import config_engine, run_plan
    from simulator.plan.planner import make_plan

    cfg, scene, sensors = load_workload(name, every)
    sim = dataclasses.replace(cfg.simulation, samples=samples, rel_error=None, time_limit_s=None)
    plan = make_plan(scene, sensors, sim.method, sim.component)
    engine = config_engine(cfg, scene, sensors, device=device, threads=0)
    run_plan(engine, plan, dataclasses.replace(sim, samples=16, seed=sim.seed + 1000))  # kernels, guide, pilots
    exact_memo.clear()  # the computed direct light is part of each timed run, as in a fresh process
    t0 = time.perf_counter()
    fixed = run_plan(engine, plan, dataclasses.replace(sim, seed=sim.seed))
    fixed_s = time.perf_counter() - t0
    n = int(fixed.samples.sum())
    # rays per sample: each method group again on a shorter budget, its rays counted by the kernels
    rays = drawn = 0
    for method, ids in plan.groups().items():
        if method in ("analytic", "exact"):
            continue
        r = engine.run(method, samples=max(16, samples // 8), seed=sim.seed + 7, sensor_ids=ids, count_rays=True,
                       max_depth=sim.max_depth)  # fmt: skip
        rays += engine.rays_traced
        drawn += int(r.samples[ids].sum())
    per_sample = rays / max(drawn, 1)
    exact_memo.clear()
    t0 = time.perf_counter()
    ad = run_plan(engine, plan, dataclasses.replace(cfg.simulation, rel_error=rel_error, seed=sim.seed + 2, time_limit_s=None))
    ad_s = time.perf_counter() - t0
    sps = n / fixed_s if fixed_s > 0 else None
    return {"workload": name, "device": engine.device, "device_name": device_name(engine.device), "sensors": len(sensors),
            "methods": {m: len(ix) for m, ix in plan.groups().items()}, "samples_per_sensor": samples,
            "samples_per_s": sps, "rays_per_s": None if sps is None else sps * per_sample, "rays_per_sample": per_sample,
            "fixed_s": fixed_s, "target_rel_error": rel_error, "time_to_target_s": ad_s,
            "target_met": bool(ad.target_met.all()) if ad.target_met is not None else True,
            "adaptive_samples": int(ad.samples.sum()), "load_1m": os.getloadavg()[0]}  # fmt: skip


def table(rows: list[dict]) -> str:
    head = (f"{'workload':18s} {'device':8s} {'sensors':>7s} {'samples/s':>12s} {'rays/s':>13s} {'rays/smp':>8s} "
            f"{'to target':>10s} {'met':>4s} {'CPU/CUDA fixed':>14s} {'CPU/CUDA target':>15s}")  # fmt: skip
    lines = [head]
    by = {(r["workload"], r["device"].split(":")[0]): r for r in rows}
    for r in rows:
        cpu, cuda = by.get((r["workload"], "cpu")), by.get((r["workload"], "cuda"))
        ratio_f = ratio_t = "-"
        if cpu and cuda and r is cuda:
            ratio_f = f"{cuda['samples_per_s'] / cpu['samples_per_s']:.1f}x"
            ratio_t = f"{cpu['time_to_target_s'] / cuda['time_to_target_s']:.1f}x"
        lines.append(f"{r['workload']:18s} {r['device']:8s} {r['sensors']:7d} {r['samples_per_s']:12,.0f} "
                     f"{r['rays_per_s']:13,.0f} {r['rays_per_sample']:8.2f} {r['time_to_target_s']:9.2f}s "
                     f"{'yes' if r['target_met'] else 'no':>4s} {ratio_f:>14s} {ratio_t:>15s}")  # fmt: skip
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--workloads", nargs="+", default=list(WORKLOADS), choices=list(WORKLOADS))
    ap.add_argument("--devices", nargs="+", default=["cpu", "cuda"], choices=["cpu", "cuda"])
    ap.add_argument("--samples", type=int, default=256, help="fixed budget per sensor (default 256)")
    ap.add_argument("--rel-error", type=float, default=0.01, help="adaptive target (default 0.01)")
    ap.add_argument("--every", type=int, default=1, help="read every Nth sensor only (default 1: all)")
    ap.add_argument("--json", type=Path, help="also write the JSON lines here")
    a = ap.parse_args()
    devices = list(a.devices)
    if "cuda" in devices and not cuda_present():
        print("cuda: no CUDA device on this machine (Warp finds none): skipped; the CPU figures follow")
        devices.remove("cuda")
    rows = []
    for w in a.workloads:
        if not (ROOT / WORKLOADS[w][0]).is_file():
            print(f"{w}: {WORKLOADS[w][0]} not found: skipped")
            continue
        for d in devices:
            rows.append(measure(w, d, a.samples, a.rel_error, a.every))
            print(f"{w} on {rows[-1]['device']}: done", file=sys.stderr)
    print(table(rows))
    text = "\n".join(json.dumps({k: r[k] for k in KEYS}) for r in rows)
    print(text)
    if a.json:
        a.json.write_text(text + "\n")


if __name__ == "__main__":
    main()
